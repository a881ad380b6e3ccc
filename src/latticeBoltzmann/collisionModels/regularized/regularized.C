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

#include "regularized.H"
#include "optionalEntry.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(regularized, 0);
    addToRunTimeSelectionTable(collisionModel, regularized, dictionary);
}
}


Foam::collisionModels::regularized::regularized
(
    const dictionary& dict,
    const velocitySet& vs
)
:
    collisionModel(typeName, dict, vs),
    recursive_(optionalEntry<bool>(coeffs_, "recursive", false))
{}


void Foam::collisionModels::regularized::streamCollide
(
    const lbmKernelArgs& a,
    lbmKernelStats& stats
) const
{
    if (recursive_)
    {
        dispatch<regularizedRecursiveOperator>
        (
            a, stats,
            [](auto vs)
            {
                return regularizedRecursiveOperator<decltype(vs)>{};
            }
        );
    }
    else
    {
        dispatch<regularizedOperator>
        (
            a, stats,
            [](auto vs) { return regularizedOperator<decltype(vs)>{}; }
        );
    }
}


void Foam::collisionModels::regularized::report(Ostream& os) const
{
    os  << "    collision model regularized"
        << (recursive_ ? " (recursive, third order)" : " (second order)")
        << nl;
}


// ************************************************************************* //
