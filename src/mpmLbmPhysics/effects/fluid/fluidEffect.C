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

#include "fluidEffect.H"
#include "physicsScene.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(fluid, 0);
    addToRunTimeSelectionTable(physicsEffect, fluid, scene);
    addToMemberFunctionSelectionTable(physicsEffect, fluid, haloWidth, mesh);
}
}


Foam::physicsEffects::fluid::fluid(physicsScene& scene)
:
    physicsEffect(scene),
    lbm_(scene.lattice())
{
    // Bodies in the water are for the water and what it carries alone
    // (a transported scalar closes its links into them): the couplings
    // with the soil do not know their solid nodes yet
    if (!lbm_.obstacles().empty())
    {
        const wordList effects(scene.dict().get<wordList>("effects"));
        const wordList allowed
        ({
            "fluid", "gravity", "freeSurface", "scalarTransport"
        });
        for (const word& e : effects)
        {
            if (!allowed.found(e))
            {
                FatalIOErrorInFunction(lbm_.dict())
                    << "obstacles " << lbm_.obstacles().names()
                    << " are for the water alone: the scene's effect " << e
                    << " (constant/physicsProperties effects " << effects
                    << ") does not take bodies in the water into account."
                    << nl << "    Allowed with obstacles: " << allowed
                    << "; or give the body as cells missing from the mesh"
                    << exit(FatalIOError);
            }
        }
    }
}


void Foam::physicsEffects::fluid::evolve(const sceneStage stage)
{
    if (stage == sceneStage::streamPrepare)
    {
        lbm_.prepareStream();
    }
    else
    {
        lbm_.step();
    }
}


Foam::string Foam::physicsEffects::fluid::plan() const
{
    const lbmUnits& u = lbm_.units();
    return
        "one lattice step per step, " + Foam::name(u.dt()) + " s (tau "
      + Foam::name(u.tau()) + ", lattice speed dx/dt "
      + Foam::name(u.velocityScale()) + " m/s)";
}


void Foam::physicsEffects::fluid::updateFields()
{
    lbm_.updateFields();
}


void Foam::physicsEffects::fluid::write()
{
    lbm_.writePopulations();
    if (lbm_.writesViscousStress())
    {
        lbm_.writeViscousStress();
    }
}


void Foam::physicsEffects::fluid::restartState
(
    restartManifest::stateTable& state
) const
{
    state.set("waterNodes", lbm_.lattice().cellNode().size());
    // (water that was set at equilibrium from U and p has no written mass
    // to be compared with)
    if (lbm_.restarted() || lbm_.nSteps() > 0)
    {
        state.set("waterLatticeMass", lbm_.populationSum());
    }
}


void Foam::physicsEffects::fluid::restartStateSources
(
    restartManifest::stateSources& sources
) const
{
    sources.set("waterLatticeMass", lbm_.populationFiles());
}


Foam::wordList Foam::physicsEffects::fluid::stateFiles() const
{
    return lbm_.populationFiles();
}


Foam::scalar Foam::physicsEffects::fluid::updatesPerStep() const
{
    return lbm_.nNodes();
}


Foam::scalar Foam::physicsEffects::fluid::updatesDone() const
{
    return scalar(lbm_.nNodes())*lbm_.nSteps();
}


Foam::scalar Foam::physicsEffects::fluid::memoryBytes() const
{
    return lbm_.memoryBytes();
}


Foam::string Foam::physicsEffects::fluid::progress() const
{
    const lbmKernelStats& s = lbm_.stats();
    const scalar Ma = std::sqrt(returnReduce(s.u2Max, maxOp<scalar>())*3.0);
    return
        "Mach " + Foam::name(Ma)
      + "  mass defect " + Foam::name(lbm_.massDefect());
}


// ************************************************************************* //
