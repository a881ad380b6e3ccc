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

#include "constitutiveModel.H"
#include "optionalEntry.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(constitutiveModel, 0);
    defineRunTimeSelectionTable(constitutiveModel, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::constitutiveModel::notAllowed
(
    const dictionary& dict,
    const word& keyword,
    const scalar value,
    const string& reason
) const
{
    FatalIOErrorInFunction(dict)
        << keyword << ' ' << value << " is not allowed: " << reason.c_str()
        << " (material " << name_ << ")" << exit(FatalIOError);
}


void Foam::constitutiveModel::readFrictionalStrength
(
    scalar& cohesion,
    scalar& frictionAngle,
    scalar& dilationAngle
) const
{
    cohesion = coeffs_.get<scalar>("cohesion");
    const scalar phiDeg = coeffs_.get<scalar>("frictionAngle");
    const scalar psiDeg = coeffs_.get<scalar>("dilationAngle");

    // Written so that NaN fails every test
    if (!(cohesion >= 0))
    {
        notAllowed
        (
            coeffs_, "cohesion", cohesion, "the cohesion must be >= 0 [Pa]"
        );
    }
    if (!(phiDeg >= 0 && phiDeg < 90))
    {
        notAllowed
        (
            coeffs_, "frictionAngle", phiDeg,
            "the friction angle must lie in [0, 90) degrees"
        );
    }
    if (!(psiDeg >= 0 && psiDeg <= phiDeg))
    {
        notAllowed
        (
            coeffs_, "dilationAngle", psiDeg,
            "the dilation angle must lie in [0, frictionAngle] = [0, "
          + Foam::name(phiDeg) + "] degrees"
        );
    }

    frictionAngle = degToRad(phiDeg);
    dilationAngle = degToRad(psiDeg);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::constitutiveModel::constitutiveModel
(
    const word& type,
    const word& name,
    const dictionary& dict
)
:
    name_(name),
    coeffs_(modelCoeffsDict(dict, type, dictionaryConstructorTablePtr_)),
    rho_(dict.get<scalar>("rho")),
    E_(dict.get<scalar>("E")),
    nu_(dict.get<scalar>("nu")),
    G_(0),
    K_(0),
    lambda_(0),
    M_(0)
{
    // (upper bounds beyond any soil or rock, osmium 22590 kg/m3, diamond
    // 1.2e12 Pa: 1e300 passed and the soil's step underflowed to 1e-144)
    if (!(rho_ > 0 && rho_ <= 1e5))
    {
        notAllowed
        (
            dict, "rho", rho_,
            "the density must lie in (0, 1e5] kg/m3 (the solid's mass per"
            " mixture volume, phi rho_s)"
        );
    }
    if (!(E_ > 0 && E_ <= 1e13))
    {
        notAllowed
        (
            dict, "E", E_, "Young's modulus must lie in (0, 1e13] Pa"
        );
    }
    if (!(nu_ > -1 && nu_ < 0.5))
    {
        notAllowed
        (
            dict, "nu", nu_, "Poisson's ratio must lie in (-1, 0.5)"
        );
    }

    G_ = E_/(2*(1 + nu_));
    K_ = E_/(3*(1 - 2*nu_));
    lambda_ = E_*nu_/((1 + nu_)*(1 - 2*nu_));
    M_ = E_*(1 - nu_)/((1 + nu_)*(1 - 2*nu_));
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::constitutiveModel> Foam::constitutiveModel::New
(
    const word& name,
    const dictionary& dict
)
{
    const word modelType(dict.get<word>("model"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "model",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(name, dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::constitutiveModel::pWaveSpeed() const
{
    return sqrt(M_/rho_);
}


void Foam::constitutiveModel::updateStresses
(
    const label n,
    const symmTensor* dStrain,
    symmTensor* stress,
    scalar* plasticStrain
) const
{
    for (label i = 0; i < n; ++i)
    {
        updateStress(dStrain[i], stress[i], plasticStrain[i]);
    }
}


void Foam::constitutiveModel::report(Ostream& os) const
{
    os  << "    material " << name_ << ": model " << type()
        << ", rho " << rho_ << " kg/m3, E " << E_ << " Pa, nu " << nu_
        << nl
        << "        G " << G_ << " Pa, K " << K_ << " Pa, M " << M_
        << " Pa, p-wave speed " << pWaveSpeed() << " m/s" << nl;
}


// ************************************************************************* //
