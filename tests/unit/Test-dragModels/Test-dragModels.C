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

Application
    Test-dragModels

Description
    Unit checks of the soil-water drag models and the node-local momentum
    exchange (phi = SOLID volume fraction, n = 1 - phi = porosity, beta per
    unit mixture volume):
    - BeetstraVanDerHoef: Fhat against the 30 tabulated values of
      coupling-formulas.md 2.1, the Stokes limit (Kozeny-Carman plus the
      (1 - phi)^2 (1 + 1.5 sqrt(phi)) term), the dilute limit Fhat -> 1;
    - KozenyCarman: the documented 1.93086e5 N s/m4 at phi = 0.63, d = 1 mm;
    - Ergun's Stokes limit, every model's permeability() against its
      closed-form Stokes limit, DiFelice and WenYu continuous at slip -> 0;
    - every model: beta >= 0 and finite for phi in [0, 0.99] (and clipped
      outside), slip in [0, 100]; beta = 0 at phi = 0; drag force
      beta slip non-decreasing in the slip;
    - momentum exchange, both schemes, constant C from 1 to 1e12 (and to
      infinity) and slip-dependent laws: momentum conserved, the slip keeps
      its direction and shrinks, consistency of the implicit solve, the
      exact exponential decay over many steps, slip -> 0 as C -> infinity;
    - the iterative solve with test laws whose beta decreases with or
      oscillates in the slip (fall-back brackets);
    - bad input raises FatalIOError naming the keyword.
    Prints PASS:/FAIL: lines; exits 1 on any failure.

\*---------------------------------------------------------------------------*/

#include "dragModel.H"
#include "BeetstraVanDerHoef.H"
#include "momentumExchange.H"
#include "IOstreams.H"
#include "IStringStream.H"
#include "unitTest.H"

#include <sstream>
#include <cmath>
#include <limits>

using namespace Foam;
using dragModels::BeetstraVanDerHoef;
typedef momentumExchange::schemeType schemeType;

using unitTest::check;

static std::string num(const scalar x)
{
    std::ostringstream os;
    os.precision(6);
    os << x;
    return os.str();
}

static dictionary makeDict(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

static std::string couplingText
(
    const word& model,
    const scalar d = 1e-3,
    const std::string& extra = ""
)
{
    return "dragModel " + model + "; d " + num(d)
        + "; rhoFluid 1000; muFluid 1e-3; " + extra;
}

static autoPtr<dragModel> makeModel(const word& model, const scalar d = 1e-3)
{
    return dragModel::New(makeDict(couplingText(model, d)));
}

static const wordList modelNames
({
    "BeetstraVanDerHoef", "KozenyCarman", "Ergun", "DiFelice", "WenYu"
});

static const scalar mu = 1e-3;
static const scalar rhoF = 1000;


// * * * * * * * * * * * * * * * Drag laws * * * * * * * * * * * * * * * * //

static void testFhatTable()
{
    const scalar phis[6] = {0.10, 0.30, 0.40, 0.55, 0.60, 0.63};
    const scalar Res[5] = {0, 1, 10, 100, 1000};
    const scalar table[6][5] =
    {
        {2.4288, 2.4982, 3.2181, 8.5537, 47.745},
        {7.0150, 7.0561, 8.2794, 19.688, 106.51},
        {11.813, 11.843, 13.464, 30.742, 163.15},
        {27.588, 27.609, 30.303, 66.398, 346.08},
        {37.846, 37.865, 41.195, 89.789, 468.46},
        {46.319, 46.338, 50.180, 109.36, 572.50}
    };

    scalar errMax = 0;
    for (label i = 0; i < 6; ++i)
    {
        for (label j = 0; j < 5; ++j)
        {
            const scalar F = BeetstraVanDerHoef::Fhat(phis[i], Res[j]);
            const scalar err = mag(F - table[i][j])/table[i][j];
            errMax = max(errMax, err);
            check
            (
                err <= 5e-5,
                "Fhat(" + num(phis[i]) + ", " + num(Res[j]) + ") = "
              + num(F) + " vs table " + num(table[i][j]),
                err, 5e-5
            );
        }
    }
    Info<< "    largest relative deviation from the table " << errMax << nl;
}


static void testBeetstraLimits()
{
    const scalar d = 1e-3;
    autoPtr<dragModel> B = makeModel("BeetstraVanDerHoef", d);
    autoPtr<dragModel> KC = makeModel("KozenyCarman", d);

    // Stokes limit: beta_B(phi, 0) minus the dilute term = Kozeny-Carman
    scalar err = 0;
    for (const scalar phi : {0.01, 0.1, 0.3, 0.5, 0.63, 0.8, 0.95})
    {
        const scalar n = 1 - phi;
        const scalar extra =
            18*phi*n*mu/(d*d)*n*n*(1 + 1.5*std::sqrt(phi));
        const scalar kc = 180*phi*phi*mu/(n*d*d);
        err = max(err, mag(B->beta(phi, 0) - extra - kc)/kc);
        err = max(err, mag(KC->beta(phi, 0) - kc)/kc);
    }
    check(err <= 1e-13, "Beetstra Stokes limit minus (1-phi)^2(1+1.5"
        "sqrt(phi)) term = 180 phi^2 mu/((1-phi) d^2) = KozenyCarman",
        err, 1e-13);

    // The documented number
    {
        const scalar beta = KC->beta(0.63, 0);
        const scalar e = mag(beta - 1.93086e5)/1.93086e5;
        check(e <= 5e-6, "KozenyCarman beta(0.63) = " + num(beta)
            + " N s/m4 vs 1.93086e5 (d = 1 mm, mu = 1e-3)", e, 5e-6);

        const scalar extra = B->beta(0.63, 0)/beta - 1;
        check(mag(extra - 0.0065) < 5e-4, "Beetstra Stokes limit exceeds "
            "KozenyCarman by " + num(100*extra) + " % at phi = 0.63 (0.65 %)",
            mag(extra - 0.0065), 5e-4);
    }

    // Dilute limit: Fhat -> 1 as phi -> 0 (as 1 + 1.5 sqrt(phi))
    {
        check(BeetstraVanDerHoef::Fhat(0, 0) == 1, "Fhat(0, 0) = 1 exactly",
            mag(BeetstraVanDerHoef::Fhat(0, 0) - 1), 0);
        // Fhat(phi, 0) - 1 = 1.5 sqrt(phi) + 8 phi + O(phi^1.5)
        scalar worst = 0;
        for (const scalar phi : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12})
        {
            const scalar e = mag(BeetstraVanDerHoef::Fhat(phi, 0) - 1);
            worst = max(worst, mag(e - 1.5*std::sqrt(phi) - 8*phi)/phi);
        }
        check(worst <= 0.1, "dilute limit Fhat(phi, 0) = 1 + 1.5 sqrt(phi) + "
            "8 phi + O(phi^1.5) -> 1 for phi = 1e-2 .. 1e-12 (largest "
            "|Fhat - 1 - 1.5 sqrt(phi) - 8 phi|/phi)", worst, 0.1);
        const scalar e = mag(BeetstraVanDerHoef::Fhat(1e-12, 0) - 1);
        check(e < 1e-5, "Fhat(1e-12, 0) -> 1", e, 1e-5);
    }

    // Re -> 0 of the inertial part is continuous
    {
        scalar e = 0;
        for (const scalar phi : {0.0, 0.1, 0.63, 0.99})
        {
            e = max
            (
                e,
                mag
                (
                    BeetstraVanDerHoef::Fhat(phi, 1e-12)
                  - BeetstraVanDerHoef::Fhat(phi, 0)
                )/BeetstraVanDerHoef::Fhat(phi, 0)
            );
        }
        check(e < 1e-7, "Fhat(phi, Re = 1e-12) -> Fhat(phi, 0)", e, 1e-7);
    }
}


// Closed-form Stokes-limit permeability of each law
static scalar kStokes(const word& model, const scalar phi, const scalar d)
{
    const scalar n = 1 - phi;
    if (model == "BeetstraVanDerHoef")
    {
        return n*d*d/(18*phi*BeetstraVanDerHoef::Fhat(phi, 0));
    }
    if (model == "KozenyCarman")
    {
        return d*d*n*n*n/(180*phi*phi);
    }
    if (model == "Ergun")
    {
        return d*d*n*n*n/(150*phi*phi);
    }
    if (model == "DiFelice")
    {
        return std::pow(n, 4.7)*d*d/(17.28*phi);
    }
    return std::pow(n, 4.65)*d*d/(18*phi);     // WenYu
}


static void testStokesLimits()
{
    const scalar d = 1e-3;

    // Ergun at slip 0
    {
        autoPtr<dragModel> E = makeModel("Ergun", d);
        scalar err = 0;
        for (const scalar phi : {0.01, 0.3, 0.63, 0.9})
        {
            const scalar ref = 150*phi*phi*mu/((1 - phi)*d*d);
            err = max(err, mag(E->beta(phi, 0) - ref)/ref);
        }
        check(err <= 1e-14, "Ergun beta(phi, 0) = 150 phi^2 mu/((1-phi) d^2)",
            err, 1e-14);
    }

    // permeability() = n^2 mu/beta(phi, 0) = the closed form
    for (const word& name : modelNames)
    {
        autoPtr<dragModel> m = makeModel(name, d);
        scalar err = 0;
        for (const scalar phi : {0.01, 0.3, 0.63, 0.9, 0.99})
        {
            const scalar k = kStokes(name, phi, d);
            err = max(err, mag(m->permeability(phi) - k)/k);
        }
        check(err <= 1e-13, name + " permeability() = its Stokes-limit "
            "closed form", err, 1e-13);
        check
        (
            m->permeability(0) == VGREAT,
            name + " permeability(0) infinite (VGREAT)", 0, 0
        );
    }
    {
        autoPtr<dragModel> m = makeModel("KozenyCarman", d);
        const scalar Kh = m->hydraulicConductivity(0.63, 9.81);
        const scalar ref = kStokes("KozenyCarman", 0.63, d)*rhoF*9.81/mu;
        check(mag(Kh - ref) <= 1e-14*ref, "KozenyCarman hydraulic "
            "conductivity " + num(Kh) + " m/s = k rho g/mu",
            mag(Kh - ref)/ref, 1e-14);
    }

    // Continuity at slip -> 0 of the laws with C_D ~ 1/Re
    for (const word name : {"DiFelice", "WenYu", "BeetstraVanDerHoef"})
    {
        autoPtr<dragModel> m = makeModel(name, d);
        scalar err = 0;
        bool finite = true;
        for (const scalar phi : {0.01, 0.3, 0.63, 0.99})
        {
            const scalar b0 = m->beta(phi, 0);
            const scalar b1 = m->beta(phi, 1e-12);
            finite = finite && std::isfinite(b0) && b0 > 0;
            err = max(err, mag(b1 - b0)/b0);
        }
        check(finite && err < 1e-5, name + " beta(phi, 0) finite and "
            "|beta(phi, 1e-12) - beta(phi, 0)|/beta(phi, 0) small",
            err, 1e-5);
    }

    // DiFelice and WenYu Stokes limits in closed form
    {
        autoPtr<dragModel> DF = makeModel("DiFelice", d);
        autoPtr<dragModel> WY = makeModel("WenYu", d);
        scalar e1 = 0, e2 = 0;
        for (const scalar phi : {0.01, 0.3, 0.63, 0.99})
        {
            const scalar n = 1 - phi;
            const scalar r1 = 17.28*phi*mu*std::pow(n, -2.7)/(d*d);
            const scalar r2 = 18*phi*mu*std::pow(n, -2.65)/(d*d);
            e1 = max(e1, mag(DF->beta(phi, 0) - r1)/r1);
            e2 = max(e2, mag(WY->beta(phi, 0) - r2)/r2);
        }
        check(e1 <= 1e-14, "DiFelice beta(phi, 0) = 17.28 phi mu n^-2.7/d^2 "
            "(limit of 0.75 C_D0 rho phi n^(2-chi) slip/d)", e1, 1e-14);
        check(e2 <= 1e-14, "WenYu beta(phi, 0) = 18 phi mu n^-2.65/d^2 "
            "(limit of 0.75 C_D phi n rho slip/d n^-2.65)", e2, 1e-14);

        // At a finite slip, the original (un-rearranged) formulas
        const scalar phi = 0.4, n = 0.6;
        scalar e3 = 0, e4 = 0;
        for (const scalar slip : {1e-4, 1e-2, 0.3, 5.0, 80.0})
        {
            const scalar Re = n*rhoF*d*slip/mu;
            const scalar CD0 = sqr(0.63 + 4.8/std::sqrt(Re));
            const scalar chi =
                3.7 - 0.65*std::exp(-sqr(1.5 - std::log10(Re))/2);
            const scalar r3 =
                0.75*CD0*rhoF*phi*std::pow(n, 2 - chi)*slip/d;
            e3 = max(e3, mag(DF->beta(phi, slip) - r3)/r3);

            const scalar CD =
                Re < 1000 ? 24/Re*(1 + 0.15*std::pow(Re, 0.687)) : 0.44;
            const scalar r4 =
                0.75*CD*phi*n*rhoF*slip/d*std::pow(n, -2.65);
            e4 = max(e4, mag(WY->beta(phi, slip) - r4)/r4);
        }
        check(e3 <= 1e-13, "DiFelice beta = 0.75 C_D0 rho phi n^(2-chi) "
            "slip/d at finite slip", e3, 1e-13);
        check(e4 <= 1e-13, "WenYu beta = 0.75 C_D phi n rho slip/d n^-2.65 "
            "at finite slip (both C_D branches)", e4, 1e-13);

        // Ergun and Beetstra at a finite slip
        autoPtr<dragModel> E = makeModel("Ergun", d);
        autoPtr<dragModel> B = makeModel("BeetstraVanDerHoef", d);
        scalar e5 = 0, e6 = 0;
        for (const scalar slip : {1e-4, 1e-2, 0.3, 5.0, 80.0})
        {
            const scalar r5 =
                150*phi*phi*mu/(n*d*d) + 1.75*phi*rhoF*slip/d;
            e5 = max(e5, mag(E->beta(phi, slip) - r5)/r5);
            const scalar Re = n*rhoF*d*slip/mu;
            const scalar r6 =
                18*phi*n*mu*BeetstraVanDerHoef::Fhat(phi, Re)/(d*d);
            e6 = max(e6, mag(B->beta(phi, slip) - r6)/r6);
        }
        check(e5 <= 1e-14, "Ergun beta = 150 phi^2 mu/(n d^2) + 1.75 phi "
            "rho slip/d", e5, 1e-14);
        check(e6 <= 1e-14, "Beetstra beta = 18 phi n mu Fhat(phi, Re)/d^2, "
            "Re = n rho d slip/mu", e6, 1e-14);
    }
}


static void testRanges()
{
    const scalar phis[] =
        {0, 1e-12, 1e-6, 0.01, 0.1, 0.3, 0.5, 0.63, 0.8, 0.9, 0.95, 0.99};
    const scalar slips[] =
        {0, 1e-14, 1e-12, 1e-9, 1e-6, 1e-3, 0.01, 0.1, 1, 3, 10, 31.6, 100};

    for (const word& name : modelNames)
    {
        for (const scalar d : {1e-6, 1e-3, 0.1})
        {
            autoPtr<dragModel> m = makeModel(name, d);
            bool ok = true;
            bool zero = true;
            bool clip = true;
            bool forceMonotone = true;
            scalar worstDrop = 0;
            for (const scalar phi : phis)
            {
                scalar forcePrev = 0;
                for (const scalar s : slips)
                {
                    const scalar b = m->beta(phi, s);
                    ok = ok && std::isfinite(b) && b >= 0;
                    if (phi == 0) zero = zero && (b == 0);
                    const scalar force = b*s;
                    if (force < forcePrev*(1 - 1e-14))
                    {
                        forceMonotone = false;
                        worstDrop =
                            max(worstDrop, (forcePrev - force)/forcePrev);
                    }
                    forcePrev = force;
                }
            }
            for (const scalar s : slips)
            {
                clip = clip
                    && m->beta(1.0, s) == m->beta(0.99, s)
                    && m->beta(1.5, s) == m->beta(0.99, s)
                    && m->beta(-0.2, s) == 0;
            }
            const std::string tag = name + " (d = " + num(d) + ")";
            check(ok, tag + ": beta >= 0 and finite for phi in [0, 0.99], "
                "slip in [0, 100]", 0, 0);
            check(zero, tag + ": beta = 0 at phi = 0", 0, 0);
            check(clip, tag + ": phi clipped into [0, 0.99]", 0, 0);
            check(forceMonotone, tag + ": drag force beta*slip "
                "non-decreasing in the slip", worstDrop, 0);
        }
    }
    // NaN solid fraction is clipped to 0
    {
        autoPtr<dragModel> m = makeModel("KozenyCarman");
        const scalar b = m->beta(std::numeric_limits<scalar>::quiet_NaN(), 1);
        check(b == 0, "phi = NaN clipped to 0 (beta 0)", b, 0);
    }
}


// * * * * * * * * * * * * * * * Exchange  * * * * * * * * * * * * * * * * //

struct exchangeErrors
{
    scalar momentum = 0;    // |dP|/(|m_s v_s| + |m_f v_f|)
    scalar growth = 0;      // max(|w|/|w*| - 1, 0)
    scalar reverse = 0;     // max(-w.w*/|w*|, 0)/(|v_s*| + |v_f*|)
    scalar parallel = 0;    // |w - (w.w^*) w^*|/(|v_s*| + |v_f*|)

    void add
    (
        const scalar ms, const scalar mf,
        const vector& vs0, const vector& vf0,
        const vector& vs, const vector& vf
    )
    {
        const vector P0(ms*vs0 + mf*vf0);
        const vector P(ms*vs + mf*vf);
        const scalar scale = ms*mag(vs0) + mf*mag(vf0);
        momentum = max(momentum, mag(P - P0)/scale);

        const vector w0(vs0 - vf0);
        const vector w(vs - vf);
        const vector e(w0/mag(w0));
        const scalar vScale = mag(vs0) + mag(vf0);
        growth = max(growth, mag(w)/mag(w0) - 1);
        reverse = max(reverse, -(w & e)/vScale);
        parallel = max(parallel, mag(w - (w & e)*e)/vScale);
    }

    void report(const std::string& tag) const
    {
        check(momentum <= 1e-14, tag + ": total momentum conserved",
            momentum, 1e-14);
        check(growth <= 1e-14, tag + ": |slip| does not grow", growth, 1e-14);
        check(reverse <= 1e-14, tag + ": slip keeps its sign (round-off "
            "of the velocities allowed)", reverse, 1e-14);
        check(parallel <= 1e-14, tag + ": slip keeps its direction",
            parallel, 1e-14);
    }
};


// Node of the seed: dx = 0.5 m, phi = 0.63, rho_s = 2650, rho_f = 1000
static const scalar Vnode = 0.125;
static const scalar phiNode = 0.63;
static const scalar msNode = 0.63*2650*0.125;
static const scalar mfNode = 0.37*1000*0.125;
static const scalar dtNode = 1e-3;
static const vector vsNode(1.0, -0.5, 0.25);
static const vector vfNode(-0.3, 0.7, 2.0);

static word schemeName(const schemeType s)
{
    return momentumExchange::schemeTypeNames[s];
}


static void testConstantC()
{
    const scalar mr = msNode*mfNode/(msNode + mfNode);

    for (const schemeType scheme :
        {schemeType::implicit, schemeType::exponential})
    {
        exchangeErrors errs;
        scalar prevRatio = 2;
        bool shrinking = true;
        scalar bwErr = 0;
        for (scalar C = 1; C <= 1.0001e12; C *= 10)
        {
            vector vs(vsNode), vf(vfNode);
            const vector J = momentumExchange::impulse
            (
                scheme, C, dtNode, msNode, mfNode, vs, vf
            );
            momentumExchange::apply(J, msNode, mfNode, vs, vf);
            errs.add(msNode, mfNode, vsNode, vfNode, vs, vf);

            // The formula of Baumgarten & Kamrin / the exponential
            const vector w0(vsNode - vfNode);
            const scalar lambdaDt = dtNode*C/mr;
            const vector Jref =
                (scheme == schemeType::implicit)
              ? dtNode*C/(1 + dtNode*C*(1/msNode + 1/mfNode))*w0
              : -mr*std::expm1(-lambdaDt)*w0;
            bwErr = max(bwErr, mag(J - Jref)/mag(Jref));

            const scalar ratio = mag(vs - vf)/mag(w0);
            shrinking = shrinking && (ratio <= prevRatio);
            prevRatio = ratio;
        }
        const std::string tag =
            schemeName(scheme) + ", constant C = 1 .. 1e12, dt = 1e-3, "
            "m_s = " + num(msNode) + ", m_f = " + num(mfNode);
        errs.report(tag);
        check(bwErr <= 1e-13, tag + ": impulse = "
            + word(scheme == schemeType::implicit
              ? "dt C/(1 + dt C (1/m_s + 1/m_f)) (v_s* - v_f*)"
              : "mr (1 - exp(-lambda dt)) (v_s* - v_f*)"),
            bwErr, 1e-13);
        check(shrinking, tag + ": remaining slip decreases with C", 0, 0);
    }

    // C -> infinity: the slip -> 0 (residual bounded by 1/(lambda dt) and
    // round-off), including C = inf
    for (const schemeType scheme :
        {schemeType::implicit, schemeType::exponential})
    {
        scalar worst = 0;
        bool ok = true;
        for
        (
            const scalar C
          : {1e12, 1e16, 1e20, 1e100, 1e300, std::numeric_limits<scalar>::infinity()}
        )
        {
            vector vs(vsNode), vf(vfNode);
            const vector J = momentumExchange::impulse
            (
                scheme, C, dtNode, msNode, mfNode, vs, vf
            );
            momentumExchange::apply(J, msNode, mfNode, vs, vf);
            const scalar r = mag(vs - vf)/mag(vsNode - vfNode);
            const scalar bound =
                (scheme == schemeType::implicit ? mr/(dtNode*C) : 0)
              + 1e-14*(mag(vsNode) + mag(vfNode))/mag(vsNode - vfNode);
            ok = ok && std::isfinite(r) && r <= bound;
            worst = max(worst, r);
        }
        check(ok, schemeName(scheme) + ": slip -> 0 as C -> infinity "
            "(C = 1e12 .. inf; largest remaining fraction)", worst, 0);
    }

    // One phase absent: nothing exchanged
    {
        const vector J1 = momentumExchange::impulse
        (
            schemeType::implicit, 1e6, dtNode, 0, mfNode, vsNode, vfNode
        );
        const vector J2 = momentumExchange::impulse
        (
            schemeType::exponential, 1e6, dtNode, msNode, 0, vsNode, vfNode
        );
        check(mag(J1) == 0 && mag(J2) == 0, "m_s = 0 or m_f = 0: no "
            "impulse", mag(J1) + mag(J2), 0);
    }

    // Many steps against the analytic decay (zero total momentum, so that
    // the velocities are of the size of the slip)
    {
        const scalar C = 0.01*mr/dtNode;    // lambda dt = 0.01
        const scalar lambdaDt = dtNode*C/mr;
        const label N = 1000;
        const vector w0(1.0, -2.0, 0.5);
        for (const schemeType scheme :
            {schemeType::implicit, schemeType::exponential})
        {
            vector vs(mfNode/(msNode + mfNode)*w0);
            vector vf(-msNode/(msNode + mfNode)*w0);
            for (label i = 0; i < N; ++i)
            {
                const vector J = momentumExchange::impulse
                (
                    scheme, C, dtNode, msNode, mfNode, vs, vf
                );
                momentumExchange::apply(J, msNode, mfNode, vs, vf);
            }
            const scalar ref =
                (scheme == schemeType::implicit)
              ? std::pow(1 + lambdaDt, -scalar(N))
              : std::exp(-lambdaDt*N);
            const vector w(vs - vf);
            const scalar err = mag(w - ref*w0)/(ref*mag(w0));
            check(err <= 1e-11, schemeName(scheme) + ": 1000 steps at "
                "lambda dt = 0.01 give " + word(scheme == schemeType::implicit
                ? "(1 + lambda dt)^-N" : "exp(-lambda t)") + " = "
                + num(ref), err, 1e-11);
        }
    }
}


static void testModelExchange()
{
    const scalar mr = msNode*mfNode/(msNode + mfNode);
    const scalar kappaPerV = dtNode/mr;

    // d spans C = beta V from ~1 to ~1e12 kg/s (Kozeny-Carman scale
    // 1.6e4/d^2 x V)
    const scalar ds[] = {0.1, 3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 1e-5,
        1e-6, 1e-7};
    const vector vfCases[] =
    {
        vfNode,                         // slip 2.48 m/s
        vsNode - vector(1e-6, 0, 0),    // slip 1e-6 m/s (Stokes)
        vfNode + vector(80, -30, 10)    // slip ~ 87 m/s (inertial)
    };

    for (const word& name : modelNames)
    {
        for (const schemeType scheme :
            {schemeType::implicit, schemeType::exponential})
        {
            exchangeErrors errs;
            scalar Cmin = GREAT, Cmax = 0;
            scalar residual = 0;
            label evalMax = 0;
            label evalSum = 0;
            label nSolve = 0;
            scalar worstSlip = 0;

            for (const scalar d : ds)
            {
                autoPtr<dragModel> m = makeModel(name, d);
                for (label k = 0; k < 3; ++k)
                {
                    const vector vf0(vfCases[k]);
                    vector vs(vsNode), vf(vf0);
                    const vector J = momentumExchange::impulse
                    (
                        m(), scheme, phiNode, Vnode, dtNode, msNode,
                        mfNode, vs, vf
                    );
                    momentumExchange::apply(J, msNode, mfNode, vs, vf);
                    errs.add(msNode, mfNode, vsNode, vf0, vs, vf);

                    const scalar s0 = mag(vsNode - vf0);
                    const scalar C = m->beta(phiNode, s0)*Vnode;
                    Cmin = min(Cmin, C);
                    Cmax = max(Cmax, C);

                    // Consistency: beta at the end-of-step slip
                    const scalar kappa = kappaPerV*Vnode;
                    scalar beta0, beta1;
                    if (m->affineInSlip(phiNode, beta0, beta1))
                    {
                        // Independent check of the closed forms: the
                        // remaining fraction r solves the implicit
                        // quadratic / the Riccati solution
                        const scalar a = kappa*beta0;
                        const scalar b = kappa*beta1*s0;
                        scalar r, rRef;
                        if (scheme == schemeType::implicit)
                        {
                            r = 2/(1 + a + std::sqrt(sqr(1 + a) + 4*b));
                            rRef = 1/(1 + a + b*r);
                        }
                        else
                        {
                            r = a*std::exp(-a)
                               /(a + b*(1 - std::exp(-a)));
                            rRef = r;
                            // compare with a fine explicit integration
                            // only for moderate a, b
                            if (a + b < 5)
                            {
                                scalar s = 1;
                                const label N = 200000;
                                // RK4 on ds/dt = -(a + b s) s over t = 1
                                for (label i = 0; i < N; ++i)
                                {
                                    const scalar h = 1.0/N;
                                    auto F = [&](scalar y)
                                    {
                                        return -(a + b*y)*y;
                                    };
                                    const scalar k1 = F(s);
                                    const scalar k2 = F(s + 0.5*h*k1);
                                    const scalar k3 = F(s + 0.5*h*k2);
                                    const scalar k4 = F(s + h*k3);
                                    s += h/6*(k1 + 2*k2 + 2*k3 + k4);
                                }
                                rRef = s;
                            }
                        }
                        const scalar f = momentumExchange::removedFraction
                        (
                            m(), scheme, phiNode, kappa, s0
                        );
                        if (r > 1e-300)
                        {
                            residual = max
                            (
                                residual,
                                max(mag(rRef - r)/r, mag((1 - f) - r)
                               /max(r, 1e-4))
                            );
                        }
                    }
                    else
                    {
                        // s = s0 e^-z with z = log(1 + kappa beta(s))
                        // (implicit) or kappa beta(s) (exponential)
                        label nEval = 0;
                        const scalar z = momentumExchange::solveLogDecay
                        (
                            m(), scheme, phiNode, kappa, s0, &nEval
                        );
                        const scalar x =
                            kappa*m->beta(phiNode, s0*std::exp(-z));
                        const scalar zRef =
                            (scheme == schemeType::implicit)
                          ? std::log1p(x) : x;
                        residual = max(residual, mag(z - zRef)/z);
                        evalMax = max(evalMax, nEval);
                        evalSum += nEval;
                        ++nSolve;
                    }

                    worstSlip = max(worstSlip, mag(vs - vf)/s0);
                }
            }

            const std::string tag =
                name + ", " + schemeName(scheme) + ", C = beta V = "
              + num(Cmin) + " .. " + num(Cmax) + " kg/s";
            errs.report(tag);
            check(residual <= 1e-10, tag + ": end-of-step beta consistent "
                + word(evalMax ? "(iterative, at most "
                + Foam::name(evalMax) + " beta evaluations, mean "
                + num(scalar(evalSum)/max(nSolve, 1)) + ")"
                : "(closed form vs quadratic/Riccati)"), residual, 1e-10);
        }
    }

    // Ergun: the closed form against the iterative solver
    {
        autoPtr<dragModel> m = makeModel("Ergun", 1e-3);
        scalar err = 0;
        for (const scalar kappa : {1e-9, 1e-6, 1e-3, 1e0, 1e3})
        {
            for (const scalar s0 : {1e-6, 1e-2, 1.0, 100.0})
            {
                const scalar f = momentumExchange::removedFraction
                (
                    m(), schemeType::implicit, 0.5, kappa, s0
                );
                const scalar z = momentumExchange::solveLogDecay
                (
                    m(), schemeType::implicit, 0.5, kappa, s0
                );
                // compare the remaining fractions 1 - f and e^-z
                // (and f, 1 - e^-z when f is small)
                const scalar r1 = std::exp(-z);
                const scalar f1 = -std::expm1(-z);
                err = max
                (
                    err,
                    min(mag((1 - f) - r1)/r1, mag(f - f1)/f1)
                );
            }
        }
        check(err <= 1e-10, "Ergun implicit: analytic quadratic root = "
            "iterative solve", err, 1e-10);
    }

    // Ergun exponential over many steps = the exact Riccati solution
    {
        autoPtr<dragModel> m = makeModel("Ergun", 1e-3);
        scalar beta0, beta1;
        m->affineInSlip(phiNode, beta0, beta1);
        const scalar Mv = Vnode/mr;                 // V (1/m_s + 1/m_f)
        const scalar alpha = Mv*beta0;
        const scalar gamma = Mv*beta1;
        const label N = 1000;
        const scalar dt = 1e-6;
        const vector w0(3.0, -1.0, 0.5);
        vector vs(mfNode/(msNode + mfNode)*w0);
        vector vf(-msNode/(msNode + mfNode)*w0);
        exchangeErrors errs;
        for (label i = 0; i < N; ++i)
        {
            const vector vs0(vs), vf0(vf);
            const vector J = momentumExchange::impulse
            (
                m(), schemeType::exponential, phiNode, Vnode, dt, msNode,
                mfNode, vs, vf
            );
            momentumExchange::apply(J, msNode, mfNode, vs, vf);
            errs.add(msNode, mfNode, vs0, vf0, vs, vf);
        }
        const scalar t = N*dt;
        const scalar s0 = mag(w0);
        const scalar E = std::exp(-alpha*t);
        const scalar sRef = alpha*s0*E/(alpha + gamma*s0*(1 - E));
        const scalar s = mag(vs - vf);
        const scalar err = mag(s - sRef)/sRef;
        check(err <= 1e-11, "Ergun exponential: 1000 steps follow the exact "
            "Riccati decay (alpha t = " + num(alpha*t) + ", gamma s0 t = "
            + num(gamma*s0*t) + ")", err, 1e-11);
        errs.report("Ergun exponential, 1000 steps");
    }

    // A momentumExchange object from the coupling dictionary
    {
        const dictionary dict(makeDict(couplingText
        (
            "BeetstraVanDerHoef", 1e-3, "scheme exponential;"
        )));
        momentumExchange ex(dict);
        vector vs(vsNode), vf(vfNode);
        const vector J = ex.exchange
        (
            phiNode, Vnode, dtNode, msNode, mfNode, vs, vf
        );
        const vector Jref = momentumExchange::impulse
        (
            ex.drag(), schemeType::exponential, phiNode, Vnode, dtNode,
            msNode, mfNode, vsNode, vfNode
        );
        const scalar dP =
            mag(msNode*vs + mfNode*vf - msNode*vsNode - mfNode*vfNode)
           /(msNode*mag(vsNode) + mfNode*mag(vfNode));
        const vector dv
        (
            (vf - vfNode) - Jref/mfNode + ((vs - vsNode) + Jref/msNode)
        );
        const scalar err =
            max(max(mag(J - Jref)/mag(Jref), dP), mag(dv)/mag(vsNode));
        check
        (
            ex.scheme() == schemeType::exponential && err <= 1e-14,
            "momentumExchange(dict): scheme exponential read, exchange() "
            "applies +J to the fluid and -J to the solid", err, 1e-14
        );
        ex.report(Info);

        const dictionary dict2(makeDict(couplingText("Ergun")));
        momentumExchange ex2(dict2);
        check(ex2.scheme() == schemeType::implicit, "scheme defaults to "
            "implicit", 0, 0);
    }
}


// Test-only laws whose beta decreases with the slip (1 + A e^-s/sRef) or
// oscillates (1 + A sin^2(s/sRef)): the fall-back brackets of the solver
class testDrag
:
    public dragModel
{
    const scalar b0_;
    const scalar A_;
    const scalar sRef_;
    const bool oscillating_;

public:

    testDrag
    (
        const dictionary& dict,
        const scalar b0,
        const scalar A,
        const scalar sRef,
        const bool oscillating
    )
    :
        dragModel("testDrag", dict),
        b0_(b0),
        A_(A),
        sRef_(sRef),
        oscillating_(oscillating)
    {}

    virtual scalar beta(const scalar phi, const scalar slip) const
    {
        const scalar g =
            oscillating_
          ? sqr(std::sin(slip/sRef_))
          : std::exp(-slip/sRef_);
        return b0_*clipPhi(phi)*(1 + A_*g);
    }

    virtual bool linear() const
    {
        return false;
    }
};


static void testNonMonotone()
{
    const dictionary dict(makeDict(couplingText("KozenyCarman")));
    const scalar mr = msNode*mfNode/(msNode + mfNode);

    for (const bool osc : {false, true})
    {
        for (const scalar A : {3.0, 50.0})
        {
            const testDrag m(dict, 1e4, A, 0.3, osc);
            for (const schemeType scheme :
                {schemeType::implicit, schemeType::exponential})
            {
                exchangeErrors errs;
                scalar residual = 0;
                label evalMax = 0;
                for (const scalar V : {1e-6, 1e-4, 1e-2, 0.125, 10.0, 1e3})
                {
                    for (const scalar s0 : {0.01, 0.2, 0.7, 2.48, 20.0})
                    {
                        const vector vf0(vsNode - s0*vector(0.6, 0.8, 0));
                        vector vs(vsNode), vf(vf0);
                        const vector J = momentumExchange::impulse
                        (
                            m, scheme, phiNode, V, dtNode, msNode, mfNode,
                            vs, vf
                        );
                        momentumExchange::apply(J, msNode, mfNode, vs, vf);
                        errs.add(msNode, mfNode, vsNode, vf0, vs, vf);

                        const scalar kappa = dtNode*V/mr;
                        label nEval = 0;
                        const scalar z = momentumExchange::solveLogDecay
                        (
                            m, scheme, phiNode, kappa, s0, &nEval
                        );
                        const scalar x =
                            kappa*m.beta(phiNode, s0*std::exp(-z));
                        const scalar zRef =
                            (scheme == schemeType::implicit)
                          ? std::log1p(x) : x;
                        residual = max(residual, mag(z - zRef)/z);
                        evalMax = max(evalMax, nEval);
                    }
                }
                const std::string tag =
                    "test law beta = b0 phi (1 + " + num(A)
                  + (osc ? " sin^2(s/0.3))" : " exp(-s/0.3))") + ", "
                  + schemeName(scheme);
                errs.report(tag);
                check(residual <= 1e-10, tag + ": a consistent root found "
                    "(fall-back brackets, at most " + Foam::name(evalMax)
                  + " evaluations)", residual, 1e-10);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Bad input  * * * * * * * * * * * * * * * //

static void expectFatal
(
    const std::string& text,
    const std::string& keyword,
    const std::string& what
)
{
    unitTest::expectFatal
    (
        [&]()
        {
            const dictionary dict(makeDict(text));
            momentumExchange ex(dict);
        },
        keyword,
        what
    );
}

static void testBadInput()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    expectFatal
    (
        "dragModel Stokes; d 1e-3; rhoFluid 1000; muFluid 1e-3;",
        "Unknown dragModel type Stokes", "unknown dragModel"
    );
    expectFatal
    (
        "dragModel Ergun; d 0; rhoFluid 1000; muFluid 1e-3;",
        "d 0 is not allowed", "d = 0"
    );
    expectFatal
    (
        "dragModel WenYu; d -1e-3; rhoFluid 1000; muFluid 1e-3;",
        "d -0.001 is not allowed", "d < 0"
    );
    expectFatal
    (
        "dragModel BeetstraVanDerHoef; d 1e-3; rhoFluid 1000; muFluid -1e-3;",
        "muFluid -0.001 is not allowed", "muFluid < 0"
    );
    expectFatal
    (
        "dragModel DiFelice; d 1e-3; rhoFluid 0; muFluid 1e-3;",
        "rhoFluid 0 is not allowed", "rhoFluid = 0"
    );
    expectFatal
    (
        "dragModel KozenyCarman; rhoFluid 1000; muFluid 1e-3;",
        "'d'", "missing d"
    );
    expectFatal
    (
        "d 1e-3; rhoFluid 1000; muFluid 1e-3;",
        "'dragModel'", "missing dragModel"
    );
    expectFatal
    (
        couplingText("KozenyCarman", 1e-3, "KozenyCarmanCoeffs { C -1; }"),
        "C -1 is not allowed", "KozenyCarman C < 0"
    );
    expectFatal
    (
        couplingText("Ergun", 1e-3, "ErgunCoeffs { B 0; }"),
        "B 0 is not allowed", "Ergun B = 0"
    );
    expectFatal
    (
        couplingText("Ergun", 1e-3, "scheme explicit;"),
        "scheme explicit is not allowed", "unknown scheme"
    );

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();

    // Coefficients are read
    const dictionary dict(makeDict(couplingText
    (
        "KozenyCarman", 1e-3, "KozenyCarmanCoeffs { C 150; }"
    )));
    autoPtr<dragModel> kc = dragModel::New(dict);
    autoPtr<dragModel> er = makeModel("Ergun");
    check(kc->beta(0.5, 0) == er->beta(0.5, 0), "KozenyCarmanCoeffs C 150 "
        "gives Ergun's Stokes limit", mag(kc->beta(0.5, 0) - er->beta(0.5, 0)),
        0);
}


// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    testFhatTable();
    testBeetstraLimits();
    testStokesLimits();
    testRanges();
    testConstantC();
    testModelExchange();
    testNonMonotone();
    testBadInput();

    for (const word& name : modelNames)
    {
        makeModel(name)->report(Info);
    }

    return unitTest::finish();
}


// ************************************************************************* //
