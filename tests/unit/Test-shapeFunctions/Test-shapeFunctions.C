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
    Test-shapeFunctions

Description
    Unit checks of the material point method shape functions (linear,
    GIMP for several particle sizes, quadraticBSpline, cubicBSpline),
    selected at run time, in lattice units, at random positions and at
    the special points (nodes, cell faces, GIMP knots, and one ulp either
    side of them):
    - support() and reach() as documented, reach attained;
    - partition of unity, sum dw = 0, linear completeness
      sum w_i i = x, sum dw_i i = 1 (1D, 2D and 3D tensor products);
    - non-negative weights, and every node of a wide window equal to an
      independent brute-force evaluation of N(x - i) and N'(x - i)
      (so zero outside the support);
    - derivative equal to a central finite difference of the weights;
    - continuity from one-sided limits at the special points: C0 linear,
      C1 GIMP and quadratic B-spline, C2 cubic B-spline, with the next
      derivative's jump printed as a negative control;
    - B-spline moments: sum w_i (i - x)^2 = (p + 1)/12 (1/4 quadratic,
      1/3 cubic), i.e. sum w_i i^2 = x^2 + (p + 1)/12, and for the cubic
      sum w_i (i - x)^3 = 0;
    - GIMP tends to linear as halfLength -> 0, equals it at 0, and equals
      the quadratic B-spline at halfLength = 1/2;
    - bad input: unknown or missing name (FatalIOError), GIMP particles
      larger than a cell (FatalError).
    Prints PASS:/FAIL: lines; exits 1 on any failure.

\*---------------------------------------------------------------------------*/

#include "shapeFunction.H"
#include "IOstreams.H"
#include "tensor.H"
#include "unitTest.H"

#include <random>
#include <vector>
#include <functional>

using namespace Foam;

using namespace Foam::unitTest;


// * * * * * * * * * * * * * Reference 1D functions  * * * * * * * * * * * //

// Written from the textbook definitions in r = x - i, independently of the
// library's local-coordinate kernels.

struct reference
{
    word name;
    scalar lp;          // GIMP half-length
    label support;
    label reach;
    label continuity;   // 0: C0, 1: C1, 2: C2

    scalar N(const scalar r) const
    {
        const scalar a = mag(r);
        if (name == "linear")
        {
            return a < 1 ? 1 - a : 0;
        }
        else if (name == "GIMP")
        {
            if (a < lp) return 1 - (r*r + lp*lp)/(2*lp);
            if (a <= 1 - lp) return 1 - a;
            if (a < 1 + lp) return sqr(1 + lp - a)/(4*lp);
            return 0;
        }
        else if (name == "quadraticBSpline")
        {
            if (a <= 0.5) return 0.75 - r*r;
            if (a < 1.5) return 0.5*sqr(1.5 - a);
            return 0;
        }
        else
        {
            if (a <= 1) return 2.0/3.0 - r*r + 0.5*a*a*a;
            if (a < 2) return pow3(2 - a)/6;
            return 0;
        }
    }

    // dN/dx; for the linear tent, the derivative from the right at kinks
    scalar dN(const scalar r) const
    {
        const scalar a = mag(r);
        const scalar s = r < 0 ? -1 : 1;
        if (name == "linear")
        {
            return r >= 0 ? (r < 1 ? -1 : 0) : (r >= -1 ? 1 : 0);
        }
        else if (name == "GIMP")
        {
            if (a < lp) return -r/lp;
            if (a <= 1 - lp) return -s;
            if (a < 1 + lp) return -s*(1 + lp - a)/(2*lp);
            return 0;
        }
        else if (name == "quadraticBSpline")
        {
            if (a <= 0.5) return -2*r;
            if (a < 1.5) return -s*(1.5 - a);
            return 0;
        }
        else
        {
            if (a <= 1) return -2*r + 1.5*s*a*a;
            if (a < 2) return -0.5*s*sqr(2 - a);
            return 0;
        }
    }
};


// * * * * * * * * * * * * Dense window of node weights  * * * * * * * * * //

static const label nWin = 16;

struct window
{
    label base;         // lattice index of the window's first node
    label first;        // as returned by the shape function
    scalar W[nWin];
    scalar dW[nWin];
    bool inside;        // the support lies within the window
};

static window evaluate
(
    const shapeFunction& sf,
    const scalar x,
    const scalar lp
)
{
    window d;
    d.base = label(std::floor(x)) - nWin/2;
    for (label n = 0; n < nWin; ++n)
    {
        d.W[n] = 0;
        d.dW[n] = 0;
    }
    scalar w[shapeWeights::maxSupport], dw[shapeWeights::maxSupport];
    sf.weights1D(x, lp, d.first, w, dw);
    const label o = d.first - d.base;
    d.inside = (o >= 0 && o + sf.support() <= nWin);
    if (d.inside)
    {
        for (label a = 0; a < sf.support(); ++a)
        {
            d.W[o + a] = w[a];
            d.dW[o + a] = dw[a];
        }
    }
    return d;
}


// Max |A - B| over nodes of two windows at nearby positions (same base
// assumed if both x have the same floor, otherwise aligned by index)
static scalar maxDiff
(
    const window& A, const scalar* a,
    const window& B, const scalar* b
)
{
    scalar e = 0;
    for (label n = 0; n < nWin; ++n)
    {
        const label m = n + A.base - B.base;
        const scalar bv = (m >= 0 && m < nWin) ? b[m] : 0;
        e = max(e, mag(a[n] - bv));
    }
    for (label m = 0; m < nWin; ++m)
    {
        const label n = m + B.base - A.base;
        if (n < 0 || n >= nWin)
        {
            e = max(e, mag(b[m]));
        }
    }
    return e;
}


// * * * * * * * * * * * * * * * * * Checks  * * * * * * * * * * * * * * * //

struct maxErr
{
    scalar pu = 0, sdw = 0, lin = 0, dlin = 0, neg = 0, brute = 0,
        bruteD = 0, fd = 0, mom2 = 0, dmom2 = 0, mom3 = 0, dmom3 = 0;
    label outside = 0, reachSeen = 0, reachOver = 0, nFD = 0;
};


static void pointChecks
(
    const shapeFunction& sf,
    const reference& ref,
    const scalar x,
    const bool doFD,
    maxErr& e
)
{
    const window d = evaluate(sf, x, ref.lp);
    if (!d.inside)
    {
        ++e.outside;
        return;
    }

    const label c = label(std::floor(x + 0.5));
    const scalar scale = 1 + mag(x);
    scalar s = 0, sd = 0, sx = 0, sdx = 0, m2 = 0, dm2 = 0, m3 = 0, dm3 = 0;
    for (label n = 0; n < nWin; ++n)
    {
        const label i = d.base + n;
        const scalar w = d.W[n], dw = d.dW[n];
        s += w;
        sd += dw;
        sx += w*i;
        sdx += dw*i;
        const scalar r = i - x;
        m2 += w*r*r;
        dm2 += dw*r*r;
        m3 += w*r*r*r;
        dm3 += dw*r*r*r;
        e.neg = max(e.neg, -w);
        e.brute = max(e.brute, mag(w - ref.N(x - i)));
        // The tent's derivative is one-sided at the nodes: compare away
        // from them (the convention at nodes is checked separately)
        if (ref.continuity > 0 || mag(x - std::round(x)) > 1e-12)
        {
            e.bruteD = max(e.bruteD, mag(dw - ref.dN(x - i)));
        }
        if (w != 0 || ref.N(x - i) != 0)
        {
            e.reachSeen = max(e.reachSeen, mag(i - c));
            if (i < d.first || i >= d.first + sf.support())
            {
                ++e.reachOver;
            }
        }
    }
    e.pu = max(e.pu, mag(s - 1));
    e.sdw = max(e.sdw, mag(sd));
    e.lin = max(e.lin, mag(sx - x)/scale);
    e.dlin = max(e.dlin, mag(sdx - 1)/scale);
    if (ref.name == "quadraticBSpline")
    {
        e.mom2 = max(e.mom2, mag(m2 - 0.25));
        e.dmom2 = max(e.dmom2, mag(dm2));
    }
    if (ref.name == "cubicBSpline")
    {
        e.mom2 = max(e.mom2, mag(m2 - 1.0/3.0));
        e.dmom2 = max(e.dmom2, mag(dm2));
        e.mom3 = max(e.mom3, mag(m3));
        e.dmom3 = max(e.dmom3, mag(dm3 - 1));
    }

    if (doFD)
    {
        const scalar h = 1e-6;
        const scalar xp = x + h, xm = x - h;
        const window P = evaluate(sf, xp, ref.lp);
        const window M = evaluate(sf, xm, ref.lp);
        for (label n = 0; n < nWin; ++n)
        {
            const label mp = n + d.base - P.base;
            const label mm = n + d.base - M.base;
            const scalar wp = (mp >= 0 && mp < nWin) ? P.W[mp] : 0;
            const scalar wm = (mm >= 0 && mm < nWin) ? M.W[mm] : 0;
            e.fd = max(e.fd, mag((wp - wm)/(xp - xm) - d.dW[n]));
        }
        ++e.nFD;
    }
}


// Distance of x to the nearest point where a piecewise definition switches
static scalar knotDistance(const scalar x, const scalar lp)
{
    const scalar f = x - std::floor(x);
    scalar d = min(f, 1 - f);                       // nodes
    d = min(d, mag(f - 0.5));                       // faces
    if (lp > 0)
    {
        d = min(d, min(mag(f - lp), mag(f - (1 - lp))));    // GIMP knots
    }
    return d;
}


// One-sided limits at a special point xk: jumps of the weights, their
// derivatives, and the second derivatives (one-sided differences of dw)
static void continuityChecks
(
    const shapeFunction& sf,
    const scalar xk,
    const scalar lp,
    scalar& jump0,
    scalar& jump1,
    scalar& jump2
)
{
    const scalar e = 1e-9;
    const window L = evaluate(sf, xk - e, lp);
    const window R = evaluate(sf, xk + e, lp);
    const window K = evaluate(sf, xk, lp);
    jump0 = max(maxDiff(L, L.W, R, R.W), maxDiff(K, K.W, R, R.W));
    jump1 = max(maxDiff(L, L.dW, R, R.dW), maxDiff(K, K.dW, R, R.dW));

    // Second derivative from each side, h = 1e-6 (exact for piecewise
    // quadratic dw away from the point, error O(h) otherwise)
    const scalar h = 1e-6;
    const scalar xl1 = xk - h, xl2 = xk - 2*h, xr1 = xk + h, xr2 = xk + 2*h;
    const window L1 = evaluate(sf, xl1, lp), L2 = evaluate(sf, xl2, lp);
    const window R1 = evaluate(sf, xr1, lp), R2 = evaluate(sf, xr2, lp);
    jump2 = 0;
    for (label n = 0; n < nWin; ++n)
    {
        const label i = L1.base + n;
        auto at = [i](const window& w, const scalar* v)
        {
            const label m = i - w.base;
            return (m >= 0 && m < nWin) ? v[m] : 0.0;
        };
        // dw at xk +- h extrapolated to xk with the other one-sided point
        const scalar d2l = (at(L1, L1.dW) - at(L2, L2.dW))/(xl1 - xl2);
        const scalar d2r = (at(R2, R2.dW) - at(R1, R1.dW))/(xr2 - xr1);
        jump2 = max(jump2, mag(d2r - d2l));
    }
}


//- 1D properties at random positions and at special points (nodes, cell
//  centres, GIMP's knots) with one ulp either side
static void test1D
(
    const shapeFunction& sf,
    const reference& ref,
    const string& tag,
    std::mt19937_64& gen
)
{
    const word& name = ref.name;
    const scalar lp = ref.lp;

    // Positions: random, and special points with one ulp either side
    std::uniform_real_distribution<scalar> U(-20, 1000);
    std::vector<scalar> randomX(20000);
    for (scalar& x : randomX) x = U(gen);

    std::vector<scalar> special;
    for (const label n : {-3, -2, -1, 0, 1, 2, 3, 7, 511, 998})
    {
        std::vector<scalar> base{scalar(n), n + 0.5};
        if (lp > 0)
        {
            for (const scalar k : {lp, 1 - lp, -lp, lp - 1, 1 + lp})
            {
                base.push_back(n + k);
            }
        }
        for (const scalar b : base)
        {
            special.push_back(b);
            special.push_back(std::nextafter(b, -GREAT));
            special.push_back(std::nextafter(b, GREAT));
        }
    }

    maxErr e;
    for (const scalar x : randomX)
    {
        pointChecks(sf, ref, x, knotDistance(x, lp) > 1e-5, e);
    }
    for (const scalar x : special)
    {
        pointChecks(sf, ref, x, false, e);
    }

    check(e.outside == 0, tag + ": support within the test window", 0);
    check(e.pu <= 1e-14, tag + ": 1D partition of unity |sum w - 1|", e.pu);
    check(e.sdw <= 1e-14, tag + ": 1D |sum dw|", e.sdw);
    check
    (
        e.lin <= 1e-14,
        tag + ": 1D linear completeness |sum w_i i - x|/(1 + |x|)", e.lin
    );
    check
    (
        e.dlin <= 1e-14,
        tag + ": 1D |sum dw_i i - 1|/(1 + |x|)", e.dlin
    );
    check(e.neg <= 0, tag + ": weights non-negative (max -w)", e.neg);
    check
    (
        e.brute <= 1e-14,
        tag + ": weights = brute-force N(x - i) on 16 nodes, 0 outside the"
        " support", e.brute
    );
    check
    (
        e.bruteD <= 1e-13,
        tag + ": derivatives = brute-force N'(x - i) on 16 nodes"
      + (name == "linear" ? " (off nodes)" : ""), e.bruteD
    );
    check
    (
        e.reachOver == 0 && e.reachSeen == sf.reach(),
        tag + ": non-zero weights only on first..first+support-1, max |i -"
        " floor(x+1/2)| = " + Foam::name(e.reachSeen) + " = reach()",
        scalar(e.reachOver)
    );
    check
    (
        e.fd <= 1e-7 && e.nFD > 19000,
        tag + ": dw = central difference of w, h = 1e-6, "
      + Foam::name(e.nFD) + " points", e.fd
    );
    if (name == "quadraticBSpline" || name == "cubicBSpline")
    {
        const scalar c = name == "cubicBSpline" ? 1.0/3.0 : 0.25;
        check
        (
            e.mom2 <= 1e-12,
            tag + ": sum w_i (i - x)^2 = " + Foam::name(c)
          + " (sum w_i i^2 = x^2 + " + Foam::name(c) + ")", e.mom2
        );
        check(e.dmom2 <= 1e-12, tag + ": sum dw_i (i - x)^2 = 0", e.dmom2);
    }
    if (name == "cubicBSpline")
    {
        check(e.mom3 <= 1e-12, tag + ": sum w_i (i - x)^3 = 0", e.mom3);
        check(e.dmom3 <= 1e-12, tag + ": sum dw_i (i - x)^3 = 1", e.dmom3);
    }

}


//- Continuity of w, dw and d2w at the knots: as much as the function
//  promises, and (control) the jump it does have one order higher
static void testContinuity
(
    const shapeFunction& sf,
    const reference& ref,
    const string& tag
)
{
    const word& name = ref.name;
    const scalar lp = ref.lp;

    // Continuity at every special point (they include all knots)
    scalar j0 = 0, j1 = 0, j2 = 0;
    for (const label n : {-2, 0, 1, 5, 511})
    {
        std::vector<scalar> pts{scalar(n), n + 0.5};
        if (lp > 0)
        {
            pts.push_back(n + lp);
            pts.push_back(n + 1 - lp);
        }
        for (const scalar xk : pts)
        {
            scalar a, b, c;
            continuityChecks(sf, xk, lp, a, b, c);
            j0 = max(j0, a);
            j1 = max(j1, b);
            j2 = max(j2, c);
        }
    }
    check(j0 <= 1e-8, tag + ": C0, jump of w at the special points", j0);
    if (ref.continuity >= 1)
    {
        const scalar tol = 1e-8/max(lp, 1e-2);
        check(j1 <= tol, tag + ": C1, jump of dw at the special points", j1);
    }
    else
    {
        check
        (
            mag(j1 - 2) < 1e-6,
            tag + ": not C1 (control: dw of the node jumps from 1 to -1)",
            mag(j1 - 2)
        );

        // At a point exactly on node n: the derivative from the right
        scalar e = 0;
        for (const label n : {-3, 0, 1, 7, 511})
        {
            label first;
            scalar w[4], dw[4];
            sf.weights1D(n, 0, first, w, dw);
            e = max(e, scalar(mag(first - n)));
            e = max(e, max(mag(w[0] - 1), mag(w[1])));
            e = max(e, max(mag(dw[0] + 1), mag(dw[1] - 1)));
        }
        check
        (
            e == 0,
            tag + ": on node n: w = (1, 0), dw = (-1, 1) on nodes n, n+1"
            " (right derivative)", e
        );
    }
    if (ref.continuity >= 2)
    {
        check
        (
            j2 <= 1e-4,
            tag + ": C2, jump of d2w (one-sided differences) at the special"
            " points", j2
        );
    }
    else if (ref.continuity == 1)
    {
        // GIMP: N'' jumps by 1/lp at |r| = lp and by 1/(2 lp) at
        // 1 +- lp (1/lp at lp = 1/2 where the two coincide); quadratic:
        // from -2 to 1, i.e. by 3 at |r| = 1/2
        const scalar expect =
            name == "quadraticBSpline" ? 3 : (lp == 0.5 ? 3 : 1/lp);
        check
        (
            mag(j2 - expect) < 1e-3*expect,
            tag + ": not C2 (control: d2w jumps by "
          + Foam::name(expect) + ")", mag(j2 - expect)
        );
    }

}


//- The 3D and 2D tensor products of the 1D kernel
static void testTensorProducts
(
    const shapeFunction& sf,
    const reference& ref,
    const string& tag,
    std::mt19937_64& gen
)
{
    const scalar lp = ref.lp;

    // Tensor products, 3D and 2D
    std::uniform_real_distribution<scalar> U3(-0.5, 60);
    for (const label nDim : {3, 2})
    {
        scalar pu = 0, sg = 0, lin = 0, dlin = 0, acc = 0, brute = 0;
        label bad = 0;
        const tensor I2(1, 0, 0, 0, 1, 0, 0, 0, nDim == 3 ? 1 : 0);
        for (label p = 0; p < 5000; ++p)
        {
            vector x(U3(gen), U3(gen), U3(gen));
            if (p < 27)
            {
                // Nodes, faces and corners
                x = vector(p % 3, (p/3) % 3, p/9)*0.5 + vector(4, 5, 6);
            }
            const vector hl(lp, lp, lp);
            shapeWeights sw;
            sf.weights(x, hl, nDim, sw);
            if
            (
                sw.size() != sf.nNodes(nDim)
             || (nDim == 2 && sw.first.z() != label(std::floor(x.z()+0.5)))
            )
            {
                ++bad;
            }
            scalar s = 0;
            vector g(Zero), sx(Zero);
            tensor sdx(Zero);
            sw.forEachNode
            (
                [&](label i, label j, label k, scalar N, const vector& gN)
                {
                    const vector xi(i, j, k);
                    s += N;
                    g += gN;
                    sx += N*xi;
                    sdx += gN*xi;
                    const label a = i - sw.first.x();
                    const label b = j - sw.first.y();
                    const label c = k - sw.first.z();
                    acc = max(acc, mag(N - sw.N(a, b, c)));
                    acc = max(acc, mag(gN - sw.gradN(a, b, c)));
                    const scalar nz = nDim == 3 ? ref.N(x.z() - k) : 1;
                    brute = max
                    (
                        brute,
                        mag(N - ref.N(x.x() - i)*ref.N(x.y() - j)*nz)
                    );
                }
            );
            pu = max(pu, mag(s - 1));
            sg = max(sg, mag(g));
            vector dx(sx - x);
            if (nDim == 2) dx.z() = 0;
            lin = max(lin, mag(dx)/(1 + mag(x)));
            dlin = max(dlin, mag(sdx - I2)/(1 + mag(x)));
        }
        const string t = tag + ": " + Foam::name(nDim) + "D tensor product";
        check
        (
            bad == 0,
            t + " has support^nDim nodes (z collapsed in 2D)", scalar(bad)
        );
        check(pu <= 1e-14, t + " |sum N - 1|", pu);
        check(sg <= 1e-14, t + " |sum grad N|", sg);
        check(lin <= 1e-14, t + " |sum N x_i - x|/(1 + |x|)", lin);
        check(dlin <= 1e-14, t + " |sum grad N x_i - I|/(1 + |x|)", dlin);
        // Same products; not compared bitwise since the compiler may
        // contract the test's subtraction into an FMA
        check
        (
            acc <= 1e-15, t + ": forEachNode = N(a,b,c), gradN(a,b,c)", acc
        );
        check(brute <= 1e-14, t + " = product of brute-force N", brute);
    }
}


static void testShapeFunction(const word& name, const scalar lp)
{
    dictionary dict;
    dict.add("shapeFunction", name);
    autoPtr<shapeFunction> sfPtr = shapeFunction::New(dict);
    const shapeFunction& sf = *sfPtr;

    reference ref;
    ref.name = name;
    ref.lp = lp;
    ref.support =
        name == "linear" ? 2 : name == "cubicBSpline" ? 4 : 3;
    ref.reach = name == "cubicBSpline" ? 2 : 1;
    ref.continuity =
        name == "linear" ? 0 : name == "cubicBSpline" ? 2 : 1;

    const string tag =
        name + (name == "GIMP" ? " lp=" + Foam::name(lp) : string(""));

    check
    (
        sf.type() == name && sf.support() == ref.support
     && sf.reach() == ref.reach,
        tag + ": selected, support " + Foam::name(sf.support())
      + ", reach " + Foam::name(sf.reach()),
        0
    );

    // One generator for both random sets, in this order
    std::mt19937_64 gen(12345);
    test1D(sf, ref, tag, gen);
    testContinuity(sf, ref, tag);
    testTensorProducts(sf, ref, tag, gen);
}


static void testGIMPLimits()
{
    dictionary dG, dL, dQ;
    dG.add("shapeFunction", word("GIMP"));
    dL.add("shapeFunction", word("linear"));
    dQ.add("shapeFunction", word("quadraticBSpline"));
    autoPtr<shapeFunction> G(shapeFunction::New(dG));
    autoPtr<shapeFunction> L(shapeFunction::New(dL));
    autoPtr<shapeFunction> Q(shapeFunction::New(dQ));

    std::mt19937_64 gen(777);
    std::uniform_real_distribution<scalar> U(-5, 200);
    std::vector<scalar> xs(5000);
    for (scalar& x : xs) x = U(gen);
    for (label n = 0; n < 4; ++n)
    {
        xs.push_back(n);
        xs.push_back(n + 0.5);
    }

    scalar prev = GREAT;
    bool monotone = true;
    for (const scalar lp : {1e-1, 1e-2, 1e-4, 1e-6, 1e-8, 0.0})
    {
        scalar e = 0;
        for (const scalar x : xs)
        {
            const window g = evaluate(*G, x, lp);
            const window l = evaluate(*L, x, 0);
            e = max(e, maxDiff(g, g.W, l, l.W));
        }
        // The largest difference is lp/2, at a node
        const bool ok = (lp == 0 ? e == 0 : e <= 0.5*lp*(1 + 1e-6));
        check
        (
            ok,
            "GIMP -> linear: max |w_GIMP - w_linear| <= lp/2 at lp = "
          + Foam::name(lp), e
        );
        monotone = monotone && e <= prev;
        prev = e;
    }
    check(monotone, "GIMP -> linear: difference decreases with lp", 0);

    scalar e = 0;
    for (const scalar x : xs)
    {
        const window g = evaluate(*G, x, 0.5);
        const window q = evaluate(*Q, x, 0);
        e = max(e, maxDiff(g, g.W, q, q.W));
        e = max(e, maxDiff(g, g.dW, q, q.dW));
    }
    check(e <= 1e-15, "GIMP lp = 1/2 is the quadratic B-spline", e);
}


static void testBadInput()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    {
        dictionary d;
        d.add("shapeFunction", word("quinticBSpline"));
        bool caught = false;
        try
        {
            autoPtr<shapeFunction> sf(shapeFunction::New(d));
        }
        catch (const Foam::IOerror& err)
        {
            caught = true;
            const string msg(err.message());
            Info<< "    (message: " << msg.substr(0, msg.find('\n')).c_str()
                << ")" << endl;
        }
        check(caught, "bad input: unknown shapeFunction -> FatalIOError", 0);
    }
    {
        dictionary d;
        bool caught = false;
        try
        {
            autoPtr<shapeFunction> sf(shapeFunction::New(d));
        }
        catch (const Foam::IOerror&)
        {
            caught = true;
        }
        check(caught, "bad input: missing shapeFunction -> FatalIOError", 0);
    }
    {
        dictionary d;
        d.add("shapeFunction", word("GIMP"));
        autoPtr<shapeFunction> sf(shapeFunction::New(d));
        label nCaught = 0;
        for (const scalar lp : {0.6, -0.1})
        {
            try
            {
                sf->checkHalfLength(lp);
            }
            catch (const Foam::error&)
            {
                ++nCaught;
            }
        }
        bool okCaught = false;
        try
        {
            sf->checkHalfLength(0.5);
            sf->checkHalfLength(0.25);
        }
        catch (const Foam::error&)
        {
            okCaught = true;
        }
        check
        (
            nCaught == 2 && !okCaught,
            "bad input: GIMP halfLength 0.6 and -0.1 -> FatalError,"
            " 0.5 and 0.25 accepted", scalar(2 - nCaught)
        );
    }
    {
        dictionary d;
        d.add("shapeFunction", word("cubicBSpline"));
        autoPtr<shapeFunction> sf(shapeFunction::New(d));
        bool caught = false;
        try
        {
            sf->checkHalfLength(0.6);
        }
        catch (const Foam::error&)
        {
            caught = true;
        }
        check(!caught, "cubicBSpline ignores halfLength (0.6 accepted)", 0);
    }

    FatalError.dontThrowExceptions();
    FatalIOError.dontThrowExceptions();
}


// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    testShapeFunction("linear", 0);
    for (const scalar lp : {0.25, 1.0/6.0, 0.125, 0.4, 0.5})
    {
        testShapeFunction("GIMP", lp);
    }
    testShapeFunction("quadraticBSpline", 0);
    testShapeFunction("cubicBSpline", 0);
    testGIMPLimits();
    testBadInput();

    return finish();
}


// ************************************************************************* //
