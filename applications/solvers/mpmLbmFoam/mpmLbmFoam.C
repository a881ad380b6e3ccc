/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | mpmLbmFoam: material point + lattice Boltzmann
   \\    /   O peration     | soil-water interaction on OpenFOAM
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of mpmLbmFoam, distributed under the terms of the GNU
    General Public License version 3 or later, as OpenFOAM it builds on.

Application
    mpmLbmFoam

Group
    grpSolvers

Description
    Soil-water interaction: the soil skeleton by the material point method,
    the water by the lattice Boltzmann method, on one uniform hex mesh whose
    cell centres are both the MPM grid nodes and the lattice nodes.

    The scene's effects (water, soil, couplings) are selected in
    constant/physicsProperties; see physicsScene.

Usage
    \b mpmLbmFoam [OPTION]

    Options:
      - \par -estimate
        Run a few steps, project the wall time and memory of the case and
        of the case with dx halved and doubled, write nothing.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "IFstream.H"
#include "physicsScene.H"
#include "caseChecks.H"
#include "restartManifest.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Soil-water interaction: material point soil, lattice Boltzmann"
        " water, on one uniform mesh"
    );

    argList::addBoolOption
    (
        "estimate",
        "Run a few steps, print the projected wall time and memory of the"
        " case and of the case with dx halved and doubled; write nothing"
    );

    #include "setRootCase.H"
    // (an error in a global file names it in parallel too)
    const IOobject::fileCheckTypes fileChecking =
        readGlobalFilesOnEveryProcessor();

    // The input is read with overflow untrapped and OpenFOAM's fatal
    // errors ending the run cleanly (caseChecks.H)
    const bool inputTrapped = suspendInputTraps();
    autoPtr<Time> runTimePtr;
    autoPtr<fvMesh> meshPtr;
    autoPtr<physicsScene> scenePtr;
    runSetup
    (
        [&]()
        {
            checkControlDict(args);
            restartManifest::checkWritable(args);
            restartManifest::setAsideIncompleteTimes(args);

            Info<< "Create time\n" << endl;
            runTimePtr.reset(new Time(Time::controlDictName, args));
            restoreRunClock(*runTimePtr);
            // The function objects' state of the start time, which OpenFOAM
            // reads when they start, after this guarded set-up: read here
            // first, so that 1e400 in it ends with the parser's error naming
            // the file rather than a floating-point trap
            {
                const fileName state
                (
                    runTimePtr->timePath()/"uniform"/"functionObjects"
                   /"functionObjectProperties"
                );
                if (isFile(state))
                {
                    IFstream is(state);
                    const dictionary check(is);
                }
            }

            Info<< "Create mesh for time = " << runTimePtr->timeName()
                << nl << endl;
            meshPtr.reset
            (
                new fvMesh
                (
                    IOobject
                    (
                        fvMesh::defaultRegion,
                        runTimePtr->timeName(),
                        *runTimePtr,
                        IOobject::MUST_READ
                    )
                )
            );

            scenePtr.reset(new physicsScene(*runTimePtr, *meshPtr));
        }
    );
    restoreInputTraps(inputTrapped);
    IOobject::fileModificationChecking = fileChecking;
    Time& runTime = *runTimePtr;
    physicsScene& scene = *scenePtr;

    if (args.found("estimate"))
    {
        scene.estimate();
        Info<< "End\n" << endl;
        return 0;
    }

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        scene.keepDeltaT();
        ++runTime;

        scene.evolve();

        // The effects' outputs and the registered fields at write times
        scene.write();
    }

    scene.summary();

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
