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

#include "suffusion.H"
#include "selectEntry.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace erosionLaws
{
    defineTypeNameAndDebug(suffusion, 0);
    addToRunTimeSelectionTable(erosionLaw, suffusion, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::erosionLaws::suffusion::suffusion(const dictionary& dict)
:
    erosionLaw(typeName, dict),
    lambda_(readCoeff("lambda", true, "[1/m]")),
    iC_(readCoeff("criticalGradient", false, "(a hydraulic gradient)")),
    cSeed_(readCoeff("seedConcentration", false, "(volume of fines per"
        " volume of pore water)"))
{
    if (!(cSeed_ < 1))
    {
        entryNotAllowed
        (
            coeffs_, "seedConcentration", cSeed_,
            "it is a volume fraction of the pore water, in [0, 1)"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::erosionLaws::suffusion::report(Ostream& os) const
{
    os  << "Erosion law suffusion (Vardoulakis, Stavropoulou &"
        << " Papanastasiou 1996): m_dot/rho_s = lambda (1 - n) c |q|,"
        << " lambda " << lambda_ << " 1/m, above the fines limit and the"
        << " critical gradient " << iC_ << ", c at least "
        << cSeed_ << nl;
}


// ************************************************************************* //
