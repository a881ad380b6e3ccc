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

#include "velocitySet.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(velocitySet, 0);
    defineRunTimeSelectionTable(velocitySet, word);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::velocitySet> Foam::velocitySet::New
(
    const word& name,
    const dictionary& dict
)
{
    auto cstrIter = wordConstructorTablePtr_->cfind(name);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "velocitySet",
            name,
            *wordConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::velocitySet::direction(const labelVector& v) const
{
    forAll(c_, q)
    {
        if (c_[q] == v)
        {
            return q;
        }
    }
    return -1;
}


// ************************************************************************* //
