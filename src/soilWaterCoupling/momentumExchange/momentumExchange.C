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

#include "momentumExchange.H"
#include "FlatOutput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(momentumExchange, 0);
}

constexpr Foam::scalar Foam::momentumExchange::tolerance;
constexpr Foam::label Foam::momentumExchange::maxIter;

const Foam::Enum<Foam::momentumExchange::schemeType>
Foam::momentumExchange::schemeTypeNames
({
    { schemeType::implicit, "implicit" },
    { schemeType::exponential, "exponential" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::momentumExchange::momentumExchange(const dictionary& dict)
:
    drag_(dragModel::New(dict)),
    scheme_(readScheme(dict))
{}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::momentumExchange::schemeType Foam::momentumExchange::readScheme
(
    const dictionary& dict
)
{
    const word name
    (
        dict.getOrDefault<word>
        (
            "scheme",
            schemeTypeNames[schemeType::implicit]
        )
    );

    if (!schemeTypeNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "scheme " << name << " is not allowed: the drag exchange"
            << " scheme must be one of "
            << flatOutput(schemeTypeNames.names())
            << " (implicit: backward Euler; exponential: exact decay for"
            << " linear drag)" << exit(FatalIOError);
    }

    return schemeTypeNames.get(name);
}


Foam::scalar Foam::momentumExchange::solveLogDecay
(
    const dragModel& drag,
    const schemeType scheme,
    const scalar phi,
    const scalar kappa,
    const scalar slip0,
    label* nEval
)
{
    const bool implicit = (scheme == schemeType::implicit);

    label n = 0;

    // Fixed-point map: the log-decay that beta at the slip s0 e^-z gives,
    // log(1 + kappa beta) (backward Euler) or kappa beta (exponential)
    auto P = [&](const scalar z)
    {
        ++n;
        const scalar x = kappa*drag.beta(phi, slip0*std::exp(-z));
        return implicit ? std::log1p(x) : x;
    };

    // Residual R(z) = z - P(z): R(0) = -P(0) <= 0, R -> +inf as z -> inf.
    // For beta non-decreasing in the slip, P is non-increasing and
    // 1 <= R' <= 1 + d ln(beta)/d ln(slip): R is nearly linear in z
    const scalar z0 = P(0);     // explicit: beta at the predicted slip

    if (!(z0 > 0))
    {
        // No drag (kappa = 0, phi = 0)
        if (nEval) *nEval = n;
        return 0;
    }

    const scalar z1 = P(z0);
    scalar lo, hi, Rlo, Rhi;

    if (z1 <= z0)
    {
        // Usual case (beta non-decreasing in the slip): z* in [z1, z0]
        hi = z0;
        Rhi = z0 - z1;
        if (Rhi <= tolerance*z0)
        {
            if (nEval) *nEval = n;
            return z0;
        }
        lo = z1;
        Rlo = z1 - P(z1);
        if (Rlo > 0)
        {
            // beta not monotone: fall back on the bracket [0, z0]
            lo = 0;
            Rlo = -z0;
        }
    }
    else
    {
        // beta decreasing with the slip somewhere: R(z0) < 0
        lo = z0;
        Rlo = z0 - z1;
        hi = z1;
        Rhi = z1 - P(z1);
        while (Rhi < 0 && n < maxIter)
        {
            lo = hi;
            Rlo = Rhi;
            hi *= 2;
            Rhi = hi - P(hi);
        }
    }

    // Regula falsi with the Anderson-Bjorck weights in [lo, hi],
    // Rlo <= 0 <= Rhi
    int side = 0;
    scalar z = hi;
    while (n < maxIter)
    {
        if (Rhi <= 0)
        {
            z = hi;
            break;
        }
        if (Rlo >= 0)
        {
            z = lo;
            break;
        }
        if (hi - lo <= tolerance*hi)
        {
            z = 0.5*(lo + hi);
            break;
        }

        z = (lo*Rhi - hi*Rlo)/(Rhi - Rlo);
        z = (z < lo) ? lo : (z > hi ? hi : z);

        const scalar Rz = z - P(z);

        if (std::abs(Rz) <= tolerance*z)
        {
            break;
        }
        if (Rz > 0)
        {
            if (side == 1)
            {
                const scalar m = 1 - Rz/Rhi;
                Rlo *= (m > 0 ? m : 0.5);
            }
            hi = z;
            Rhi = Rz;
            side = 1;
        }
        else
        {
            if (side == -1)
            {
                const scalar m = 1 - Rz/Rlo;
                Rhi *= (m > 0 ? m : 0.5);
            }
            lo = z;
            Rlo = Rz;
            side = -1;
        }
    }

    if (nEval) *nEval = n;
    return z;
}


Foam::scalar Foam::momentumExchange::removedFraction
(
    const dragModel& drag,
    const schemeType scheme,
    const scalar phi,
    const scalar kappa,
    const scalar slip0
)
{
    if (!(kappa > 0))
    {
        return 0;
    }

    const scalar s0 = (slip0 > 0) ? slip0 : 0;

    scalar beta0, beta1;
    if (drag.affineInSlip(phi, beta0, beta1))
    {
        const scalar a = kappa*beta0;
        const scalar b = kappa*beta1*s0;
        return
            (scheme == schemeType::implicit)
          ? implicitFractionAffine(a, b)
          : exponentialFractionAffine(a, b);
    }

    if (s0 == 0)
    {
        // No slip to remove: the Stokes-limit fraction (J = 0 anyway)
        return fraction(scheme, kappa*drag.beta(phi, 0));
    }

    return -std::expm1(-solveLogDecay(drag, scheme, phi, kappa, s0));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::momentumExchange::report(Ostream& os) const
{
    os  << "    momentumExchange: scheme " << schemeTypeNames[scheme_]
        << nl;
    drag_->report(os);
}


// ************************************************************************* //
