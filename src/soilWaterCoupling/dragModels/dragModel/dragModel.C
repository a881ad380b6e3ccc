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

#include "dragModel.H"
#include "optionalEntry.H"
#include "selectEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(dragModel, 0);
    defineRunTimeSelectionTable(dragModel, dictionary);
}

constexpr Foam::scalar Foam::dragModel::phiMax;


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::dragModel::readPositiveCoeff
(
    const word& keyword,
    const scalar deflt
) const
{
    const scalar value = optionalEntry<scalar>(coeffs_, keyword, deflt);

    // Written so that NaN fails
    if (!(value > 0))
    {
        entryNotAllowed
        (
            coeffs_, keyword, value, "the coefficient must be > 0 (default "
          + Foam::name(deflt) + ")"
        );
    }
    return value;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::dragModel::dragModel(const word& type, const dictionary& dict)
:
    coeffs_(modelCoeffsDict(dict, type, dictionaryConstructorTablePtr_)),
    d_(dict.get<scalar>("d")),
    rhoFluid_(dict.get<scalar>("rhoFluid")),
    muFluid_(dict.get<scalar>("muFluid"))
{
    // Written so that NaN fails every test
    // (and bounded: 1e300 overflowed the drag laws' powers)
    if (!(d_ > 0 && d_ <= 10))
    {
        entryNotAllowed
        (
            dict, "d", d_, "the grain diameter must lie in (0, 10] [m]"
        );
    }
    if (!(rhoFluid_ > 0 && rhoFluid_ <= 1e5))
    {
        entryNotAllowed
        (
            dict, "rhoFluid", rhoFluid_,
            "the fluid density must lie in (0, 1e5] [kg/m3]"
        );
    }
    if (!(muFluid_ > 0 && muFluid_ <= 1e6))
    {
        entryNotAllowed
        (
            dict, "muFluid", muFluid_,
            "the (physical) fluid dynamic viscosity must lie in (0, 1e6]"
            " [Pa s] (water 1e-3)"
        );
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::dragModel> Foam::dragModel::New(const dictionary& dict)
{
    const word modelType(dict.get<word>("dragModel"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "dragModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::dragModel::permeability(const scalar phi) const
{
    const scalar n = 1 - clipPhi(phi);
    const scalar beta0 = beta(phi, 0);

    return (beta0 > 0) ? n*n*muFluid_/beta0 : VGREAT;
}


Foam::scalar Foam::dragModel::hydraulicConductivity
(
    const scalar phi,
    const scalar g
) const
{
    const scalar k = permeability(phi);

    return (k < VGREAT) ? k*rhoFluid_*g/muFluid_ : VGREAT;
}


void Foam::dragModel::report(Ostream& os) const
{
    const scalar phi = 0.63;

    os  << "    dragModel " << type() << ": d " << d_ << " m, rhoFluid "
        << rhoFluid_ << " kg/m3, muFluid " << muFluid_ << " Pa s" << nl
        << "        at phi " << phi << ": beta(slip 0) " << beta(phi, 0)
        << " kg/(m3 s), permeability " << permeability(phi)
        << " m2, hydraulic conductivity "
        << hydraulicConductivity(phi, 9.81) << " m/s (g 9.81)" << nl;
}


// ************************************************************************* //
