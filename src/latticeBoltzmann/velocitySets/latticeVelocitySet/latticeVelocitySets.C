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

#include "latticeVelocitySet.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    typedef latticeVelocitySet<lattice::D2Q9> D2Q9VelocitySet;
    typedef latticeVelocitySet<lattice::D3Q19> D3Q19VelocitySet;
    typedef latticeVelocitySet<lattice::D3Q27> D3Q27VelocitySet;

    defineTemplateTypeNameAndDebugWithName(D2Q9VelocitySet, "D2Q9", 0);
    defineTemplateTypeNameAndDebugWithName(D3Q19VelocitySet, "D3Q19", 0);
    defineTemplateTypeNameAndDebugWithName(D3Q27VelocitySet, "D3Q27", 0);

    addToRunTimeSelectionTable(velocitySet, D2Q9VelocitySet, word);
    addToRunTimeSelectionTable(velocitySet, D3Q19VelocitySet, word);
    addToRunTimeSelectionTable(velocitySet, D3Q27VelocitySet, word);
}

// ************************************************************************* //
