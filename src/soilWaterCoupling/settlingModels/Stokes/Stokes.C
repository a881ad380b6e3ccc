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
    settlingModel(typeName, dict),
    d_(readPositive("d", "[m] (the grain diameter)")),
    ws_((rhoSolid_ - rhoFluid_)*g_*d_*d_/(18*rhoFluid_*nuFluid_))
{
    setExponent(d_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::settlingModels::Stokes::report(Ostream& os) const
{
    os  << "Settling Stokes: d " << d_ << " m, terminal velocity " << ws_
        << " m/s (Re_p " << ws_*d_/nuFluid_ << ")";
    if (hindered_)
    {
        os  << ", hindered (1 - phi)^" << n_ << " (Richardson-Zaki, Rowe)";
    }
    os  << nl;
}


// ************************************************************************* //
