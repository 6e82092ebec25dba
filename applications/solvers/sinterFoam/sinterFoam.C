// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers
/*
Application
    sinterFoam

Description
    Transient thermal CFD-DEM solver for dense gas-particle flows: fluidized
    beds of hot micron powder that may sinter and defluidize.

    Gas (thesis Ch. 4.2.1 / 5.2.1), volume-averaged with voidage eps:
        d(eps rho)/dt + div(eps rho U) = 0                           (4.1)
        d(eps rho U)/dt + div(eps rho U U)
            = -eps grad(p) + div(eps tau) - S + eps rho g            (4.2)
        d(eps rho h)/dt + div(eps rho U h)
            = div(eps k_eff/Cp grad(h)) + Q_pf                        (4.5)
        eps k_eff = (1 - sqrt(1 - eps)) k                             (4.6)
    Thermal wall condition (tBC, bedWallTemperature on T): the wall faces
    conduct with the bed conductivity k_b of eq 4.14-4.24.
    Pressure-velocity coupling: PIMPLE; the particle drag is semi-implicit,
    explicit particle forces and gravity enter the pressure equation as face
    fluxes.

    Gas properties come from constant/thermophysicalProperties (rhoThermo):
    constant density at the operating temperature (equationOfState
    rhoConst, Ch. 5) or ideal gas at a thermodynamic pressure
    (incompressiblePerfectGas, Ch. 4).

    With the ideal gas the density follows the energy equation inside the
    PIMPLE loop: use nOuterCorrectors >= 3 for a conservative enthalpy
    balance (the solver warns otherwise; test/thermalBox measures it).

    Particles: one thermal colliding cloud, constant/cloudProperties.

    Hydrogen reduction (the cloud's reduction dictionary, gas transported):
    the gas carries H2 and H2O (Y_H2, Y_H2O, YEqn.H) with the parcels'
    sources, and its continuity the oxygen's mass; that mass enters at the
    gas's own enthalpy.

    Checked at the start (named errors, not a trap or a loop without end):
    the gas's mu, Cp, kappa and rho > 0 (thermophysicalProperties), PIMPLE
    nOuterCorrectors in [1, 100] (fvSolution), deltaT > 0; every step, the
    gas's Courant number below CourantLimit (system/controlDict, optional,
    default 100: a bed runs far below 1).

    Data flow of a time step:
        gas -> cloud (move, collide, drag, heat) -> voidage and sources
            -> gas (momentum, energy, pressure)
            -> cloud (the parcels' share of the implicit heat exchange)
*/

#include "fvCFD.H"
#include "rhoThermo.H"
#include "SLGThermo.H"
#include "pimpleControl.H"
#include "keywordRange.H"
#include "constrainPressure.H"
#include "constrainHbyA.H"
#include "fixedFluxPressureFvPatchScalarField.H"
#include "basicSinterCloud.H"
#include "cloudCoupling.H"
#include "bedWallTemperatureFvPatchScalarField.H"
#include "incrementSolve.H"
#include "numberLiterals.H"
#include "writtenTimes.H"
#include "cloudInput.H"
#include "ironOxidePath.H"
#include "profiling.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Thermal CFD-DEM solver for fluidized beds of sintering powder"
    );

    #include "postProcess.H"
    #include "setRootCaseLists.H"
    numberLiterals::checkCase(args);
    #include "createTime.H"
    #include "checkTimeStep.H"
    // The start time whole (the cloud of createFields): its parcels
    const label nWritten = writtenTimes::checkStart(runTime, "cloud");
    #include "createMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    // The Courant number beyond which a step stops (CourantNo.H): optional,
    // default 100 (a CFD-DEM bed runs far below 1), read once
    const scalar CoLimit = keywordRange::getOrDefault
    (
        runTime.controlDict(), "CourantLimit", 100, 0, GREAT,
        "the gas's Courant number beyond which the run stops", true
    );
    #include "createFields.H"
    writtenTimes::checkParcelsRead(runTime, nWritten, cloud.nParcels());

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "setDeltaT.H"

        ++runTime;
        Info<< "Time = " << runTime.timeName() << nl << endl;

        // Gas -> cloud: parcels move, collide, take drag and heat (and
        // hydrogen)
        {
            addProfiling(cloudEvolve, "sinterFoam::cloud");
            cloud.evolve();
        }
        oxygenSource = cloud.oxygenSource();
        massSource =
            dimensionedScalar("M_O", dimMass/dimMoles, ironOxidePath::MO)
           *oxygenSource;

        // Cloud -> gas: voidage from the new parcel positions
        #include "updateVoidage.H"

        addProfiling(gas, "sinterFoam::gas");
        while (pimple.loop())
        {
            #include "UEqn.H"

            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            // Energy with the mass flux that satisfies continuity for the
            // new voidage: conservative, and exact for uniform temperature
            #include "EEqn.H"
        }

        // H2 and H2O with the parcels' sources
        #include "YEqn.H"
        endProfiling(gas);

        // Gas -> cloud: the parcels follow the change of the gas
        // temperature their implicit heat exchange assumed
        {
            addProfiling(heatCorrection, "sinterFoam::correctHeatExchange");
            cloud.correctHeatExchange();
        }

        runTime.write();
        writtenTimes::markComplete(runTime, cloud.nParcels());
        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;
    return 0;
}
