// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactKernel.H"

Foam::HashTable<Foam::contactKernel::constructorPtr>&
Foam::contactKernel::table()
{
    static HashTable<constructorPtr> kernels;
    return kernels;
}


Foam::autoPtr<Foam::contactKernel> Foam::contactKernel::New
(
    const contactLaw& law,
    const cohesionModel& cohesion,
    const label durationSlot
)
{
    const word name(law.type() + "," + cohesion.type());
    const auto iter = table().cfind(name);
    if (!iter.found())
    {
        FatalErrorInFunction
            << "No contact kernel for contactLaw " << law.type()
            << " with cohesionModel " << cohesion.type() << nl
            << "Valid contactLaw,cohesionModel pairs are "
            << table().sortedToc() << exit(FatalError);
    }
    return (*iter)(law, cohesion, durationSlot);
}


void Foam::contactKernelDetail::coincidentParticles(const point& x)
{
    FatalErrorInFunction
        << "Two particles are at the same point " << x
        << ": their contact has no direction." << nl
        << "Particles must start at distinct points: check the injection"
        << " (e.g. a positionsFile listing a point twice)"
        << exit(FatalError);
}
