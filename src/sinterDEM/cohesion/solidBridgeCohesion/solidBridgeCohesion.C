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

} // End anonymous namespace


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
    cWall_(timeCorrection(law.particleMaterial(), law.wallMaterial()))
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
        << std::pow(K_, 12.0/7.0) << endl;
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

    const scalar scale = std::pow(K_, 12.0/7.0);
    const vector* __restrict__ x = P.position.cdata();
    const scalar* __restrict__ r = P.radius.cdata();
    const scalar* __restrict__ T = P.temperature.cdata();
    vector* __restrict__ F = P.force.data();

    // Temperature-dependent factors, re-evaluated when T changes
    scalar Tlast = -1;
    scalar growth = 0;      // c G/a^3 dt [m^4]
    scalar strength = 0;    // K^(12/7) C pi sigma [N/m^2]

    for (contactPair& c : pairs)
    {
        if (!c.history.active())
        {
            continue;
        }
        const label i = c.i;
        const label j = c.j;

        const scalar Tc = 0.5*(T[i] + T[j]);
        if (Tc != Tlast)
        {
            checkedTemperature(Tc);
            growth = cPair_*law_.neckGrowthRate(1, Tc)*deltaT;
            strength = scale*law_.forceFromNeck(1, Tc);
            Tlast = Tc;
        }

        // Primary particles' radius of the pair, r_p for equal spheres
        const scalar rp = 2*r[i]*r[j]/((r[i] + r[j])*K_);
        c.history.bridge += growth*pow3(law_.curvatureRadius(rp));

        const vector d = x[j] - x[i];
        const vector n = d/mag(d);
        const vector f = (strength*std::pow(c.history.bridge, 2.0/7.0))*n;
        F[i] += f;
        F[j] -= f;
    }
}


void Foam::cohesionModels::solidBridge::wallForces
(
    demParticles& P,
    UList<wallContact>& contacts,
    const scalar deltaT,
    const scalar time
) const
{
    if (time <= activationTime_ || law_.C() <= 0)
    {
        return;
    }

    const scalar scale = std::pow(K_, 12.0/7.0);
    const scalar* __restrict__ r = P.radius.cdata();
    const scalar* __restrict__ T = P.temperature.cdata();
    vector* __restrict__ F = P.force.data();

    scalar Tlast = -1;
    scalar growth = 0;
    scalar strength = 0;

    for (wallContact& c : contacts)
    {
        if (!c.history.active())
        {
            continue;
        }
        const label i = c.i;

        // The wall has the particle's temperature and properties
        const scalar Tc = T[i];
        if (Tc != Tlast)
        {
            checkedTemperature(Tc);
            growth = cWall_*law_.neckGrowthRate(1, Tc)*deltaT;
            strength = scale*law_.forceFromNeck(1, Tc);
            Tlast = Tc;
        }

        c.history.bridge += growth*pow3(law_.curvatureRadius(r[i]/K_));

        // Towards the wall: c.normal points from the wall to the particle
        const vector f = -(strength*std::pow(c.history.bridge, 2.0/7.0))*c.normal;
        F[i] += f;
        c.force += f;
    }
}
