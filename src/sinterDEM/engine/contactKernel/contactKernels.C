// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
// The contact kernels: one per pair of contact law and cohesion model.
// A new law or cohesion model adds its lines here.

#include "contactKernel.H"
#include "HertzMindlin.H"
#include "linearSpringDashpot.H"
#include "noCohesion.H"
#include "solidBridgeCohesion.H"

#define makeContactKernel(Law, Cohesion)                                      \
    static const Foam::contactKernel::registration                            \
        add##Law##Cohesion##ContactKernel_                                    \
        (                                                                     \
            Foam::word(#Law "," #Cohesion),                                   \
            &Foam::contactKernelTemplate                                      \
            <                                                                 \
                Foam::contactLaws::Law,                                       \
                Foam::cohesionModels::Cohesion                                \
            >::New                                                            \
        );

makeContactKernel(HertzMindlin, none)
makeContactKernel(HertzMindlin, solidBridge)
makeContactKernel(linearSpringDashpot, none)
makeContactKernel(linearSpringDashpot, solidBridge)
