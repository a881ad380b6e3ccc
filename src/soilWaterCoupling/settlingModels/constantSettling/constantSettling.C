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

#include "constantSettling.H"
#include "optionalEntry.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace settlingModels
{
    defineTypeNameAndDebug(constantSettling, 0);
    addToRunTimeSelectionTable(settlingModel, constantSettling, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::settlingModels::constantSettling::constantSettling
(
    const dictionary& dict
)
:
    settlingModel(typeName, dict)
{
    setVelocity
    (
        readPositive("ws", "[m/s] (the terminal velocity)"),
        foundEntry(coeffs_, "d") ? readPositive("d", "[m] (the grain diameter)") : 0
    );
}


// ************************************************************************* //
