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

#include "physicsEffect.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(physicsEffect, 0);
    defineRunTimeSelectionTable(physicsEffect, scene);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffect::physicsEffect(physicsScene& scene)
:
    scene_(scene)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::physicsEffect> Foam::physicsEffect::New
(
    const word& name,
    physicsScene& scene,
    const dictionary& dict
)
{
    auto cstrIter = sceneConstructorTablePtr_->cfind(name);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "effect",
            name,
            *sceneConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(scene);
}


// ************************************************************************* //
