// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
// The contact kernels: one for every contact law with every cohesion model,
// generated from the two lists below. A new contact law or cohesion model
// adds its header and its class to its list; the combinations follow.

#include "contactKernel.H"
#include "HertzMindlin.H"
#include "linearSpringDashpot.H"
#include "noCohesion.H"
#include "solidBridgeCohesion.H"

#include <initializer_list>

namespace
{

using namespace Foam;

template<class... Types>
struct typeList {};

//- The contact laws
typedef typeList
<
    contactLaws::HertzMindlin,
    contactLaws::linearSpringDashpot
> contactLawTypes;

//- The cohesion models
typedef typeList
<
    cohesionModels::none,
    cohesionModels::solidBridge
> cohesionModelTypes;


//- Register the kernel of Law with every cohesion model of the list
template<class Law, class... Cohesions>
void registerLaw(typeList<Cohesions...>)
{
    (void)std::initializer_list<int>
    {
        (
            contactKernel::table().insert
            (
                word(Law::typeName_()) + "," + Cohesions::typeName_(),
                &contactKernelTemplate<Law, Cohesions>::New
            ),
            0
        )...
    };
}

//- Register every law with every cohesion model
template<class... Laws>
void registerAll(typeList<Laws...>)
{
    (void)std::initializer_list<int>
    {
        (registerLaw<Laws>(cohesionModelTypes()), 0)...
    };
}

struct registration
{
    registration()
    {
        registerAll(contactLawTypes());
    }
};

const registration registerContactKernels_;

} // End anonymous namespace
