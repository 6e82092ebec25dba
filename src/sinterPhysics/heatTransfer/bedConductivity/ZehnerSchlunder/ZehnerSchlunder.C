// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "ZehnerSchlunder.H"
#include "mathematicalConstants.H"
#include "keywordSource.H"

const Foam::Enum<Foam::ZehnerSchlunder::solidContribution>
Foam::ZehnerSchlunder::solidContributionNames
{
    { solidContribution::none, "none" },
    { solidContribution::molecular, "molecular" },
    { solidContribution::molecularAndKinetic, "molecularAndKinetic" },
};


namespace
{

Foam::ZehnerSchlunder::solidContribution readSolids
(
    const Foam::dictionary& dict
)
{
    using namespace Foam;
    const word name
    (
        dict.lookupOrDefault<word>("solidContribution", "molecularAndKinetic")
    );
    if (!ZehnerSchlunder::solidContributionNames.found(name))
    {
        FatalIOErrorInKeyword(dict, "solidContribution")
            << "Unknown solidContribution " << name << " in " << dict.name()
            << nl << nl << "Valid solidContribution types are" << nl
            << ZehnerSchlunder::solidContributionNames << exit(FatalIOError);
    }
    return ZehnerSchlunder::solidContributionNames[name];
}

} // End anonymous namespace


Foam::ZehnerSchlunder::ZehnerSchlunder(const dictionary& dict)
:
    solids_(readSolids(dict))
{}


Foam::scalar Foam::ZehnerSchlunder::gasEffective
(
    const scalar eps,
    const scalar kf
)
{
    return (1 - std::sqrt(max(1 - eps, scalar(0))))/eps*kf;
}


Foam::scalar Foam::ZehnerSchlunder::solidMolecular
(
    const scalar eps,
    const scalar kf,
    const scalar ks
)
{
    const scalar solid = 1 - eps;
    if (solid <= 0)
    {
        return 0;
    }

    const scalar A = ks/kf;
    scalar B = 1.25*std::pow(solid/eps, 10.0/9.0);
    if (mag(1 - B/A) < 1e-4)
    {
        B = A*(1 - 1e-4);
    }
    const scalar r = 1 - B/A;

    const scalar Gamma =
        2/r
       *(
            (A - 1)/(r*r)*B/A*std::log(A/B)
          - (B - 1)/r
          - (B + 1)/2
        );

    return (omega*A + (1 - omega)*Gamma)/std::sqrt(solid)*kf;
}


Foam::scalar Foam::ZehnerSchlunder::solidKinetic
(
    const scalar rho,
    const scalar cp,
    const scalar d,
    const scalar Theta
)
{
    return
        rho*cp*d*std::sqrt(max(Theta, scalar(0)))
       *std::sqrt(constant::mathematical::pi)/16;
}


Foam::scalar Foam::ZehnerSchlunder::bed
(
    const scalar eps,
    const scalar kf,
    const scalar ks,
    const scalar ksKinetic
) const
{
    scalar kSolid = 0;
    if (solids_ != solidContribution::none)
    {
        kSolid = solidMolecular(eps, kf, ks);
    }
    if (solids_ == solidContribution::molecularAndKinetic)
    {
        kSolid += ksKinetic;
    }
    return eps*gasEffective(eps, kf) + (1 - eps)*kSolid;
}


void Foam::ZehnerSchlunder::write(Ostream& os) const
{
    os.writeEntry("solidContribution", solidContributionNames[solids_]);
}
