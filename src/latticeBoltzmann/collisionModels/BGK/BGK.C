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

#include "BGK.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(BGK, 0);
    addToRunTimeSelectionTable(collisionModel, BGK, dictionary);
}
}


Foam::collisionModels::BGK::BGK
(
    const dictionary& dict,
    const velocitySet& vs
)
:
    collisionModel(typeName, dict, vs)
{}


void Foam::collisionModels::BGK::streamCollide
(
    const lbmKernelArgs& a,
    lbmKernelStats& stats
) const
{
    dispatch<BGKOperator>
    (
        a, stats,
        [](auto vs) { return BGKOperator<decltype(vs)>(); }
    );
}


// ************************************************************************* //
