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

#include "Shields.H"
#include "optionalEntry.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace erosionLaws
{
    defineTypeNameAndDebug(Shields, 0);
    addToRunTimeSelectionTable(erosionLaw, Shields, dictionary);
}
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalar Foam::erosionLaws::Shields::Dstar
(
    const scalar d,
    const scalar s,
    const scalar nu,
    const scalar g
)
{
    return d*std::cbrt(g*(s - 1)/(nu*nu));
}


Foam::scalar Foam::erosionLaws::Shields::criticalShieldsNumber
(
    const scalar Dstar
)
{
    // Soulsby & Whitehouse (1997) (Soulsby 1997, eq. 77): the minus sign
    // in the exponent makes the curve rise to 0.055 for coarse grains
    return 0.30/(1 + 1.2*Dstar) + 0.055*(1 - std::exp(-0.020*Dstar));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::erosionLaws::Shields::Shields(const dictionary& dict)
:
    excessShearStress(typeName, dict, false),
    d_(readCoeff("d", true, "[m] (the grain diameter)")),
    thetaC_(0),
    given_(foundEntry(coeffs_, "thetaC"))
{
    const scalar s = rhoSolid_/rhoFluid_;
    thetaC_ =
        given_
      ? readCoeff("thetaC", true, "(the critical Shields number)")
      : criticalShieldsNumber(Dstar(d_, s, nuFluid_, g_));
    tauC_ = thetaC_*(rhoSolid_ - rhoFluid_)*g_*d_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::erosionLaws::Shields::report(Ostream& os) const
{
    os  << "Erosion law Shields: m_dot = kEr (tau - tauC), kEr " << kEr_
        << " s/m, d " << d_ << " m, critical Shields number " << thetaC_;
    if (given_)
    {
        os  << " (given)";
    }
    else
    {
        os  << " (Soulsby & Whitehouse 1997, D* "
            << Dstar(d_, rhoSolid_/rhoFluid_, nuFluid_, g_) << " with nu "
            << nuFluid_ << " m2/s)";
    }
    os  << ": tauC = thetaC (rho_s - rho_w) g d = " << tauC_ << " Pa" << nl;
    if (!given_ && nuFluid_ > 1e-5)
    {
        // (a probe: a tutorial's viscous stand-in for water, nu 5e-3, put
        // 1 mm sand at D* 0.09 and tauC 8.8 times the real grains')
        os  << "    Note: D* takes the water's viscosity muFluid/rho of"
            << " constant/dragProperties (default: the lattice's nu of"
            << " constant/fluidProperties), " << nuFluid_ << " m2/s here"
            << " against water's 1e-6: where the lattice's viscosity is"
            << " raised for stability, set muFluid 1e-3 in"
            << " constant/dragProperties (the drag's permeability needs it"
            << " too) or give thetaC in ShieldsCoeffs" << nl;
    }
}


// ************************************************************************* //
