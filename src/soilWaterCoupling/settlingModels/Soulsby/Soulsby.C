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
    settlingModel(typeName, dict),
    d_(readPositive("d", "[m] (the grain diameter)")),
    ws_(0)
{
    const scalar s = rhoSolid_/rhoFluid_;
    const scalar Dstar = d_*std::cbrt(g_*(s - 1)/(nuFluid_*nuFluid_));
    ws_ =
        nuFluid_/d_
       *(std::sqrt(10.36*10.36 + 1.049*Dstar*Dstar*Dstar) - 10.36);
    setExponent(d_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::settlingModels::Soulsby::report(Ostream& os) const
{
    os  << "Settling Soulsby: d " << d_ << " m, terminal velocity " << ws_
        << " m/s (Re_p " << ws_*d_/nuFluid_ << ")";
    if (hindered_)
    {
        os  << ", hindered (1 - phi)^" << n_ << " (Richardson-Zaki, Rowe)";
    }
    os  << nl;
}


// ************************************************************************* //
