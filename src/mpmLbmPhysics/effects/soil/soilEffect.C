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

#include "soilEffect.H"
#include "physicsScene.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(soil, 0);
    addToRunTimeSelectionTable(physicsEffect, soil, scene);
    addToMemberFunctionSelectionTable(physicsEffect, soil, haloWidth, mesh);
}
}


Foam::physicsEffects::soil::soil(physicsScene& scene)
:
    physicsEffect(scene),
    mpm_(scene.lattice()),
    mapped_(false)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::physicsEffects::soil::map()
{
    if (!mapped_)
    {
        mpm_.nodalFields(solidFraction_, nodeVelocity_);
        mapped_ = true;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::sceneStageList Foam::physicsEffects::soil::stages() const
{
    return sceneStageList
    ({
        scene_.needsSoilWithWater()
      ? sceneStage::soilWithWater
      : sceneStage::soilStep
    });
}


void Foam::physicsEffects::soil::evolve(const sceneStage)
{
    for (const auto& work : beforeAdvance_)
    {
        work();
    }
    mpm_.advance(scene_.mesh().time().deltaTValue());

    // The couplings' forces were for this step
    mpm_.clearPointForces();
    mapped_ = false;
}


void Foam::physicsEffects::soil::updateFields()
{
    mpm_.updateFields();
}


void Foam::physicsEffects::soil::write()
{
    mpm_.write();
}


void Foam::physicsEffects::soil::restartState
(
    restartManifest::stateTable& state
) const
{
    const materialPoints& p = mpm_.points();
    state.set("soilPoints", p.size());
    state.set("soilMass", sum(p.m));
}


void Foam::physicsEffects::soil::restartStateSources
(
    restartManifest::stateSources& sources
) const
{
    const fileName cloud("lagrangian"/materialPoints::cloudName);
    sources.set
    (
        "soilPoints", wordList({cloud/"coordinates", cloud/"positions"})
    );
    sources.set("soilMass", wordList({cloud/"mass"}));
}


Foam::wordList Foam::physicsEffects::soil::stateFiles() const
{
    // (a processor without points writes no cloud)
    return
        mpm_.points().size()
      ? wordList(1, "lagrangian"/materialPoints::cloudName)
      : wordList();
}


Foam::scalar Foam::physicsEffects::soil::updatesPerStep() const
{
    return mpm_.nPoints();
}


Foam::scalar Foam::physicsEffects::soil::updatesDone() const
{
    return mpm_.pointUpdates();
}


Foam::scalar Foam::physicsEffects::soil::memoryBytes() const
{
    return mpm_.memoryBytes();
}


Foam::string Foam::physicsEffects::soil::plan() const
{
    // The sub-steps follow the soil's stable step at every outer step: at
    // the start they are set by the p-wave speed (and the points' speed)
    const scalar deltaT = scene_.mesh().time().deltaTValue();
    const scalar dt = mpm_.stableDt();
    const label n = max(label(std::ceil(deltaT/dt - 1e-9)), label(1));
    return
        Foam::name(n) + " sub-steps of " + Foam::name(deltaT/n)
      + " s per step at the start (stable step " + Foam::name(dt)
      + " s = soilCFL " + Foam::name(mpm_.CFL()) + " dx/(c_p + |v|), c_p "
      + Foam::name(mpm_.pWaveSpeed()) + " m/s); re-planned every step";
}


Foam::string Foam::physicsEffects::soil::progress() const
{
    return
        "soil sub-steps " + Foam::name(mpm_.nSubSteps())
      + "  kinetic energy " + Foam::name(mpm_.kineticEnergy()) + " J";
}


// ************************************************************************* //
