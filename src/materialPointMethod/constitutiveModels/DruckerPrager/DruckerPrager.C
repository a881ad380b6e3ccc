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

#include "DruckerPrager.H"
#include "selectEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "unitConversion.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace constitutiveModels
{
    defineTypeNameAndDebug(DruckerPrager, 0);
    addToRunTimeSelectionTable(constitutiveModel, DruckerPrager, dictionary);
}
}


const Foam::Enum
<
    Foam::constitutiveModels::DruckerPrager::fitType
>
Foam::constitutiveModels::DruckerPrager::fitTypeNames
({
    { fitType::outerCone, "outerCone" },
    { fitType::innerCone, "innerCone" },
    { fitType::planeStrain, "planeStrain" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::constitutiveModels::DruckerPrager::DruckerPrager
(
    const word& name,
    const dictionary& dict
)
:
    constitutiveModel(typeName, name, dict),
    cohesion_(0),
    phi_(0),
    psi_(0),
    fit_
    (
        selectEntry(fitTypeNames, "fit", coeffs_, true, fitType::planeStrain)
    ),
    eta_(0),
    etaBar_(0),
    xi_(0),
    pApex_(GREAT)
{
    readFrictionalStrength(cohesion_, phi_, psi_);

    const scalar sinPhi = sin(phi_);
    const scalar cosPhi = cos(phi_);
    const scalar sinPsi = sin(psi_);

    // de Souza Neto, Peric & Owen (2008), section 6.4.4
    switch (fit_)
    {
        case fitType::outerCone:
        {
            eta_ = 6*sinPhi/(sqrt(3.0)*(3 - sinPhi));
            xi_ = 6*cosPhi/(sqrt(3.0)*(3 - sinPhi));
            etaBar_ = 6*sinPsi/(sqrt(3.0)*(3 - sinPsi));
            break;
        }
        case fitType::innerCone:
        {
            eta_ = 6*sinPhi/(sqrt(3.0)*(3 + sinPhi));
            xi_ = 6*cosPhi/(sqrt(3.0)*(3 + sinPhi));
            etaBar_ = 6*sinPsi/(sqrt(3.0)*(3 + sinPsi));
            break;
        }
        case fitType::planeStrain:
        {
            // Plane-strain plastic flow, e^p_zz = 0, puts
            // s_zz = -2 etaBar sqrt(J2)/3, hence in the plane
            // sqrt(J2) = ((s1 - s3)/2)/w and p = (s1 + s3)/2 - etaBar
            // sqrt(J2)/3; equate f = 0 with the Mohr-Coulomb plane-strain
            // failure and the dilatancy ratio with sin(psi)
            etaBar_ = 3*sinPsi/sqrt(9 + 3*sqr(sinPsi));
            const scalar w = sqrt(1 - sqr(etaBar_)/3);
            eta_ = sinPhi/(w + etaBar_*sinPhi/3);
            xi_ = cosPhi*(1 - eta_*etaBar_/3)/w;
            break;
        }
    }

    pApex_ = (eta_ > 0) ? xi_*cohesion_/eta_ : GREAT;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::constitutiveModels::DruckerPrager::yieldFunction
(
    const symmTensor& sigma
) const
{
    const symmTensor s(dev(sigma));
    return sqrt(0.5*(s && s)) + eta_*tr(sigma)/3 - xi_*cohesion_;
}


Foam::constitutiveModels::DruckerPrager::returnRegion
Foam::constitutiveModels::DruckerPrager::update
(
    const symmTensor& dStrain,
    symmTensor& stress,
    scalar& plasticStrain
) const
{
    const symmTensor trial(stress + elasticIncrement(dStrain));

    const scalar pTrial = tr(trial)/3;
    const symmTensor sTrial(dev(trial));
    const scalar qTrial = sqrt(0.5*(sTrial && sTrial));  // sqrt(J2)

    const scalar f = qTrial + eta_*pTrial - xi_*cohesion_;

    if (f <= 0)
    {
        stress = trial;
        return elastic;
    }

    // de Souza Neto et al. (2008), section 8.3.3, perfect plasticity
    const scalar dGamma = f/(G_ + K_*eta_*etaBar_);

    returnRegion region = cone;

    if (qTrial - G_*dGamma >= 0 || !(eta_ > 0))
    {
        // Smooth cone; eta = 0 (von Mises) has no apex
        const scalar factor =
            (qTrial > 0) ? max(1 - G_*dGamma/qTrial, scalar(0)) : scalar(0);
        const scalar p = pTrial - K_*etaBar_*dGamma;
        stress = factor*sTrial + p*I;
    }
    else
    {
        region = apex;
        stress = symmTensor(pApex_, 0, 0, pApex_, 0, pApex_);
    }

    // Equivalent deviatoric plastic strain: dev(trial - stress)/(2G)
    const symmTensor devDS(dev(trial - stress));
    plasticStrain += sqrt(2.0/3.0)*sqrt(devDS && devDS)/(2*G_);

    return region;
}


void Foam::constitutiveModels::DruckerPrager::updateStress
(
    const symmTensor& dStrain,
    symmTensor& stress,
    scalar& plasticStrain
) const
{
    update(dStrain, stress, plasticStrain);
}


void Foam::constitutiveModels::DruckerPrager::report(Ostream& os) const
{
    constitutiveModel::report(os);
    os  << "        Drucker-Prager (" << fitTypeNames[fit_]
        << " fit): cohesion " << cohesion_
        << " Pa, friction angle " << radToDeg(phi_)
        << " deg, dilation angle " << radToDeg(psi_)
        << " deg; eta " << eta_ << ", etaBar " << etaBar_ << ", xi " << xi_
        << ", apex ";
    if (eta_ > 0)
    {
        os  << pApex_ << " Pa";
    }
    else
    {
        os  << "none";
    }
    os  << nl;
}


// ************************************************************************* //
