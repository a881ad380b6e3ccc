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

#include "filtrationLaw.H"
#include "selectEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(filtrationLaw, 0);
    defineRunTimeSelectionTable(filtrationLaw, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::filtrationLaw::readCoeff
(
    const word& keyword,
    const scalar upper,
    const string& units
) const
{
    const scalar value = coeffs_.get<scalar>(keyword);

    // Written so that NaN fails
    if (!(value > 0) || !(value < upper) || !std::isfinite(value))
    {
        entryNotAllowed
        (
            coeffs_, keyword, value,
            "it must be > 0"
          + (upper < VGREAT ? " and < " + Foam::name(upper) : string(""))
          + " and finite " + units
        );
    }
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::filtrationLaw::filtrationLaw(const word& type, const dictionary& dict)
:
    coeffs_(dict.subDict(type + "Coeffs"))
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::filtrationLaw>
Foam::filtrationLaw::New(const dictionary& dict)
{
    const word lawType(dict.get<word>("filtrationLaw"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "filtrationLaw",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


// ************************************************************************* //
