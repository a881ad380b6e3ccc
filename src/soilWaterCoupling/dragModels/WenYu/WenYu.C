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

#include "WenYu.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(WenYu, 0);
    addToRunTimeSelectionTable(dragModel, WenYu, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragModels::WenYu::WenYu(const dictionary& dict)
:
    dragModel(typeName, dict),
    stokes_(18*muFluid_/(d_*d_)),
    rhoDByMu_(rhoFluid_*d_/muFluid_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragModels::WenYu::CdRe24(const scalar Rep)
{
    if (!(Rep > 0))
    {
        return 1;
    }
    return (Rep < 1000) ? 1 + 0.15*pow(Rep, 0.687) : 0.44*Rep/24;
}


Foam::scalar Foam::dragModels::WenYu::beta
(
    const scalar phi,
    const scalar slip
) const
{
    const scalar p = clipPhi(phi);
    const scalar n = 1 - p;

    return stokes_*p*pow(n, -2.65)*CdRe24(n*rhoDByMu_*slip);
}


// ************************************************************************* //
