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

#include "sceneStages.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::sceneStage> Foam::sceneStageNames
({
    { sceneStage::soilStep, "soilStep" },
    { sceneStage::exchange, "exchange" },
    { sceneStage::porosity, "porosity" },
    { sceneStage::forcing, "forcing" },
    { sceneStage::streamPrepare, "streamPrepare" },
    { sceneStage::soilWithWater, "soilWithWater" },
    { sceneStage::streamCollide, "streamCollide" },
    { sceneStage::transport, "transport" },
    { sceneStage::interfaceUpdate, "interfaceUpdate" },
    { sceneStage::endStep, "endStep" },
});


// ************************************************************************* //
