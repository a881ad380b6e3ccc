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
    - the exchange the drag and porousFlow effects use (dragRelaxation),
      one-way and two-way, a = beta dt/m_f from 1e-12 to 1e12 and
      infinity, and every model's beta over its range: momentum conserved
      (two-way), the slip keeps its direction and shrinks, by exactly
      exp(-a) (one-way) or exp(-a (1 + m_f/m_s)) (two-way) per step, also
      over 1000 steps; s = kappa/a, kappa and s in [0, 1], no drag at
      a = 0;
    - bad input raises FatalIOError naming the keyword.
    Prints PASS:/FAIL: lines; exits 1 on any failure.

\*---------------------------------------------------------------------------*/

#include "dragModel.H"
#include "BeetstraVanDerHoef.H"
#include "dragRelaxation.H"
#include "vector.H"
#include "IOstreams.H"
#include "IStringStream.H"
#include "unitTest.H"

#include <sstream>
#include <cmath>
#include <limits>

using namespace Foam;
using dragModels::BeetstraVanDerHoef;

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


// Node of the seed: phi = 0.63, rho_s = 2650, rho_f = 1000 (masses per
// volume, as the drag effect gives them)
static const scalar phiNode = 0.63;
static const scalar msNode = 0.63*2650;
static const scalar mfNode = 0.37*1000;
static const scalar dtNode = 1e-3;
static const vector vsNode(1.0, -0.5, 0.25);
static const vector vfNode(-0.3, 0.7, 2.0);


// One step of a node as the lattice takes the relaxation (lbmKernel.H, no
// other force): the water moves by kappa (v_s - v_f); the soil is not acted
// on (oneWay)
static void relax
(
    const dragRelaxation& r,
    const scalar mf,
    vector& vs,
    vector& vf
)
{
    const vector J = (mf*r.kappa())*(vs - vf);
    vf += J/mf;
}


// twoWay: the exact two-body exchange over dt (as the soil's sub-steps
// take it, physicsEffects::drag) with drag C = a m_f/dt, a = beta dt/m_f,
// and no other force: the water receives J, the soil the opposite
static void exchangeTwoWay
(
    const scalar a,
    const scalar ms,
    const scalar mf,
    const scalar dt,
    vector& vs,
    vector& vf,
    const vector& da = Zero
)
{
    const vector J =
        dragRelaxation::twoBodyImpulse(a*mf/dt, ms, mf, vf - vs, da, dt);
    vf += J/mf;
    vs -= J/ms;
}


static void testRelaxation()
{
    for (const bool twoWay : {false, true})
    {
        const std::string way(twoWay ? "twoWay" : "oneWay");
        // The exact decay of the slip per unit a
        const scalar rate = twoWay ? 1 + mfNode/msNode : 1;

        // a = beta dt/m_f from 1e-12 to 1e12 and infinity: momentum, the
        // slip's direction, the exact exponential decay, kappa and s
        exchangeErrors errs;
        scalar decayErr = 0, sErr = 0;
        bool bounded = true;
        for (scalar a = 1e-12; a <= 1.0001e12; a *= 10)
        {
            for (const scalar A : {a, std::numeric_limits<scalar>::infinity()})
            {
                vector vs(vsNode), vf(vfNode);
                if (twoWay)
                {
                    exchangeTwoWay(A, msNode, mfNode, dtNode, vs, vf);
                    errs.add(msNode, mfNode, vsNode, vfNode, vs, vf);
                }
                else
                {
                    const dragRelaxation r = dragRelaxation::oneWay(A);
                    relax(r, mfNode, vs, vf);
                    if (A > SMALL && std::isfinite(A))
                    {
                        sErr = max(sErr, mag(r.s()*A - r.kappa())/r.kappa());
                    }
                    // (to round-off)
                    bounded = bounded && r.kappa() >= 0 && r.kappa() <= 1
                        && r.s() >= 0 && r.s() <= 1 + 1e-15
                        && r.kappa() <= A*(1 + 1e-15);
                }
                const vector w0(vsNode - vfNode);
                const scalar vScale = mag(vsNode) + mag(vfNode);
                decayErr = max
                (
                    decayErr,
                    mag((vs - vf) - std::exp(-A*rate)*w0)/vScale
                );
            }
        }
        const std::string tag =
            way + ", a = beta dt/m_f = 1e-12 .. 1e12 and inf, m_s = "
          + num(msNode) + ", m_f = " + num(mfNode) + " kg/m3";
        check(decayErr <= 1e-14, tag + ": the slip decays by exactly exp(-a"
            + word(twoWay ? " (1 + m_f/m_s)" : "") + ") in one step",
            decayErr, 1e-14);
        if (twoWay)
        {
            errs.report(tag);

            // a -> 0: no drag
            vector vs(vsNode), vf(vfNode);
            exchangeTwoWay(0, msNode, mfNode, dtNode, vs, vf);
            check(vs == vsNode && vf == vfNode, way + ": a = 0 exchanges"
                " nothing (no drag)", mag(vs - vsNode) + mag(vf - vfNode), 0);
        }
        else
        {
            check(sErr <= 1e-15, tag + ": s = kappa/a", sErr, 1e-15);
            check(bounded, tag + ": 0 <= kappa <= min(a, 1), 0 <= s <= 1",
                0, 0);

            // a -> 0: no drag
            const dragRelaxation r0 = dragRelaxation::oneWay(0);
            check(r0.kappa() == 0 && r0.s() == 1, way + ": a = 0 gives"
                " kappa 0, s 1 (no drag)", r0.kappa(), 0);
        }

        // Many steps against the analytic decay (zero total momentum, so
        // that the velocities are of the size of the slip)
        const scalar a = 0.01/rate;
        const label N = 1000;
        const vector w0(1.0, -2.0, 0.5);
        vector vs(mfNode/(msNode + mfNode)*w0);
        vector vf(-msNode/(msNode + mfNode)*w0);
        const vector vs0(vs);
        const dragRelaxation r = dragRelaxation::oneWay(a);
        for (label i = 0; i < N; ++i)
        {
            if (twoWay)
            {
                exchangeTwoWay(a, msNode, mfNode, dtNode, vs, vf);
            }
            else
            {
                relax(r, mfNode, vs, vf);
            }
        }
        const scalar ref = std::exp(-0.01*N);
        const scalar err = mag((vs - vf) - ref*w0)/(ref*mag(w0));
        check(err <= 1e-11, way + ": 1000 steps at a rate of 0.01 per step"
            " give exp(-10) = " + num(ref), err, 1e-11);
        if (!twoWay)
        {
            check(vs == vs0, "oneWay: the soil is not acted on", 0, 0);
        }
    }
}


// The two-body exchange with the other forces of the sub-step
// (dragRelaxation::twoBodyImpulse): steps compose, steady states are exact,
// a stiff drag moves the two as one mass, and a soil node on a spring
// sub-stepped with it decays as the exact solution (the exchange held over
// an outer step instead feeds the spring's mode)
static void testTwoBodyExchange()
{
    const vector w0(vsNode - vfNode);
    const scalar vScale = mag(vsNode) + mag(vfNode);

    // N sub-steps of dt/N compose to one of dt (no other forces), for a
    // from 1e-6 to 1e6
    {
        scalar err = 0;
        for (scalar a = 1e-6; a <= 1.0001e6; a *= 10)
        {
            vector vs1(vsNode), vf1(vfNode), vsN(vsNode), vfN(vfNode);
            exchangeTwoWay(a, msNode, mfNode, dtNode, vs1, vf1);
            const label N = 37;
            for (label i = 0; i < N; ++i)
            {
                // (a per sub-step: a/N)
                exchangeTwoWay(a/N, msNode, mfNode, dtNode/N, vsN, vfN);
            }
            err = max(err, (mag(vsN - vs1) + mag(vfN - vf1))/vScale);
        }
        check(err <= 1e-13, "twoBodyImpulse: 37 sub-steps compose to one"
            " step, a = 1e-6 .. 1e6", err, 1e-13);
    }

    // Other forces: momentum takes exactly the impulse of the forces, and
    // the relative velocity is the exact solution of
    // dw/dt = da - lambda w (for a from 1e-8 to 1e8)
    {
        const vector Fs(3.0, -1.0, 0.5), Ff(-2.0, 4.0, 1.0);
        scalar momErr = 0, wErr = 0;
        for (scalar a = 1e-8; a <= 1.0001e8; a *= 10)
        {
            vector vs(vsNode), vf(vfNode);
            const vector da(Ff/mfNode - Fs/msNode);
            const vector J = dragRelaxation::twoBodyImpulse
            (
                a*mfNode/dtNode, msNode, mfNode, vf - vs, da, dtNode
            );
            vs += (dtNode*Fs - J)/msNode;
            vf += (dtNode*Ff + J)/mfNode;
            const vector P0(msNode*vsNode + mfNode*vfNode + dtNode*(Fs + Ff));
            momErr = max
            (
                momErr,
                mag(msNode*vs + mfNode*vf - P0)
               /(msNode*mag(vsNode) + mfNode*mag(vfNode))
            );
            const scalar lambda = a*(1 + mfNode/msNode)/dtNode;
            const vector wInf(da/lambda);
            const vector wRef = wInf + (-w0 - wInf)*std::exp(-lambda*dtNode);
            wErr = max
            (
                wErr,
                mag((vf - vs) - wRef)/(vScale + mag(da)*dtNode)
            );
        }
        check(momErr <= 1e-14, "twoBodyImpulse with other forces: momentum"
            " changes by their impulse exactly", momErr, 1e-14);
        check(wErr <= 1e-12, "twoBodyImpulse with other forces: the slip is"
            " the exact solution, a = 1e-8 .. 1e8", wErr, 1e-12);
    }

    // Darcy: the water at the slip where the drag balances its force, the
    // soil held by an equal and opposite force: nothing changes, the drag
    // takes exactly -dt F_f, for any a
    {
        scalar err = 0;
        const vector Ff(0, -5.0, 2.0);
        for (scalar a = 1e-6; a <= 1.0001e9; a *= 10)
        {
            const scalar C = a*mfNode/dtNode;
            const vector vs(Zero);
            const vector vf(Ff/C);
            const vector da(Ff/mfNode + Ff/msNode);
            const vector J = dragRelaxation::twoBodyImpulse
            (
                C, msNode, mfNode, vf - vs, da, dtNode
            );
            err = max(err, mag(J + dtNode*Ff)/(dtNode*mag(Ff)));
        }
        check(err <= 1e-12, "twoBodyImpulse: a steady seepage (Darcy) is"
            " kept exactly, a = 1e-6 .. 1e9", err, 1e-12);
    }

    // A soil node on a spring (omega) with its pore water, stiff drag
    // (a = 40, d = 0.1 mm in a soft soil), 59 sub-steps per step of 1 ms:
    // at omega dt = 4.34 (sin < 0) the exchange held over the step grows
    // the mode; sub-stepped it decays as the exact coupled solution
    {
        const scalar ms = 1590, mf = 400, dt = 1e-3, a = 40;
        const scalar C = a*mf/dt, omega = 4340, k = ms*omega*omega;
        const label N = 59;
        const scalar h = dt/N;
        auto run = [&](const bool subStepped)
        {
            scalar x = 1e-6, vs = 0, vf = 0;
            for (label step = 0; step < 200; ++step)
            {
                scalar Jstep = 0;
                if (!subStepped)
                {
                    Jstep = dragRelaxation::twoBodyImpulse
                    (
                        C, ms, mf, vector(vf - vs, 0, 0), Zero, dt
                    ).x();
                    vf += Jstep/mf;
                }
                for (label i = 0; i < N; ++i)
                {
                    scalar F = -k*x;
                    if (subStepped)
                    {
                        const scalar J = dragRelaxation::twoBodyImpulse
                        (
                            C, ms, mf, vector(vf - vs, 0, 0),
                            vector(-F/ms, 0, 0), h
                        ).x();
                        F -= J/h;
                        vf += J/mf;
                    }
                    else
                    {
                        F -= Jstep/dt;
                    }
                    vs += h*F/ms;
                    x += h*vs;
                }
            }
            // energy of the mode over its start
            return
                (0.5*k*x*x + 0.5*ms*vs*vs + 0.5*mf*vf*vf)
               /(0.5*k*1e-12);
        };
        const scalar held = run(false);
        const scalar subStepped = run(true);
        check(held > 1, "spring and stiff drag, omega dt = 4.34: the"
            " exchange held over the step feeds the mode (energy x"
            + num(held) + " in 200 steps)", held, 1);
        check(subStepped < 1e-3, "spring and stiff drag, omega dt = 4.34:"
            " exchanged in the sub-steps the mode decays (energy x"
            + num(subStepped) + " in 200 steps)", subStepped, 1e-3);
    }
}


static void testModelRelaxation()
{
    // d spans beta dt/m_f from ~1e-5 to ~1e10 (Kozeny-Carman scale
    // 1.6e4/d^2)
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
        exchangeErrors errs;
        scalar aMin = GREAT, aMax = 0;
        for (const scalar d : ds)
        {
            autoPtr<dragModel> m = makeModel(name, d);
            for (const vector& vf0 : vfCases)
            {
                // As the drag effect: beta at the slip carried into the
                // step
                const scalar a =
                    m->beta(phiNode, mag(vsNode - vf0))*dtNode/mfNode;
                aMin = min(aMin, a);
                aMax = max(aMax, a);
                vector vs(vsNode), vf(vf0);
                exchangeTwoWay(a, msNode, mfNode, dtNode, vs, vf);
                errs.add(msNode, mfNode, vsNode, vf0, vs, vf);
            }
        }
        errs.report
        (
            name + ", twoWay, a = beta dt/m_f = " + num(aMin) + " .. "
          + num(aMax)
        );
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
            dragModel::New(dict);
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
    testRelaxation();
    testTwoBodyExchange();
    testModelRelaxation();
    testBadInput();

    for (const word& name : modelNames)
    {
        makeModel(name)->report(Info);
    }

    return unitTest::finish();
}


// ************************************************************************* //
