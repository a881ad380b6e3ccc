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

#include "quadraticBSpline.H"
#include "makeShapeFunction.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makeShapeFunction(quadraticBSpline);


// ************************************************************************* //
