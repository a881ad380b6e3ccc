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
    bareLoop

Description
    The reference for the effect-cost benchmark (benchmarks/effectCost):
    one phase's library driven in a bare loop, without the scene (no
    effects, no run-time loop, no progress, no writing), on a case set up
    for mpmLbmFoam:
    \verbatim
        bareLoop -phase fluid -steps 200
        bareLoop -phase soil -steps 200
    \endverbatim
    Prints "bare <phase>: <steps> steps <wall> s".

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "latticeMesh.H"
#include "latticeBoltzmannFluid.H"
#include "materialPointSoil.H"
#include "uniformDimensionedFields.H"
#include <chrono>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote("One phase in a bare loop: the effect-cost reference");
    argList::addOption("phase", "fluid|soil", "the phase to run");
    argList::addOption("steps", "N", "number of steps");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const word phase(args.get<word>("phase"));
    const label nSteps = args.get<label>("steps");
    if (phase != "fluid" && phase != "soil")
    {
        FatalErrorInFunction
            << "-phase " << phase << " is not allowed: fluid or soil"
            << exit(FatalError);
    }

    // As the scene builds it: halo 2 when the soil is present
    const latticeMesh lattice(mesh, phase == "soil" ? 2 : 1);
    const scalar dt = runTime.deltaTValue();

    using clock = std::chrono::steady_clock;
    scalar wall = 0;
    if (phase == "fluid")
    {
        latticeBoltzmannFluid lbm(lattice);
        const clock::time_point t0 = clock::now();
        for (label s = 0; s < nSteps; ++s)
        {
            lbm.step();
        }
        wall = std::chrono::duration<scalar>(clock::now() - t0).count();
    }
    else
    {
        materialPointSoil mpm(lattice);
        // The soil's weight, as the scene's gravity effect sets it
        mpm.setGravity
        (
            uniformDimensionedVectorField
            (
                IOobject
                (
                    "g",
                    runTime.constant(),
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE
                )
            ).value()
        );
        const clock::time_point t0 = clock::now();
        for (label s = 0; s < nSteps; ++s)
        {
            mpm.advance(dt);
        }
        wall = std::chrono::duration<scalar>(clock::now() - t0).count();
    }

    Info<< "bare " << phase << ": " << nSteps << " steps " << wall << " s"
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
