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

#include "Stokes.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace settlingModels
{
    defineTypeNameAndDebug(Stokes, 0);
    addToRunTimeSelectionTable(settlingModel, Stokes, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::settlingModels::Stokes::Stokes(const dictionary& dict)
:
    settlingModel(typeName, dict)
{
    const scalar d = readPositive("d", "[m] (the grain diameter)");
    setVelocity((rhoSolid_ - rhoFluid_)*g_*d*d/(18*rhoFluid_*nuFluid_), d);
}


// ************************************************************************* //
