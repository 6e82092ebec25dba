// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "solidBridgeCohesion.H"
#include "contactLaw.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace cohesionModels
{
    defineTypeNameAndDebug(solidBridge, 0);
    addToRunTimeSelectionTable(cohesionModel, solidBridge, dictionary);
}
}


const Foam::Enum
<
    Foam::cohesionModels::solidBridge::wallTemperatureModel
>
Foam::cohesionModels::solidBridge::wallTemperatureModelNames
({
    { wallTemperatureModel::wall, "wall" },
    { wallTemperatureModel::particle, "particle" },
});


namespace
{

using namespace Foam;

//- Effective modulus of two bodies, eq 5.15 [Pa]
scalar effectiveModulus
(
    const scalar Y1, const scalar nu1,
    const scalar Y2, const scalar nu2
)
{
    return 1/((1 - sqr(nu1))/Y1 + (1 - sqr(nu2))/Y2);
}


//- c = (Y*_DEM/Y*_real)^(2/5) of two contact materials (eq 5.14)
scalar timeCorrection(const contactMaterial& a, const contactMaterial& b)
{
    const scalar softened = effectiveModulus
    (
        a.youngsModulus(), a.poissonsRatio(),
        b.youngsModulus(), b.poissonsRatio()
    );
    const scalar real = effectiveModulus
    (
        a.realYoungsModulus(), a.poissonsRatio(),
        b.realYoungsModulus(), b.poissonsRatio()
    );
    return std::pow(softened/real, 0.4);
}


//- Temperature of a contact, checked: kelvin, at least 200 K
inline scalar checkedTemperature(const scalar T)
{
    if (!(T >= 200))
    {
        FatalErrorInFunction
            << "contact temperature " << T << " K is below 200 K: particle"
               " temperatures are in kelvin" << exit(FatalError);
    }
    return T;
}


//- The temperature-dependent factors of the bridges over one step,
//  evaluated again only when the contact temperature changes from one
//  contact to the next (once per step in a bed at a uniform temperature)
class bridgeFactors
{
    const Foam::solidBridge& law_;

    //- Contact-time correction c [-] and DEM step [s]
    const scalar c_;
    const scalar deltaT_;

    //- K^(12/7)
    const scalar scale_;

    scalar T_ = -1;

    //- Growth of x^7 over the step per a^3 [m^4]
    scalar growth_ = 0;

    //- Force per x^2 [N/m^2]
    scalar strength_ = 0;

public:

    bridgeFactors
    (
        const Foam::solidBridge& law,
        const scalar c,
        const scalar deltaT,
        const scalar K
    )
    :
        law_(law),
        c_(c),
        deltaT_(deltaT),
        scale_(std::pow(K, 12.0/7.0))
    {}

    //- Set the factors for a contact at temperature T [K]
    void at(const scalar T)
    {
        if (T != T_)
        {
            checkedTemperature(T);
            growth_ = c_*law_.neckGrowthRate(1, T)*deltaT_;
            strength_ = scale_*law_.forceFromNeck(1, T);
            T_ = T;
        }
    }

    //- Grow a neck of curvature radius a [m]; the bridge force [N]
    scalar grow(scalar& x7, const scalar a) const
    {
        x7 += growth_*pow3(a);
        return strength_*std::pow(x7, 2.0/7.0);
    }
};

} // End anonymous namespace


Foam::cohesionModels::solidBridge::wallTemperatureModel
Foam::cohesionModels::solidBridge::readWallTemperature
(
    const dictionary& coeffs
)
{
    const word name(coeffs.lookupOrDefault<word>("wallTemperature", "wall"));
    if (!wallTemperatureModelNames.found(name))
    {
        FatalIOErrorInFunction(coeffs)
            << "Unknown wallTemperature " << name << " in " << coeffs.name()
            << nl << "Valid wallTemperature values are "
            << wallTemperatureModelNames << exit(FatalIOError);
    }
    return wallTemperatureModelNames[name];
}


Foam::cohesionModels::solidBridge::solidBridge
(
    const dictionary& dict,
    const contactLaw& law,
    const scalar coarseGrainFactor
)
:
    coeffs_(dict.subDict("solidBridgeCoeffs")),
    material_(coeffs_.subDict("material")),
    law_(material_, coeffs_),
    activationTime_(coeffs_.lookupOrDefault<scalar>("activationTime", 0)),
    K_(coarseGrainFactor),
    cPair_(timeCorrection(law.particleMaterial(), law.particleMaterial())),
    cWall_(timeCorrection(law.particleMaterial(), law.wallMaterial())),
    wallTemperature_(readWallTemperature(coeffs_))
{
    if (activationTime_ < 0)
    {
        FatalIOErrorInFunction(coeffs_)
            << "activationTime " << activationTime_ << " must be >= 0 [s]"
            << exit(FatalIOError);
    }

    Info<< "    solid bridges: C " << law_.C() << ", activation at "
        << activationTime_ << " s, contact-time correction c = " << cPair_
        << " (pairs), " << cWall_ << " (walls), force scale K^(12/7) = "
        << std::pow(K_, 12.0/7.0) << ", wall contacts at the "
        << wallTemperatureModelNames[wallTemperature_] << "'s temperature"
        << endl;
}


void Foam::cohesionModels::solidBridge::pairForces
(
    demParticles& P,
    UList<contactPair>& pairs,
    const scalar deltaT,
    const scalar time
) const
{
    if (time <= activationTime_ || law_.C() <= 0)
    {
        return;
    }

    const vector* __restrict__ x = P.position.cdata();
    const scalar* __restrict__ r = P.radius.cdata();
    const scalar* __restrict__ T = P.temperature.cdata();
    vector* __restrict__ F = P.force.data();
    bridgeFactors factors(law_, cPair_, deltaT, K_);

    for (contactPair& c : pairs)
    {
        if (!c.history.active())
        {
            continue;
        }
        const label i = c.i;
        const label j = c.j;

        factors.at(0.5*(T[i] + T[j]));

        // Primary particles' radius of the pair, r_p for equal spheres
        const scalar rp = 2*r[i]*r[j]/((r[i] + r[j])*K_);
        const scalar Fsb =
            factors.grow(c.history.bridge, law_.curvatureRadius(rp));

        const vector d = x[j] - x[i];
        const vector f = Fsb*(d/mag(d));
        F[i] += f;
        F[j] -= f;
    }
}


void Foam::cohesionModels::solidBridge::wallForces
(
    demParticles& P,
    UList<wallContact>& contacts,
    const demWalls& walls,
    const scalar deltaT,
    const scalar time
) const
{
    if (time <= activationTime_ || law_.C() <= 0)
    {
        return;
    }

    const bool atWall = wallTemperature_ == wallTemperatureModel::wall;
    if (atWall && walls.temperature().size() != walls.size())
    {
        FatalErrorInFunction
            << "wallTemperature wall in " << coeffs_.name()
            << ": the wall faces have no temperature (the solver sets it"
               " from the gas temperature field T); use wallTemperature"
               " particle" << exit(FatalError);
    }
    const scalar* __restrict__ r = P.radius.cdata();
    const scalar* __restrict__ T = P.temperature.cdata();
    const scalar* __restrict__ Tw = walls.temperature().cdata();
    vector* __restrict__ F = P.force.data();
    bridgeFactors factors(law_, cWall_, deltaT, K_);

    for (wallContact& c : contacts)
    {
        if (!c.history.active())
        {
            continue;
        }
        const label i = c.i;

        // The wall has the particle's properties (§5.3.2)
        factors.at(atWall ? Tw[c.face] : T[i]);
        const scalar Fsb =
            factors.grow(c.history.bridge, law_.curvatureRadius(r[i]/K_));

        // Towards the wall: c.normal points from the wall to the particle
        const vector f = -Fsb*c.normal;
        F[i] += f;
        c.force += f;
    }
}
