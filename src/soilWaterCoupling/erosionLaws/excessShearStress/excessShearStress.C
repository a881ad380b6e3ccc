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

#include "excessShearStress.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace erosionLaws
{
    defineTypeNameAndDebug(excessShearStress, 0);
    addToRunTimeSelectionTable(erosionLaw, excessShearStress, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::erosionLaws::excessShearStress::excessShearStress
(
    const word& type,
    const dictionary& dict,
    const bool readTauC
)
:
    erosionLaw(type, dict),
    kEr_(readCoeff("kEr", false, "[s/m]")),
    tauC_(readTauC ? readCoeff("tauC", false, "[Pa]") : 0)
{}


Foam::erosionLaws::excessShearStress::excessShearStress
(
    const dictionary& dict
)
:
    excessShearStress(typeName, dict, true)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::erosionLaws::excessShearStress::report(Ostream& os) const
{
    os  << "Erosion law excessShearStress (Wan & Fell 2004; Bonelli &"
        << " Brivois 2008): m_dot = kEr (tau - tauC), kEr " << kEr_
        << " s/m (erosion rate index " << (kEr_ > 0 ? -log10(kEr_) : GREAT)
        << "), tauC " << tauC_ << " Pa" << nl;
}


// ************************************************************************* //
