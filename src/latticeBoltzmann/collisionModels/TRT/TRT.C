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

#include "TRT.H"
#include "optionalEntry.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(TRT, 0);
    addToRunTimeSelectionTable(collisionModel, TRT, dictionary);
}
}


Foam::collisionModels::TRT::TRT
(
    const dictionary& dict,
    const velocitySet& vs
)
:
    collisionModel(typeName, dict, vs),
    magic_(optionalEntry<scalar>(coeffs_, "magic", 3.0/16.0))
{
    if (!(magic_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "TRTCoeffs: magic " << magic_ << " is not allowed:"
            << " the magic parameter Lambda must be > 0"
            << " (3/16 = 0.1875 for exact half-way walls, 1/4 for the"
            << " best stability)" << exit(FatalIOError);
    }
}


void Foam::collisionModels::TRT::streamCollide
(
    const lbmKernelArgs& a,
    lbmKernelStats& stats
) const
{
    const scalar magic = magic_;
    const scalar omega0 = a.omega;
    const scalar omegaMinus0 = 1.0/(magic/(1.0/omega0 - 0.5) + 0.5);
    dispatch<TRTOperator>
    (
        a, stats,
        [=](auto vs)
        {
            return TRTOperator<decltype(vs)>{magic, omega0, omegaMinus0};
        }
    );
}


void Foam::collisionModels::TRT::report(Ostream& os) const
{
    os  << "    collision model TRT, magic parameter " << magic_ << nl;
}


// ************************************************************************* //
