// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "KochHill.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace dragLaws
{
    defineTypeNameAndDebug(KochHill, 0);
    addToRunTimeSelectionTable(dragLaw, KochHill, dictionary);
}
}


Foam::scalar Foam::dragLaws::KochHill::F(const scalar eps, const scalar Re) const
{
    const scalar phi = 1 - eps;
    const scalar ReH = 0.5*Re;

    // Dense limit and the blend towards it
    const scalar dense = 10*phi/pow3(eps);
    const scalar w = phi > 0 ? std::exp(-10*(0.4 - phi)/phi) : 0;
    const scalar phiLnPhi = phi > 0 ? phi*std::log(phi) : 0;
    const scalar sqrtHalfPhi = std::sqrt(0.5*phi);

    // F0 and F2: the dilute fit blended into the dense limit below 0.4
    auto blended = [&](const scalar a, const scalar b, const scalar c)
    {
        return
            phi < 0.4
          ? (1 - w)*(1 + 3*sqrtHalfPhi + 135.0/64.0*phiLnPhi + a*phi)
           /(1 + 0.681*phi + b*sqr(phi) + c*pow3(phi))
          + w*dense
          : dense;
    };

    const scalar F2 = blended(17.89, -11.03, 15.41);

    const scalar F3 =
        phi < 0.0953
      ? 0.9351*phi + 0.03667
      : 0.0673 + 0.212*phi + 0.0232/pow5(eps);

    scalar FKH;

    if (phi <= 0.01)
    {
        const scalar Re1 = (F2 - 1)/(0.375 - F3);
        FKH = ReH <= Re1 ? 1 + 0.375*ReH : F2 + F3*ReH;
    }
    else
    {
        const scalar F0 = blended(17.14, -8.48, 8.16);

        const scalar F1 =
            phi <= 0.1
          ? std::sqrt(2/phi)/40
          : 0.11 + 5.1e-4*std::exp(11.6*phi);

        const scalar Re2 =
            (F3 + std::sqrt(sqr(F3) - 4*F1*(F0 - F2)))/(2*F1);

        FKH = ReH <= Re2 ? F0 + F1*sqr(ReH) : F2 + F3*ReH;
    }

    return eps*FKH;
}
