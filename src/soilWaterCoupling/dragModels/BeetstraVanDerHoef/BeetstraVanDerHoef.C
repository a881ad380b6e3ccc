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

#include "BeetstraVanDerHoef.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(BeetstraVanDerHoef, 0);
    addToRunTimeSelectionTable(dragModel, BeetstraVanDerHoef, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragModels::BeetstraVanDerHoef::BeetstraVanDerHoef
(
    const dictionary& dict
)
:
    dragModel(typeName, dict),
    stokes_(18*muFluid_/(d_*d_)),
    rhoDByMu_(rhoFluid_*d_/muFluid_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragModels::BeetstraVanDerHoef::Fhat
(
    const scalar phi,
    const scalar Re
)
{
    const scalar n = 1 - phi;
    const scalar n2 = n*n;

    // Viscous part (Re -> 0): the Kozeny-Carman term plus the correction
    // that makes Fhat -> 1 in the dilute limit (van der Hoef et al. 2005)
    scalar F = 10*phi/n2 + n2*(1 + 1.5*sqrt(phi));

    // Inertial part (Beetstra et al. 2007) as written by Baumgarten &
    // Kamrin (2019): Re [...]/(1 + 10^(3 phi) Re^-e) with Re^-0.343 taken
    // into the bracket. For Re -> 0, Re^-e overflows to inf and the ratio
    // tends to 0 without NaN; for large Re nothing overflows.
    if (Re > 0)
    {
        const scalar e = 0.5 + 2*phi;
        F +=
            0.413/(24*n2)
           *((1/n + 3*phi*n)*Re + 8.4*pow(Re, 0.657))
           /(1 + pow(10.0, 3*phi)*pow(Re, -e));
    }

    return F;
}


Foam::scalar Foam::dragModels::BeetstraVanDerHoef::beta
(
    const scalar phi,
    const scalar slip
) const
{
    const scalar p = clipPhi(phi);
    const scalar n = 1 - p;

    return stokes_*p*n*Fhat(p, n*rhoDByMu_*slip);
}


// ************************************************************************* //
