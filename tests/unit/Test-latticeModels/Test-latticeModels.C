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
    Test-latticeModels

Description
    Unit checks of the lattice Boltzmann building blocks, for D2Q9, D3Q19
    and D3Q27:
    - velocity-set moments up to fourth order (isotropy) and opposites;
    - equilibrium moments: rho, rho u, rho cs2 I + rho u u;
    - Guo forcing moments: 0, F, u F + F u;
    - every collision model (BGK, TRT, MRT, regularized, run-time
      selected) through the real kernel on a one-node lattice: mass
      conserved, momentum gains exactly F, equilibrium is a fixed point,
      the second moment relaxes as in BGK;
    - the MRT basis is orthonormal under the weights.
    Prints PASS:/FAIL: lines; exits 1 on any failure.

\*---------------------------------------------------------------------------*/

#include "velocitySet.H"
#include "collisionModel.H"
#include "MRT.H"
#include "lbmKernel.H"
#include "IOstreams.H"
#include "Random.H"
#include "symmTensor.H"
#include "vector.H"
#include "tensor.H"
#include "unitTest.H"

using namespace Foam;

using namespace Foam::unitTest;


// Moments of a population set
struct moments
{
    scalar rho = 0;
    vector j = Zero;
    symmTensor P = Zero;
};

static moments computeMoments(const velocitySet& vs, const scalarList& f)
{
    moments m;
    for (label q = 0; q < vs.Q(); ++q)
    {
        const vector c(vs.c()[q]);
        m.rho += f[q];
        m.j += f[q]*c;
        m.P += f[q]*sqr(c);
    }
    return m;
}


static scalarList equilibrium
(
    const velocitySet& vs,
    const scalar rho,
    const vector& u
)
{
    scalarList f(vs.Q());
    for (label q = 0; q < vs.Q(); ++q)
    {
        const scalar cu = vector(vs.c()[q]) & u;
        f[q] = vs.w()[q]*rho*(1 + 3*cu + 4.5*cu*cu - 1.5*magSqr(u));
    }
    return f;
}


static void testVelocitySet(const velocitySet& vs)
{
    const word n = vs.type();
    const label Q = vs.Q();
    const scalar cs2 = 1.0/3.0;

    scalar e0 = -1, e1 = 0, e2 = 0, e3 = 0, e4 = 0, eOpp = 0;
    for (label q = 0; q < Q; ++q) e0 += vs.w()[q];

    const label D = vs.D();
    for (label a = 0; a < D; ++a)
    {
        scalar s1 = 0;
        for (label q = 0; q < Q; ++q) s1 += vs.w()[q]*vs.c()[q][a];
        e1 = max(e1, mag(s1));
        for (label b = 0; b < D; ++b)
        {
            scalar s2 = 0;
            for (label q = 0; q < Q; ++q)
            {
                s2 += vs.w()[q]*vs.c()[q][a]*vs.c()[q][b];
            }
            e2 = max(e2, mag(s2 - (a == b ? cs2 : 0)));
            for (label c = 0; c < D; ++c)
            {
                scalar s3 = 0;
                for (label q = 0; q < Q; ++q)
                {
                    s3 += vs.w()[q]*vs.c()[q][a]*vs.c()[q][b]*vs.c()[q][c];
                }
                e3 = max(e3, mag(s3));
                for (label d = 0; d < D; ++d)
                {
                    scalar s4 = 0;
                    for (label q = 0; q < Q; ++q)
                    {
                        s4 += vs.w()[q]*vs.c()[q][a]*vs.c()[q][b]
                             *vs.c()[q][c]*vs.c()[q][d];
                    }
                    const scalar exact = cs2*cs2*
                    (
                        (a == b && c == d) + (a == c && b == d)
                      + (a == d && b == c)
                    );
                    e4 = max(e4, mag(s4 - exact));
                }
            }
        }
    }
    for (label q = 0; q < Q; ++q)
    {
        const labelVector s = vs.c()[q] + vs.c()[vs.opp()[q]];
        eOpp = max(eOpp, scalar(mag(s.x()) + mag(s.y()) + mag(s.z())));
    }

    check(mag(e0) < 1e-15, n + " weights sum to 1", mag(e0));
    {
        // exactly, as the doubles they are (a long double holds their sum
        // without rounding): each equilibrium then holds its density
        long double sum = 0;
        for (label q = 0; q < Q; ++q) sum += vs.w()[q];
        check(sum == 1.0L, n + " weights as doubles sum to exactly 1",
            scalar(sum - 1.0L));
    }
    check(e1 < 1e-15, n + " first moment of weights is 0", e1);
    check(e2 < 1e-15, n + " second moment is cs2 I", e2);
    check(e3 < 1e-15, n + " third moment is 0", e3);
    check(e4 < 1e-15, n + " fourth moment is isotropic cs4 (dd+dd+dd)", e4);
    check(eOpp == 0, n + " opposite directions", eOpp);

    // Equilibrium moments
    Random rnd(7);
    scalar eEq = 0;
    for (label trial = 0; trial < 20; ++trial)
    {
        const scalar rho = 0.9 + 0.2*rnd.sample01<scalar>();
        vector u = 0.1*(2*rnd.sample01<vector>() - vector::one);
        if (D == 2) u.z() = 0;
        const moments m = computeMoments(vs, equilibrium(vs, rho, u));
        eEq = max(eEq, mag(m.rho - rho));
        eEq = max(eEq, mag(m.j - rho*u));
        symmTensor P = rho*cs2*symmTensor::I + rho*sqr(u);
        if (D == 2) P.zz() = 0;
        eEq = max(eEq, mag(m.P - P));
    }
    check(eEq < 1e-15, n + " equilibrium moments rho, rho u, rho(cs2 I + uu)",
        eEq);

    // Guo forcing moments
    scalar eS = 0;
    for (label trial = 0; trial < 20; ++trial)
    {
        vector u = 0.1*(2*rnd.sample01<vector>() - vector::one);
        vector F = 1e-3*(2*rnd.sample01<vector>() - vector::one);
        if (D == 2) { u.z() = 0; F.z() = 0; }
        scalarList S(Q);
        for (label q = 0; q < Q; ++q)
        {
            const vector c(vs.c()[q]);
            S[q] = vs.w()[q]*(3*((c - u) & F) + 9*(c & u)*(c & F));
        }
        const moments m = computeMoments(vs, S);
        eS = max(eS, mag(m.rho));
        eS = max(eS, mag(m.j - F));
        eS = max(eS, mag(m.P - symm(2*(u*F))));
    }
    check(eS < 1e-16, n + " Guo source moments 0, F, uF + Fu", eS);
}


// Collide one node through the run-time selected model and the real kernel
static scalarList collideOne
(
    const collisionModel& model,
    const velocitySet& vs,
    const scalarList& f,
    const vector& F,
    const scalar omega,
    const scalar smagorinsky = 0,
    const scalar kappa = 0,
    const scalar s = 1,
    const vector& Ur = Zero,
    vector* drag = nullptr
)
{
    const label Q = vs.Q();
    scalarList fNew(Q, 0.0);
    label runs[1][2] = {{0, 1}};
    scalarList Fx(1, F.x()), Fy(1, F.y()), Fz(1, F.z());
    const scalarList relaxK(1, kappa), relaxS(1, s);
    const scalarList Urx(1, Ur.x()), Ury(1, Ur.y()), Urz(1, Ur.z());
    scalarList dx(1, 0.0), dy(1, 0.0), dz(1, 0.0);

    lbmKernelArgs a;
    a.fOld = f.cdata();
    a.fNew = fNew.data();
    // (one node, natural layout: direction q at q)
    const labelList base(identity(Q));
    a.srcBase = base.cdata();
    a.dstBase = base.cdata();
    a.oldBase = base.cdata();
    a.runs = runs;
    a.nRuns = 1;
    a.Fx = Fx.cdata();
    a.Fy = Fy.cdata();
    a.Fz = Fz.cdata();
    a.relaxK = relaxK.cdata();
    a.relaxS = relaxS.cdata();
    a.relaxUx = Urx.cdata();
    a.relaxUy = Ury.cdata();
    a.relaxUz = Urz.cdata();
    a.dragX = dx.data();
    a.dragY = dy.data();
    a.dragZ = dz.data();
    a.omega = omega;
    a.smagorinsky = smagorinsky;
    lbmKernelStats stats;
    model.streamCollide(a, stats);
    if (drag)
    {
        *drag = vector(dx[0], dy[0], dz[0]);
    }
    return fNew;
}


static void testCollision
(
    const word& modelName,
    const velocitySet& vs,
    const bool recursive = false
)
{
    dictionary dict;
    dict.add("collisionModel", modelName);
    dictionary coeffs;
    coeffs.add("recursive", recursive);
    dict.add(keyType(word(modelName + "Coeffs")), coeffs);
    autoPtr<collisionModel> model = collisionModel::New(dict, vs);
    const word n =
        modelName + (recursive ? " (recursive) " : " ") + vs.type();
    const label Q = vs.Q();
    const label D = vs.D();
    const scalar omega = 1.0/0.73;

    Random rnd(11);
    scalar eMass = 0, eMom = 0, eFixed = 0, eStress = 0;
    for (label trial = 0; trial < 20; ++trial)
    {
        const scalar rho = 0.95 + 0.1*rnd.sample01<scalar>();
        vector u = 0.05*(2*rnd.sample01<vector>() - vector::one);
        vector F = 1e-3*(2*rnd.sample01<vector>() - vector::one);
        if (D == 2) { u.z() = 0; F.z() = 0; }

        // Equilibrium is a fixed point without force
        const scalarList feq = equilibrium(vs, rho, u);
        {
            // Pre-collision momentum rho u (no force)
            const scalarList fs = collideOne(model(), vs, feq, Zero, omega);
            for (label q = 0; q < Q; ++q)
            {
                eFixed = max(eFixed, mag(fs[q] - feq[q]));
            }
        }

        // Perturbed state with force
        scalarList f(feq);
        for (label q = 0; q < Q; ++q)
        {
            f[q] *= 1 + 0.02*(2*rnd.sample01<scalar>() - 1);
        }
        const moments m0 = computeMoments(vs, f);
        const scalarList fs = collideOne(model(), vs, f, F, omega);
        const moments m1 = computeMoments(vs, fs);
        eMass = max(eMass, mag(m1.rho - m0.rho));
        eMom = max(eMom, mag(m1.j - (m0.j + F)));

        // Second moment as BGK: P* = P - omega (P - Peq) + (1 - omega/2)(uF+Fu)
        const vector uG = (m0.j + 0.5*F)/m0.rho;
        const moments meq = computeMoments(vs, equilibrium(vs, m0.rho, uG));
        const symmTensor Pexp =
            m0.P - omega*(m0.P - meq.P) + (1 - 0.5*omega)*symm(2*(uG*F));
        eStress = max(eStress, mag(m1.P - Pexp));
    }
    check(eMass < 1e-14, n + " conserves mass", eMass);
    check(eMom < 1e-14, n + " momentum gains exactly F", eMom);
    if (!recursive)
    {
        // (the recursive scheme's equilibrium carries third-order terms)
        check(eFixed < 1e-14, n + " equilibrium is a fixed point", eFixed);
    }
    check(eStress < 1e-13, n + " second moment relaxes at 1/tau (viscosity)",
        eStress);

    // No bias in the collision's rounding: the mean relative mass change
    // per collision over many states near rest, summed in long double.
    // Random rounding averages out (about 1e-18 over 4000 states); weights
    // that summed to 1 - 5.55e-17 took omega times that off every node at
    // every collision (-7.6e-17 here: a drift of the water's mass)
    long double bias = 0;
    const label nBias = 4000;
    for (label trial = 0; trial < nBias; ++trial)
    {
        const scalar rho = 0.99 + 0.02*rnd.sample01<scalar>();
        vector u = 1e-3*(2*rnd.sample01<vector>() - vector::one);
        vector F = 1e-5*(2*rnd.sample01<vector>() - vector::one);
        if (D == 2) { u.z() = 0; F.z() = 0; }
        scalarList f = equilibrium(vs, rho, u);
        long double m0 = 0, m1 = 0;
        for (label q = 0; q < Q; ++q)
        {
            f[q] *= 1 + 1e-3*(2*rnd.sample01<scalar>() - 1);
            m0 += f[q];
        }
        const scalarList fs = collideOne(model(), vs, f, F, omega);
        for (label q = 0; q < Q; ++q)
        {
            m1 += fs[q];
        }
        bias += (m1 - m0)/m0;
    }
    bias /= nBias;
    check(std::abs(double(bias)) < 1e-17, n + " no mass drift: mean change "
        "per collision below 1e-17 of the density", scalar(bias));
}


// MRT as applied (the groups' projectors) against its definition in the
// basis: m* = m - S (m - m_eq) + (I - S/2) M F_q, f* = diag(w) M^T m*, with
// every group at its own rate (bulk, odd and even ghosts not the shear's)
static void testMRTMatrix(const velocitySet& vs)
{
    dictionary dict;
    dict.add("collisionModel", "MRT");
    dictionary coeffs;
    coeffs.add("magic", 0.1);
    coeffs.add("omegaEven", 1.3);
    coeffs.add("omegaBulk", 1.1);
    dict.add("MRTCoeffs", coeffs);
    const collisionModels::MRT mrt(dict, vs);
    const scalarList& M = mrt.basis();
    const label Q = vs.Q();
    const label D = vs.D();
    const scalar omega = 1.0/0.61;
    const scalar omegaOdd = 1.0/(0.1/(1.0/omega - 0.5) + 0.5);
    scalarList rate(Q);
    for (label k = 0; k < Q; ++k)
    {
        const label d = mrt.degree()[k];
        rate[k] =
            d < 2 ? 1.0
          : d == 2 ? (mrt.isTrace()[k] ? 1.1 : omega)
          : (d % 2) ? omegaOdd : 1.3;
    }

    Random rnd(5);
    scalar e = 0;
    for (label trial = 0; trial < 20; ++trial)
    {
        const scalar rho = 0.95 + 0.1*rnd.sample01<scalar>();
        vector u = 0.05*(2*rnd.sample01<vector>() - vector::one);
        vector F = 1e-3*(2*rnd.sample01<vector>() - vector::one);
        if (D == 2) { u.z() = 0; F.z() = 0; }
        scalarList f(equilibrium(vs, rho, u));
        for (label q = 0; q < Q; ++q)
        {
            f[q] *= 1 + 0.05*(2*rnd.sample01<scalar>() - 1);
        }
        const scalarList fs = collideOne(mrt, vs, f, F, omega);

        const moments m0 = computeMoments(vs, f);
        const vector uG = (m0.j + 0.5*F)/m0.rho;
        const scalarList feq(equilibrium(vs, m0.rho, uG));
        scalarList dm(Q, 0.0);
        for (label k = 0; k < Q; ++k)
        {
            scalar mneq = 0, mS = 0;
            for (label q = 0; q < Q; ++q)
            {
                const vector c(vs.c()[q]);
                const scalar Sq =
                    vs.w()[q]*(3*((c - uG) & F) + 9*(c & uG)*(c & F));
                mneq += M[k*Q + q]*(f[q] - feq[q]);
                mS += M[k*Q + q]*Sq;
            }
            dm[k] = (1 - rate[k])*mneq + (1 - 0.5*rate[k])*mS;
        }
        for (label q = 0; q < Q; ++q)
        {
            scalar sum = 0;
            for (label k = 0; k < Q; ++k)
            {
                sum += M[k*Q + q]*dm[k];
            }
            e = max(e, mag(fs[q] - (feq[q] + vs.w()[q]*sum)));
        }
    }
    check(e < 1e-14, "MRT " + vs.type() + " by projectors = its matrix form"
        " (bulk, odd, even at their own rates)", e);
}


// Smagorinsky sub-grid model on BGK: conserves, leaves equilibrium alone,
// and relaxes the second moment at the Hou et al. (1996) rate
static void testSmagorinsky(const velocitySet& vs)
{
    dictionary dict;
    dict.add("collisionModel", "BGK");
    autoPtr<collisionModel> model = collisionModel::New(dict, vs);
    const word n = "BGK + Smagorinsky " + vs.type();
    const label Q = vs.Q();
    const label D = vs.D();
    const scalar tau = 0.52, Cs = 0.17;

    Random rnd(5);
    scalar eMass = 0, eMom = 0, eFixed = 0, eStress = 0, tauEffMax = 0;
    for (label trial = 0; trial < 20; ++trial)
    {
        const scalar rho = 0.95 + 0.1*rnd.sample01<scalar>();
        vector u = 0.05*(2*rnd.sample01<vector>() - vector::one);
        vector F = 1e-4*(2*rnd.sample01<vector>() - vector::one);
        if (D == 2) { u.z() = 0; F.z() = 0; }
        const scalarList feq = equilibrium(vs, rho, u);
        {
            const scalarList fs =
                collideOne(model(), vs, feq, Zero, 1.0/tau, Cs);
            for (label q = 0; q < Q; ++q)
            {
                eFixed = max(eFixed, mag(fs[q] - feq[q]));
            }
        }
        scalarList f(feq);
        for (label q = 0; q < Q; ++q)
        {
            f[q] *= 1 + 0.02*(2*rnd.sample01<scalar>() - 1);
        }
        const moments m0 = computeMoments(vs, f);
        const scalarList fs = collideOne(model(), vs, f, F, 1.0/tau, Cs);
        const moments m1 = computeMoments(vs, fs);
        eMass = max(eMass, mag(m1.rho - m0.rho));
        eMom = max(eMom, mag(m1.j - (m0.j + F)));

        // Hou et al.: tau_eff = (tau + sqrt(tau^2 + 18 sqrt(2) Cs^2 |Pi|/rho))/2
        const vector uG = (m0.j + 0.5*F)/m0.rho;
        const moments meq = computeMoments(vs, equilibrium(vs, m0.rho, uG));
        const symmTensor Pi = m0.P - meq.P + symm(uG*F);
        const scalar magPi = std::sqrt(Pi && Pi);
        const scalar tauEff = 0.5*
        (
            tau + std::sqrt(tau*tau + 18*std::sqrt(2.0)*Cs*Cs*magPi/m0.rho)
        );
        tauEffMax = max(tauEffMax, tauEff);
        const scalar w = 1.0/tauEff;
        const symmTensor Pexp =
            m0.P - w*(m0.P - meq.P) + (1 - 0.5*w)*symm(2*(uG*F));
        eStress = max(eStress, mag(m1.P - Pexp));
    }
    check(eMass < 1e-14, n + " conserves mass", eMass);
    check(eMom < 1e-14, n + " momentum gains exactly F", eMom);
    check(eFixed < 1e-14, n + " equilibrium is a fixed point", eFixed);
    check(eStress < 1e-13 && tauEffMax > tau + 1e-3,
        n + " relaxes at the Hou et al. eddy-viscosity rate (largest tau_eff "
      + Foam::name(tauEffMax) + ")", eStress);
}


// The kernel's drag towards rho U_r (lbmKernel.H): on one node without
// streaming the relative momentum decays by exactly exp(-a) for any a
// (never changing sign), the momentum gained is the reported drag impulse,
// and a steady state balances an external force exactly: j = rho U_r + F/a
// with Guo's velocity.
static void testDrag(const word& modelName, const velocitySet& vs)
{
    dictionary dict;
    dict.add("collisionModel", modelName);
    autoPtr<collisionModel> model = collisionModel::New(dict, vs);
    const word n = modelName + " " + vs.type();
    const label D = vs.D();
    const scalar omega = 1.0/0.8;
    const scalar rho = 1.02;
    const vector u(0.03, -0.02, D == 3 ? 0.01 : 0);
    const vector Ur(-0.01, 0.02, D == 3 ? -0.015 : 0);
    const scalarList feq = equilibrium(vs, rho, u);
    const moments m0 = computeMoments(vs, feq);

    scalar eDecay = 0, eImpulse = 0;
    bool signKept = true;
    for (const scalar a : {1e-6, 1e-2, 1.0, 3.0, 1e3, 1e6, 1e12})
    {
        const scalar kappa = -std::expm1(-a);
        vector drag;
        const scalarList fs = collideOne
        (
            model(), vs, feq, Zero, omega, 0, kappa, kappa/a, Ur, &drag
        );
        const moments m1 = computeMoments(vs, fs);
        const vector e0 = m0.j - m0.rho*Ur;
        const vector e1 = m1.j - m0.rho*Ur;
        for (direction d = 0; d < D; ++d)
        {
            eDecay = max(eDecay, mag(e1[d] - std::exp(-a)*e0[d]));
            // (beyond round-off of the momentum itself)
            if (e1[d]*sign(e0[d]) < -1e-15) signKept = false;
        }
        eImpulse = max(eImpulse, mag(m1.j - m0.j - drag));
    }
    check(eDecay < 1e-15, n + " drag: relative momentum decays by exp(-a),"
        " a from 1e-6 to 1e12", eDecay);
    check(signKept, n + " drag: relative momentum never changes sign", 0);
    check(eImpulse < 1e-15, n + " drag: momentum gained = drag impulse",
        eImpulse);

    // Steady balance with an external force F: iterate the node on itself
    // (no streaming); Guo's velocity must satisfy a rho (u - U_r) = F
    scalar eSteady = 0;
    for (const scalar a : {0.1, 10.0, 1e4})
    {
        const scalar kappa = -std::expm1(-a);
        const vector F(1e-5, -2e-5, D == 3 ? 5e-6 : 0);
        scalarList f(feq);
        vector drag(Zero);
        for (label it = 0; it < 400; ++it)
        {
            f = collideOne
            (
                model(), vs, f, F, omega, 0, kappa, kappa/a, Ur, &drag
            );
        }
        const moments m = computeMoments(vs, f);
        // Guo velocity of the last step: (j_before + F_total/2)/rho with
        // j_before = j - F_total
        const vector Ftot = F + drag;
        const vector uG = (m.j - 0.5*Ftot)/m.rho;
        // (absolute, in lattice units: the slip F/a is resolved to the
        // round-off of u)
        eSteady = max(eSteady, mag(m.rho*(uG - Ur) - F/a));
    }
    check(eSteady < 1e-15, n + " drag: steady state rho (u - U_r) = F/a at"
        " a = 0.1, 10, 1e4", eSteady);
}


int main(int argc, char *argv[])
{
    const wordList sets({"D2Q9", "D3Q19", "D3Q27"});
    const wordList models({"BGK", "TRT", "MRT", "regularized"});
    dictionary dummy;

    for (const word& s : sets)
    {
        autoPtr<velocitySet> vs = velocitySet::New(s, dummy);
        testVelocitySet(vs());
        for (const word& m : models)
        {
            testCollision(m, vs());
            testDrag(m, vs());
        }
        testCollision("regularized", vs(), true);
        testSmagorinsky(vs());
        testMRTMatrix(vs());

        // MRT basis orthonormal under the weights
        dictionary dict;
        dict.add("collisionModel", "MRT");
        collisionModels::MRT mrt(dict, vs());
        const scalarList& M = mrt.basis();
        const label Q = vs->Q();
        scalar e = 0;
        for (label k = 0; k < Q; ++k)
        {
            for (label l = 0; l < Q; ++l)
            {
                scalar d = 0;
                for (label q = 0; q < Q; ++q)
                {
                    d += vs->w()[q]*M[k*Q + q]*M[l*Q + q];
                }
                e = max(e, mag(d - (k == l ? 1 : 0)));
            }
        }
        check(e < 1e-12, "MRT " + s + " basis orthonormal", e);
    }

    // Unknown names are refused (FatalIOError lists the valid ones): checked
    // by the bad-input tests, which run the solver

    return finish();
}


// ************************************************************************* //
