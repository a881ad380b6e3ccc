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

#include "collisionModel.H"
#include "optionalEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(collisionModel, 0);
    defineRunTimeSelectionTable(collisionModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModel::collisionModel
(
    const word& type,
    const dictionary& dict,
    const velocitySet& vs
)
:
    dict_(dict),
    coeffs_(modelCoeffsDict(dict, type, dictionaryConstructorTablePtr_)),
    velocitySet_(vs)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::collisionModel> Foam::collisionModel::New
(
    const dictionary& dict,
    const velocitySet& vs
)
{
    const word modelType(dict.get<word>("collisionModel"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "collisionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict, vs);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionModel::report(Ostream& os) const
{
    os  << "    collision model " << type() << nl;
}


// ************************************************************************* //
