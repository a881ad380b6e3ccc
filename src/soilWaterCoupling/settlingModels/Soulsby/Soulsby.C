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

#include "Soulsby.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace settlingModels
{
    defineTypeNameAndDebug(Soulsby, 0);
    addToRunTimeSelectionTable(settlingModel, Soulsby, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::settlingModels::Soulsby::Soulsby(const dictionary& dict)
:
    settlingModel(typeName, dict)
{
    const scalar d = readPositive("d", "[m] (the grain diameter)");
    const scalar s = rhoSolid_/rhoFluid_;
    const scalar Dstar = d*std::cbrt(g_*(s - 1)/(nuFluid_*nuFluid_));
    setVelocity
    (
        nuFluid_/d*(std::sqrt(10.36*10.36 + 1.049*Dstar*Dstar*Dstar) - 10.36),
        d
    );
}


// ************************************************************************* //
