// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "contactAgeCohesion.H"
#include "HertzMindlin.H"
#include "contactKernel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace cohesionModels
{
    defineTypeNameAndDebug(contactAge, 0);
    addToRunTimeSelectionTable(cohesionModel, contactAge, dictionary);
}
}

namespace
{

//- The kernel of HertzMindlin with this model, added to the engine's table
//  when the library loads
struct registration
{
    registration()
    {
        using namespace Foam;
        contactKernel::table().insert
        (
            word(contactLaws::HertzMindlin::typeName_()) + ","
          + cohesionModels::contactAge::typeName_(),
            &contactKernelTemplate
            <
                contactLaws::HertzMindlin,
                cohesionModels::contactAge
            >::New
        );
    }
};

const registration registerContactAgeKernel_;

} // End anonymous namespace
