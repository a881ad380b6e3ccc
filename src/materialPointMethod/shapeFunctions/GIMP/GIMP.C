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

#include "GIMP.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace shapeFunctions
{
    defineTypeNameAndDebug(GIMP, 0);
    addToRunTimeSelectionTable(shapeFunction, GIMP, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::shapeFunctions::GIMP::GIMP(const dictionary& dict)
:
    shapeFunction(typeName, dict, supportSize, reachSize)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::shapeFunctions::GIMP::weights1D
(
    const scalar x,
    const scalar halfLength,
    label& first,
    scalar* w,
    scalar* dw
) const
{
    eval(x, halfLength, first, w, dw);
}


// ************************************************************************* //
