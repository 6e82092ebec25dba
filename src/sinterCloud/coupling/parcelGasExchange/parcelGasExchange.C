// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "parcelGasExchange.H"
#include "cloudCoupling.H"
#include "gradScheme.H"
#include "IStringStream.H"

namespace Foam
{
namespace
{
    //- The gradient of a cell field, limited so that the value it moves
    //  to a cell's faces stays within the cell's and its neighbours' values
    //  (cellLimited Gauss linear 1, whatever fvSchemes says)
    vectorField limitedGrad(const volScalarField& f)
    {
        IStringStream scheme("cellLimited Gauss linear 1");
        return
            fv::gradScheme<scalar>::New(f.mesh(), scheme)()
           .grad(f, "limitedGrad(" + f.name() + ')')().primitiveField();
    }
}
}


Foam::parcelGasExchange::parcelGasExchange(const fvMesh& mesh)
:
    mesh_(mesh),
    implicit_(false),
    local_(false)
{}


void Foam::parcelGasExchange::begin
(
    const label nLocal,
    const bool implicit,
    const volScalarField& T
)
{
    implicit_ = implicit;
    local_ = implicit && cloudCoupling::New(mesh_).localGasTemperature();

    cell_.setSize(nLocal);
    fraction_.setSize(nLocal);
    from_.setSize(nLocal);
    gasAt_.setSize(nLocal);
    if (implicit_)
    {
        gasT0_ = T.primitiveField();
        target_.setSize(mesh_.nCells());
        target_ = 0;
        if (local_)
        {
            gradT0_ = limitedGrad(T);
            gas_.setSize(mesh_.nCells());
            gas_ = 0;
        }
    }
}


void Foam::parcelGasExchange::reorder(const labelList& newIndex)
{
    const label n = newIndex.size();
    labelList cell(n);
    scalarList fraction(n);
    scalarList from(n);
    scalarList gasAt(n);
    forAll(newIndex, k)
    {
        cell[newIndex[k]] = cell_[k];
        fraction[newIndex[k]] = fraction_[k];
        from[newIndex[k]] = from_[k];
        gasAt[newIndex[k]] = gasAt_[k];
    }
    cell_.transfer(cell);
    fraction_.transfer(fraction);
    from_.transfer(from);
    gasAt_.transfer(gasAt);
}


Foam::scalar Foam::parcelGasExchange::leave
(
    const label k,
    const scalar npMcp,
    scalarField& hsTrans,
    scalarField& hsCoeff
)
{
    if (!holds(k) || fraction_[k] == 0)
    {
        return 0;
    }
    const label c = cell_[k];
    const scalar K = npMcp*fraction_[k];
    const scalar dT = fraction_[k]*(gasAt_[k] - from_[k]);
    hsTrans[c] -= npMcp*dT;
    hsCoeff[c] -= K;
    target_[c] -= K*from_[k];
    if (local_)
    {
        gas_[c] -= K*gasAt_[k];
    }
    fraction_[k] = 0;
    return dT;
}


Foam::tmp<Foam::fvScalarMatrix> Foam::parcelGasExchange::Sh
(
    volScalarField& hs,
    const scalarField& Cp,
    const scalarField& hsTrans,
    const scalarField& hsCoeff,
    const scalar dt
) const
{
    tmp<fvScalarMatrix> tSh(new fvScalarMatrix(hs, dimEnergy/dimTime));
    const diffusionSmoother& smoother = cloudCoupling::New(mesh_).smoother();
    const scalarField& V = mesh_.V();

    // Explicit exchange (and that of particles that left in the step),
    // per volume and time, spread over the smoothing length
    //
    // Implicit: each cell towards its particles,
    //     smoothed:  S(sum m c_p f T_p/(V dt)) - B T_g,
    //     local:     S(sum m c_p f (T_p - T_g^0(x_p))/(V dt)) - B (T_g - T_g^0),
    //     B = S(sum m c_p f/(V dt)),  T_g = T_g^0 + (h - h^0)/c_p
    //
    // The fields smoothed in one block solve
    scalarField explicitHeat(hsTrans/(V*dt));
    scalarField A;
    scalarField B;
    scalarField BTg;
    DynamicList<scalarField*> fields({&explicitHeat});
    DynamicList<word> names({"cloudHeat"});
    if (implicit_)
    {
        A = target_/(V*dt);
        B = hsCoeff/(V*dt);
        fields.append({&A, &B});
        names.append({"cloudHeatTarget", "cloudHeatCoeff"});
        if (local_)
        {
            BTg = gas_/(V*dt);
            fields.append(&BTg);
            names.append("cloudHeatGas");
        }
    }
    UPtrList<scalarField> smoothed(fields.size());
    forAll(fields, k)
    {
        smoothed.set(k, fields[k]);
    }
    UPtrList<vectorField> none;
    smoother.smooth(smoothed, names, none, wordList());

    fvScalarMatrix& Sh = tSh.ref();
    Sh.source() -= V*explicitHeat;
    if (implicit_)
    {
        if (!local_)
        {
            BTg = B*gasT0_;
        }
        const scalarField BbyCp(B/Cp);
        Sh.diag() -= V*BbyCp;
        Sh.source() -= V*(A - BTg + BbyCp*hs.oldTime().primitiveField());
    }
    return tSh;
}


void Foam::parcelGasExchange::gather
(
    const volScalarField& hs,
    const scalarField& Cp
)
{
    // The gas's change over the step as the gas took it, (h - h^0)/c_p;
    // smoothed, with the gas temperature of the start
    const diffusionSmoother& smoother = cloudCoupling::New(mesh_).smoother();
    const scalarField dTg
    (
        (hs.primitiveField() - hs.oldTime().primitiveField())/Cp
    );
    gathered_ =
        local_
      ? smoother.smooth<scalar>(dTg, "cloudHeatGather")
      : smoother.smooth<scalar>(gasT0_ + dTg, "cloudHeatGather");
}

