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

#include "erosionLaw.H"
#include "selectEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(erosionLaw, 0);
    defineRunTimeSelectionTable(erosionLaw, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::erosionLaw::readCoeff
(
    const word& keyword,
    const bool positive,
    const string& units
) const
{
    const scalar value = coeffs_.get<scalar>(keyword);

    // Written so that NaN fails
    if (positive ? !(value > 0) : !(value >= 0))
    {
        entryNotAllowed
        (
            coeffs_, keyword, value,
            string(positive ? "it must be > 0 " : "it must be >= 0 ") + units
        );
    }
    if (!std::isfinite(value))
    {
        entryNotAllowed(coeffs_, keyword, value, "it must be finite " + units);
    }
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::erosionLaw::erosionLaw(const word& type, const dictionary& dict)
:
    coeffs_(dict.subDict(type + "Coeffs")),
    rhoFluid_(dict.get<scalar>("rhoFluid")),
    nuFluid_(dict.get<scalar>("nuFluid")),
    rhoSolid_(dict.get<scalar>("rhoSolid")),
    g_(dict.get<scalar>("g"))
{
    if (!(rhoFluid_ > 0))
    {
        entryNotAllowed(dict, "rhoFluid", rhoFluid_, "it must be > 0 [kg/m3]");
    }
    if (!(nuFluid_ > 0))
    {
        entryNotAllowed(dict, "nuFluid", nuFluid_, "it must be > 0 [m2/s]");
    }
    if (!(rhoSolid_ > rhoFluid_))
    {
        entryNotAllowed
        (
            dict, "rhoSolid", rhoSolid_,
            "the grains must be denser than the water (rhoFluid "
          + Foam::name(rhoFluid_) + " kg/m3)"
        );
    }
    if (!(g_ >= 0) || !std::isfinite(g_))
    {
        entryNotAllowed(dict, "g", g_, "it must be >= 0 and finite [m/s2]");
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::erosionLaw> Foam::erosionLaw::New(const dictionary& dict)
{
    const word lawType(dict.get<word>("erosionLaw"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "erosionLaw",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


// ************************************************************************* //
