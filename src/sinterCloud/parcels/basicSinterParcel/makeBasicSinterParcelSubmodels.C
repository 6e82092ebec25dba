// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
// Run-time selection tables of every submodel family of basicSinterCloud.

#include "basicSinterCloud.H"

#include "makeParcelCloudFunctionObjects.H"
#include "makeThermoParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeParcelInjectionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeThermoParcelSurfaceFilmModels.H"
#include "NoHeatTransfer.H"
#include "ConvectionHeatTransfer.H"

// sinterFoam's own forces
#include "VoidageDragForce.H"
#include "GasPressureGradientForce.H"
#include "WeightForce.H"

// sinterFoam's own injection
#include "LatticeBedInjection.H"

// OpenFOAM's stock families
makeParcelCloudFunctionObjects(basicSinterCloud);
makeThermoParcelForces(basicSinterCloud);
makeParcelDispersionModels(basicSinterCloud);
makeParcelInjectionModels(basicSinterCloud);
makeParcelPatchInteractionModels(basicSinterCloud);
makeParcelStochasticCollisionModels(basicSinterCloud);
makeParcelSurfaceFilmModels(basicSinterCloud);
makeHeatTransferModel(basicSinterCloud);
makeHeatTransferModelType(NoHeatTransfer, basicSinterCloud);
makeHeatTransferModelType(ConvectionHeatTransfer, basicSinterCloud);

// sinterFoam's additions to the force table
makeParticleForceModelType(VoidageDragForce, basicSinterCloud);
makeParticleForceModelType(GasPressureGradientForce, basicSinterCloud);
makeParticleForceModelType(WeightForce, basicSinterCloud);

// sinterFoam's addition to the injection table
makeInjectionModelType(LatticeBedInjection, basicSinterCloud);
