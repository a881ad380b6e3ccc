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

#include "constantSettling.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace settlingModels
{
    defineTypeNameAndDebug(constantSettling, 0);
    addToRunTimeSelectionTable(settlingModel, constantSettling, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::settlingModels::constantSettling::constantSettling
(
    const dictionary& dict
)
:
    settlingModel(typeName, dict),
    d_(coeffs_.found("d") ? readPositive("d", "[m] (the grain diameter)") : 0),
    ws_(readPositive("ws", "[m/s] (the terminal velocity)"))
{
    setExponent(d_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::settlingModels::constantSettling::report(Ostream& os) const
{
    os  << "Settling constant: terminal velocity " << ws_ << " m/s";
    if (hindered_)
    {
        os  << ", hindered (1 - phi)^" << n_ << " (Richardson-Zaki, Rowe"
            << (d_ > 0 ? ")" : "; no d: the fine-grain limit)");
    }
    os  << nl;
}


// ************************************************************************* //
