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

#include "DiFelice.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(DiFelice, 0);
    addToRunTimeSelectionTable(dragModel, DiFelice, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragModels::DiFelice::DiFelice(const dictionary& dict)
:
    dragModel(typeName, dict),
    coeff_(0.75*muFluid_/(d_*d_)),
    rhoDByMu_(rhoFluid_*d_/muFluid_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragModels::DiFelice::chi(const scalar Rep)
{
    if (!(Rep > 0))
    {
        return 3.7;
    }
    const scalar x = 1.5 - log10(Rep);
    return 3.7 - 0.65*exp(-0.5*x*x);
}


Foam::scalar Foam::dragModels::DiFelice::beta
(
    const scalar phi,
    const scalar slip
) const
{
    const scalar p = clipPhi(phi);
    const scalar n = 1 - p;
    const scalar Rep = n*rhoDByMu_*slip;

    // C_D0 slip = (0.63 sqrt(Re_p) + 4.8)^2 mu/(n rho_f d): finite at 0
    const scalar a = 0.63*sqrt(Rep > 0 ? Rep : 0) + 4.8;

    return coeff_*p*pow(n, 1 - chi(Rep))*a*a;
}


// ************************************************************************* //
