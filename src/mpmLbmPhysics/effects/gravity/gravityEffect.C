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


\*---------------------------------------------------------------------------*/

#include "caseChecks.H"
#include "optionalEntry.H"
#include "IFstream.H"
#include "gravityEffect.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "soilEffect.H"
#include "uniformDimensionedFields.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(gravity, 0);
    addToRunTimeSelectionTable(physicsEffect, gravity, scene);
    addToMemberFunctionSelectionTable(physicsEffect, gravity, haloWidth, mesh);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::gravity::gravity(physicsScene& scene)
:
    physicsEffect(scene),
    g_(Zero)
{
    const fvMesh& mesh = scene.mesh();
    const uniformDimensionedVectorField g
    (
        IOobject
        (
            "g",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    if (g.dimensions() != dimAcceleration)
    {
        FatalErrorInFunction
            << g.objectPath() << ": g has dimensions " << g.dimensions()
            << ": an acceleration " << dimAcceleration << " is needed"
            << exit(FatalError);
    }
    g_ = g.value();
    {
        checkInPlane
        (
            scene.lattice().twoD(), g_, "value", fileDictionary(g.filePath())
        );
    }

    // The phases that feel it: all those in the scene unless listed
    const dictionary& dict = scene.dict();
    const wordList allowed({"fluid", "soil"});
    if (foundEntry(dict, "gravityCoeffs"))
    {
        const dictionary& coeffs = dict.subDict("gravityCoeffs");
        // (OpenFOAM's list error names a stream, not the file: given here)
        const string unreadable = catchFatal
        (
            [&]() { phases_ = coeffs.get<wordList>("phases"); },
            false
        );
        if (!unreadable.empty())
        {
            FatalIOErrorInFunction(coeffs)
                << "phases is not a list of phases (e.g. (fluid soil)): "
                << unreadable.c_str() << exit(FatalIOError);
        }
        for (const word& ph : phases_)
        {
            if (!allowed.found(ph))
            {
                FatalIOErrorInFunction(coeffs)
                    << "phases: " << ph << " is not allowed: the phases are "
                    << allowed << exit(FatalIOError);
            }
        }
    }
    else
    {
        for (const word& ph : allowed)
        {
            if (scene.has(ph))
            {
                phases_.append(ph);
            }
        }
    }
    if (phases_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "gravity acts on the phases (fluid, soil), and the scene has"
            << " none: add fluid or soil to effects" << exit(FatalIOError);
    }

    for (const word& ph : phases_)
    {
        if (!scene.has(ph))
        {
            // (requires() names the missing phase with the scene's message)
            continue;
        }
        if (ph == "fluid")
        {
            scene.effect<physicsEffects::fluid>("fluid").lbm()
                .setBodyAcceleration(g_);
        }
        else
        {
            scene.effect<physicsEffects::soil>("soil").mpm().setGravity(g_);
        }
    }

    Info<< "Gravity " << g_ << " m/s2 (constant/g) on " << phases_ << nl
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::physicsEffects::gravity::plan() const
{
    return "set at the start, no cost per step";
}


// ************************************************************************* //
