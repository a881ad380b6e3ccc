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

#include "deepBed.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace filtrationLaws
{
    defineTypeNameAndDebug(deepBed, 0);
    addToRunTimeSelectionTable(filtrationLaw, deepBed, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::filtrationLaws::deepBed::deepBed(const dictionary& dict)
:
    filtrationLaw(typeName, dict),
    lambda_(readCoeff("lambda", VGREAT, "[1/m]")),
    fMax_(readCoeff("maxFinesContent", 1, "(a mass fraction of the solid)"))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::filtrationLaws::deepBed::report(Ostream& os) const
{
    os  << "Filtration law deepBed (Iwasaki 1937; blocking of Herzig et al."
        << " 1970): m_dot = lambda |q| C (1 - f/f_max), lambda " << lambda_
        << " 1/m, f_max " << fMax_ << nl;
}


// ************************************************************************* //
