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

Description
    MohrCoulomb: selection, construction (the constants of the return),
    the point updates and the report. The returns:
    MohrCoulombScalarReturn.C (point at a time) and
    MohrCoulombPackedReturn.C (four points at once).

\*---------------------------------------------------------------------------*/

#include "MohrCoulomb.H"
#include "optionalEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace constitutiveModels
{
    defineTypeNameAndDebug(MohrCoulomb, 0);
    addToRunTimeSelectionTable(constitutiveModel, MohrCoulomb, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::constitutiveModels::MohrCoulomb::MohrCoulomb
(
    const word& name,
    const dictionary& dict
)
:
    constitutiveModel(typeName, name, dict),
    cohesion_(0),
    phi_(0),
    psi_(0),
    k_(1),
    m_(1),
    sigmaC_(0),
    gMax_(0),
    hasApex_(false),
    sigmaApex_(GREAT),
    sigmaT_(GREAT),
    tensionActive_(false)
{
    readFrictionalStrength(cohesion_, phi_, psi_);

    const scalar sinPhi = sin(phi_);
    const scalar sinPsi = sin(psi_);

    // k - 1 = 2 sin(phi)/(1 - sin(phi)) without cancellation at small phi
    k_ = 1 + 2*sinPhi/(1 - sinPhi);
    m_ = 1 + 2*sinPsi/(1 - sinPsi);
    sigmaC_ = 2*cohesion_*sqrt(k_);
    gMax_ = sqrt(sqr(k_) + k_ + 1);

    hasApex_ = (phi_ > 0);
    sigmaApex_ = hasApex_ ? cohesion_*cos(phi_)/sinPhi : GREAT;

    // Tension cut-off
    sigmaT_ = sigmaApex_;
    if (foundEntry(coeffs_, "tensionCutoff"))
    {
        const scalar sigmaT = coeffs_.get<scalar>("tensionCutoff");
        if (!(sigmaT >= 0))
        {
            notAllowed
            (
                coeffs_, "tensionCutoff", sigmaT,
                "the tension cut-off must be >= 0 [Pa]"
                " (0: no tensile principal stress)"
            );
        }
        if (sigmaT > sigmaApex_)
        {
            IOWarningInFunction(coeffs_)
                << "tensionCutoff " << sigmaT << " lies above the apex"
                << " c cot(phi) = " << sigmaApex_ << " of material "
                << name_ << ": it has no effect" << endl;
        }
        else
        {
            sigmaT_ = sigmaT;
        }
    }
    tensionActive_ = (sigmaT_ < sigmaApex_);


    // Constants of the principal-space return (Clausen et al. 2007)

    // Planes a.sigma <= c with flow directions b: the Mohr-Coulomb plane of
    // the sorted sector and the planes of the two neighbouring sectors that
    // meet it along line 1 and line 2, then the Rankine planes
    const vector b[6] =
    {
        vector(m_, 0, -1),
        vector(0, m_, -1),
        vector(m_, -1, 0),
        vector(1, 0, 0),
        vector(0, 1, 0),
        vector(0, 0, 1)
    };
    a_[0] = vector(k_, 0, -1);
    a_[1] = vector(0, k_, -1);
    a_[2] = vector(k_, -1, 0);
    a_[3] = b[3];
    a_[4] = b[4];
    a_[5] = b[5];
    for (label i = 0; i < 6; ++i)
    {
        Db_[i] = D(b[i]);
        c_[i] = (i < 3 ? sigmaC_ : sigmaT_);
    }

    rp_ = Db_[0]/(a_[0] & Db_[0]);
    const vector rp2(Db_[1]/(a_[1] & Db_[1]));
    const vector rp3(Db_[2]/(a_[2] & Db_[2]));

    r1_ = vector(1, 1, k_);
    r2_ = vector(1, k_, k_);

    if (hasApex_)
    {
        P1_ = sigmaApex_*vector::one;
        P2_ = P1_;
    }
    else
    {
        // Tresca: the lines run parallel to the hydrostatic axis and never
        // meet. A point of each: line 1 (s1 = s2, s1 - s3 = sigma_c) and
        // line 2 (s2 = s3, s1 - s3 = sigma_c)
        P1_ = vector(0, 0, -sigmaC_);
        P2_ = vector(sigmaC_, 0, 0);
    }

    // Keep the order of the cross products (fixes the signs of the tests)
    nI_ = rp_ ^ r1_;
    nII_ = rp_ ^ r2_;
    N2_ = rp_ ^ rp2;
    N3_ = rp_ ^ rp3;
    N2r1_ = N2_ & r1_;
    N3r2_ = N3_ & r2_;

    if (!(mag(N2r1_) > SMALL*mag(N2_)*mag(r1_)))
    {
        FatalErrorInFunction
            << "Degenerate line return for material " << name_
            << " (k = " << k_ << ", m = " << m_ << ")" << abort(FatalError);
    }
    if (!(mag(N3r2_) > SMALL*mag(N3_)*mag(r2_)))
    {
        FatalErrorInFunction
            << "Degenerate line return for material " << name_
            << " (k = " << k_ << ", m = " << m_ << ")" << abort(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::constitutiveModels::MohrCoulomb::returnRegion
Foam::constitutiveModels::MohrCoulomb::update
(
    const symmTensor& dStrain,
    symmTensor& stress,
    scalar& plasticStrain
) const
{
    returnRegion region = elastic;
    updatePacked(1, &dStrain, &stress, &plasticStrain, &region);
    return region;
}


void Foam::constitutiveModels::MohrCoulomb::updateStress
(
    const symmTensor& dStrain,
    symmTensor& stress,
    scalar& plasticStrain
) const
{
    update(dStrain, stress, plasticStrain);
}


void Foam::constitutiveModels::MohrCoulomb::updateStresses
(
    const label n,
    const symmTensor* dStrain,
    symmTensor* stress,
    scalar* plasticStrain
) const
{
    for (label i = 0; i < n; i += 4)
    {
        updatePacked
        (
            std::min(label(4), n - i),
            dStrain + i,
            stress + i,
            plasticStrain + i,
            nullptr
        );
    }
}


void Foam::constitutiveModels::MohrCoulomb::report(Ostream& os) const
{
    constitutiveModel::report(os);
    os  << "        Mohr-Coulomb: cohesion " << cohesion_
        << " Pa, friction angle " << radToDeg(phi_)
        << " deg, dilation angle " << radToDeg(psi_) << " deg, apex ";
    if (hasApex_)
    {
        os  << sigmaApex_ << " Pa";
    }
    else
    {
        os  << "none";
    }
    os  << ", tension cut-off ";
    if (tensionActive_)
    {
        os  << sigmaT_ << " Pa";
    }
    else
    {
        os  << "none";
    }
    os  << nl;
}


// ************************************************************************* //
