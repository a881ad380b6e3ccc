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

#include "shapeFunction.H"
#include "optionalEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(shapeFunction, 0);
    defineRunTimeSelectionTable(shapeFunction, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::shapeFunction::shapeFunction
(
    const word& type,
    const dictionary& dict,
    const label support,
    const label reach
)
:
    dict_(dict),
    coeffs_(modelCoeffsDict(dict, type, dictionaryConstructorTablePtr_)),
    support_(support),
    reach_(reach)
{
    if (support_ < 1 || support_ > shapeWeights::maxSupport)
    {
        FatalErrorInFunction
            << "Shape function " << type << " has support " << support_
            << ": must be 1 to " << shapeWeights::maxSupport
            << abort(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::shapeFunction> Foam::shapeFunction::New
(
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("shapeFunction"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "shapeFunction",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::shapeFunction::checkHalfLength
(
    const scalar halfLength,
    const string& where
) const
{
    if (!(halfLength >= 0) || halfLength > maxHalfLength())
    {
        FatalErrorInFunction
            << "Shape function " << type() << ": particle half-size "
            << halfLength << (where.empty() ? "" : " (") << where.c_str()
            << (where.empty() ? "" : ")")
            << " (lattice units, i.e. in cells) is outside"
            << " [0, " << maxHalfLength() << "]. With GIMP a particle may"
            << " not be larger than a cell: use at least 1 point per cell"
            << " and direction." << exit(FatalError);
    }
}


void Foam::shapeFunction::report(Ostream& os) const
{
    os  << "    shape function " << type() << ", support " << support_
        << " nodes per direction, reach " << reach_ << nl;
}


// ************************************************************************* //
