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

#include "settlingModel.H"
#include "optionalEntry.H"
#include "selectEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(settlingModel, 0);
    defineRunTimeSelectionTable(settlingModel, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::settlingModel::readPositive
(
    const word& keyword,
    const string& units
) const
{
    const scalar value = coeffs_.get<scalar>(keyword);
    // Written so that NaN fails
    if (!(value > 0) || !std::isfinite(value))
    {
        entryNotAllowed
        (
            coeffs_, keyword, value, "it must be > 0 and finite " + units
        );
    }
    return value;
}


void Foam::settlingModel::setVelocity(const scalar ws, const scalar d)
{
    ws_ = ws;
    d_ = d;
    if (!hindered_)
    {
        n_ = 1;
        return;
    }
    // Rowe (1987): Richardson & Zaki's exponent, continuous in Re_p
    const scalar Re = d > 0 ? terminalVelocity()*d/nuFluid_ : 0;
    const scalar r = std::pow(Re, 0.75);
    n_ = (4.7 + 0.41*r)/(1 + 0.175*r);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::settlingModel::settlingModel(const word& type, const dictionary& dict)
:
    coeffs_(modelCoeffsDict(dict, type, dictionaryConstructorTablePtr_)),
    rhoFluid_(dict.get<scalar>("rhoFluid")),
    nuFluid_(dict.get<scalar>("nuFluid")),
    rhoSolid_(dict.get<scalar>("rhoSolid")),
    g_(dict.get<scalar>("g")),
    hindered_(optionalEntry<bool>(coeffs_, "hindered", true)),
    d_(0),
    ws_(0),
    n_(4.7)
{
    if (!(rhoFluid_ > 0))
    {
        entryNotAllowed(dict, "rhoFluid", rhoFluid_, "it must be > 0 [kg/m3]");
    }
    if (!(nuFluid_ > 0))
    {
        entryNotAllowed(dict, "nuFluid", nuFluid_, "it must be > 0 [m2/s]");
    }
    if (!(rhoSolid_ > rhoFluid_) || !std::isfinite(rhoSolid_))
    {
        entryNotAllowed
        (
            dict, "rhoSolid", rhoSolid_,
            "the grains must be denser than the water (rhoFluid "
          + Foam::name(rhoFluid_) + " kg/m3), and finite, to settle"
        );
    }
    if (!(g_ > 0) || !std::isfinite(g_))
    {
        entryNotAllowed
        (
            dict, "g", g_,
            "grains settle under gravity: constant/g must be non-zero"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::settlingModel::report(Ostream& os) const
{
    os  << "Settling " << type() << ": terminal velocity " << ws_ << " m/s";
    if (d_ > 0)
    {
        os  << ", d " << d_ << " m (Re_p " << ws_*d_/nuFluid_ << ")";
    }
    os  << ", water's viscosity nu " << nuFluid_ << " m2/s";
    if (hindered_)
    {
        os  << ", hindered (1 - phi)^" << n_ << " (Richardson-Zaki, Rowe"
            << (d_ > 0 ? ")" : "; no d: the fine-grain limit)");
    }
    os  << nl;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::settlingModel> Foam::settlingModel::New
(
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("settlingModel"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "settlingModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


// ************************************************************************* //
