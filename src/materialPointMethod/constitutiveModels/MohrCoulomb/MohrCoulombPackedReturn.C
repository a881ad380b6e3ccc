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
    MohrCoulomb: the packed update (updatePacked), four points at once,
    one per SIMD lane, branch-free: the invariant elastic test, the
    closed-form principal values, the return and the rebuild of the
    stress, selected by lane masks; lanes it cannot take go to
    updateScalar. Each step names its point-at-a-time counterpart in
    MohrCoulombScalarReturn.C.

\*---------------------------------------------------------------------------*/

#include "MohrCoulomb.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- symm(A & B) of two symmetric tensors held as component lanes
//  (XX XY XZ YY YZ ZZ)
inline void symmProduct
(
    const Foam::packed::double4 a[6],
    const Foam::packed::double4 b[6],
    Foam::packed::double4 ab[6]
)
{
    ab[0] = a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
    ab[3] = a[1]*b[1] + a[3]*b[3] + a[4]*b[4];
    ab[5] = a[2]*b[2] + a[4]*b[4] + a[5]*b[5];
    ab[1] =
        0.5*((a[0]*b[1] + a[1]*b[3] + a[2]*b[4])
      + (a[1]*b[0] + a[3]*b[1] + a[4]*b[2]));
    ab[2] =
        0.5*((a[0]*b[2] + a[1]*b[4] + a[2]*b[5])
      + (a[2]*b[0] + a[4]*b[1] + a[5]*b[2]));
    ab[4] =
        0.5*((a[1]*b[2] + a[3]*b[4] + a[4]*b[5])
      + (a[2]*b[1] + a[4]*b[3] + a[5]*b[4]));
}

inline bool isDiagonal(const Foam::direction c)
{
    return c == 0 || c == 3 || c == 5;
}


//- spectralOneApart on the lanes of mask: the principal values sB
//  (descending, replaced in those lanes) and directions n[i] of the
//  symmetric A (components XX XY XZ YY YZ ZZ) whose closed-form values sB
//  have one value well apart from the other two. Other lanes compute on
//  guarded values and are left unchanged in sB
inline void spectralOneApartPacked
(
    const Foam::packed::double4 A[6],
    Foam::packed::double4 sB[3],
    const Foam::packed::mask4 mask,
    Foam::packed::double4 n[3][3]
)
{
    using namespace Foam::packed;
    typedef double4 vec[3];

    auto cross = [](const vec& a, const vec& b, vec& c)
    {
        c[0] = a[1]*b[2] - a[2]*b[1];
        c[1] = a[2]*b[0] - a[0]*b[2];
        c[2] = a[0]*b[1] - a[1]*b[0];
    };
    auto dot = [](const vec& a, const vec& b)
    {
        return a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
    };
    auto normalise = [&](vec& a)
    {
        const double4 m2 = dot(a, a);
        const double4 inv = 1.0/sqrt(select(m2 > 0.0, m2, splat(1.0)));
        a[0] *= inv;
        a[1] *= inv;
        a[2] *= inv;
    };
    auto apply = [&](const vec& u, vec& Au)
    {
        Au[0] = A[0]*u[0] + A[1]*u[1] + A[2]*u[2];
        Au[1] = A[1]*u[0] + A[3]*u[1] + A[4]*u[2];
        Au[2] = A[2]*u[0] + A[4]*u[1] + A[5]*u[2];
    };

    const mask4 lowApart = (sB[0] - sB[1]) < (sB[1] - sB[2]);
    const double4 lambda = select(lowApart, sB[2], sB[0]);

    // The direction of the value apart: the largest cross product of two
    // rows of A - lambda I
    const vec r0 = {A[0] - lambda, A[1], A[2]};
    const vec r1 = {A[1], A[3] - lambda, A[4]};
    const vec r2 = {A[2], A[4], A[5] - lambda};
    vec c01, c02, c12;
    cross(r0, r1, c01);
    cross(r0, r2, c02);
    cross(r1, r2, c12);
    const double4 m01 = dot(c01, c01);
    const double4 m02 = dot(c02, c02);
    const double4 m12 = dot(c12, c12);
    const mask4 take01 = (m01 >= m02) & (m01 >= m12);
    const mask4 take02 = ~take01 & (m02 >= m12);
    vec na;
    for (int i = 0; i < 3; ++i)
    {
        na[i] = select(take01, c01[i], select(take02, c02[i], c12[i]));
    }
    normalise(na);

    // u normal to it (its cross product with the axis of its smallest
    // component), v = na x u
    const double4 ax = abs(na[0]), ay = abs(na[1]), az = abs(na[2]);
    const mask4 useX = (ax <= ay) & (ax <= az);
    const mask4 useY = ~useX & (ay <= az);
    // na x e_x = (0, nz, -ny), na x e_y = (-nz, 0, nx), na x e_z = (ny, -nx, 0)
    vec u =
    {
        select(useX, splat(0.0), select(useY, -na[2], na[1])),
        select(useX, na[2], select(useY, splat(0.0), -na[0])),
        select(useX, -na[1], select(useY, na[0], splat(0.0)))
    };
    normalise(u);
    vec v;
    cross(na, u, v);

    // The 2 x 2 problem in that plane, one Jacobi rotation
    vec Au, Av;
    apply(u, Au);
    apply(v, Av);
    const double4 a = dot(u, Au);
    const double4 b = dot(u, Av);
    const double4 d = dot(v, Av);
    // A rotation below 1e-150 is none (and tau^2 would overflow)
    const mask4 rotate = abs(b) > 1e-150*abs(d - a);
    const double4 tau = (d - a)/(2.0*select(rotate, b, splat(1.0)));
    const double4 absTau = abs(tau);
    const double4 tJ =
        select(tau >= 0.0, splat(1.0), splat(-1.0))
       /(absTau + sqrt(1.0 + select(rotate, tau*tau, splat(0.0))));
    const double4 tr = select(rotate, tJ, splat(0.0));
    const double4 c = 1.0/sqrt(1.0 + tr*tr);
    const double4 s = tr*c;
    double4 la = a - tr*b;
    double4 ld = d + tr*b;
    vec e1, e2;
    for (int i = 0; i < 3; ++i)
    {
        e1[i] = c*u[i] - s*v[i];
        e2[i] = s*u[i] + c*v[i];
    }
    const mask4 swap = la < ld;
    {
        const double4 l1 = select(swap, ld, la);
        ld = select(swap, la, ld);
        la = l1;
        for (int i = 0; i < 3; ++i)
        {
            const double4 f = select(swap, e2[i], e1[i]);
            e2[i] = select(swap, e1[i], e2[i]);
            e1[i] = f;
        }
    }

    for (int i = 0; i < 3; ++i)
    {
        n[0][i] = select(lowApart, e1[i], na[i]);
        n[1][i] = select(lowApart, e2[i], e1[i]);
        n[2][i] = select(lowApart, na[i], e2[i]);
    }
    sB[0] = select(mask, select(lowApart, la, lambda), sB[0]);
    sB[1] = select(mask, select(lowApart, ld, la), sB[1]);
    sB[2] = select(mask, select(lowApart, lambda, ld), sB[2]);
}


//- The trial stresses t (components XX XY XZ YY YZ ZZ) of up to four
//  points, stress + (lambda tr(dStrain)) I + 2 G dStrain as
//  elasticIncrement: lane j < nLanes is point j, the others repeat point 0
//  (their results are dropped)
inline void trialStressLanes
(
    const Foam::label nLanes,
    const Foam::symmTensor* dStrain,
    const Foam::symmTensor* stress,
    const Foam::scalar lambda,
    const Foam::scalar G,
    Foam::packed::double4 t[6]
)
{
    using namespace Foam;
    using namespace packed;

    double4 e[6], s[6];
    for (direction c = 0; c < 6; ++c)
    {
        for (int j = 0; j < 4; ++j)
        {
            const label i = (j < nLanes ? j : 0);
            e[c][j] = dStrain[i][c];
            s[c][j] = stress[i][c];
        }
    }
    const double4 lambdaTr = lambda*(e[0] + e[3] + e[5]);
    for (direction c = 0; c < 6; ++c)
    {
        t[c] =
            s[c]
          + (isDiagonal(c) ? lambdaTr + (2*G)*e[c] : (2*G)*e[c]);
    }
}


//- Principal values sB (descending) in closed form of the lanes of the
//  deviator d (mean q, p2 = d:d): principalValues of
//  MohrCoulombScalarReturn.C with the polynomial arc cosine, sine and
//  cosine
inline void principalValuesLanes
(
    const Foam::packed::double4 q,
    const Foam::packed::double4 d[6],
    const Foam::packed::double4 p2,
    Foam::packed::double4 sB[3]
)
{
    using namespace Foam;
    using namespace packed;

    const mask4 spread = (p2 > 0.0);
    const double4 p = sqrt(p2/6.0);
    const double4 invP = 1.0/select(spread, p, splat(1.0));
    double4 B[6];
    for (direction c = 0; c < 6; ++c)
    {
        B[c] = d[c]*invP;
    }
    const double4 detB =
        B[0]*(B[3]*B[5] - B[4]*B[4])
      - B[1]*(B[1]*B[5] - B[4]*B[2])
      + B[2]*(B[1]*B[4] - B[3]*B[2]);
    const double4 r = min(max(0.5*detB, splat(-1.0)), splat(1.0));
    double4 sinA, cosA;
    sincos(acos(r)/3.0, sinA, cosA);
    const double4 s1 = select(spread, q + 2.0*p*cosA, q);
    const double4 s3 =
        select(spread, q - p*(cosA + std::sqrt(3.0)*sinA), q);
    sB[0] = s1;
    sB[1] = select(spread, 3.0*q - s1 - s3, q);
    sB[2] = s3;
}



//- The returned stresses out of the lanes plastic: principal values sC
//  in the principal directions of the trial stresses t (principal values
//  sB), from their spectral projectors (lanes projectors) or from the
//  directions n (lanes oneApart); hydrostatic where sC is
inline void rebuildStressLanes
(
    const Foam::packed::double4 t[6],
    const Foam::packed::double4 sB[3],
    const Foam::packed::double4 sC[3],
    const Foam::packed::mask4 plastic,
    const Foam::packed::mask4 projectors,
    const Foam::packed::mask4 oneApart,
    const Foam::packed::double4 n[3][3],
    Foam::packed::double4 out[6]
)
{
    using namespace Foam;
    using namespace packed;

    // The rebuild from the spectral projectors of the trial stress
    // or from the principal directions; hydrostatic at the apex
    const mask4 separated = plastic & projectors;
    const double4 den1 =
        select(separated, (sB[0] - sB[1])*(sB[0] - sB[2]), splat(1.0));
    const double4 den3 =
        select(separated, (sB[2] - sB[0])*(sB[2] - sB[1]), splat(1.0));
    double4 A1[6], A2[6], A3[6];
    for (direction c = 0; c < 6; ++c)
    {
        const bool diag = isDiagonal(c);
        A1[c] = diag ? t[c] - sB[0] : t[c];
        A2[c] = diag ? t[c] - sB[1] : t[c];
        A3[c] = diag ? t[c] - sB[2] : t[c];
    }
    double4 P1[6], P3[6];
    symmProduct(A2, A3, P1);
    symmProduct(A1, A2, P3);
    const double4 D1 = sC[0] - sB[0];
    const double4 D2 = sC[1] - sB[1];
    const double4 D3 = sC[2] - sB[2];
    const mask4 hydrostatic = (sC[0] == sC[1]) & (sC[1] == sC[2]);
    for (direction c = 0; c < 6; ++c)
    {
        const bool diag = isDiagonal(c);
        const double4 rebuilt =
            (diag ? t[c] + D2 : t[c])
          + (D1 - D2)*(P1[c]/den1) + (D3 - D2)*(P3[c]/den3);
        out[c] =
            select(hydrostatic, diag ? sC[0] : splat(0.0), rebuilt);
    }
    if (any(plastic & oneApart))
    {
        // sum_i sC_i n_i n_i
        constexpr int row[6] = {0, 0, 0, 1, 1, 2};
        constexpr int col[6] = {0, 1, 2, 1, 2, 2};
        for (direction c = 0; c < 6; ++c)
        {
            const double4 rotated =
                sC[0]*n[0][row[c]]*n[0][col[c]]
              + sC[1]*n[1][row[c]]*n[1][col[c]]
              + sC[2]*n[2][row[c]]*n[2][col[c]];
            out[c] = select(oneApart & ~hydrostatic, rotated, out[c]);
        }
    }
}

} // End anonymous namespace

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::constitutiveModels::MohrCoulomb::returnMohrCoulombPacked
(
    const packed::double4 sB[3],
    packed::double4 sC[3],
    packed::mask4& yielding,
    packed::mask4& apexLane,
    packed::mask4& line1Lane,
    packed::mask4& planeLane
) const
{
    using namespace packed;

    // returnMohrCoulomb on four lanes: every region formed and the first
    // that holds taken (apex, line 1, plane, line 2)
    const double4 fB = k_*sB[0] - sB[2] - sigmaC_;
    const double4 x1[3] = {sB[0] - P1_.x(), sB[1] - P1_.y(), sB[2] - P1_.z()};
    const double4 x2[3] = {sB[0] - P2_.x(), sB[1] - P2_.y(), sB[2] - P2_.z()};
    auto dot = [](const vector& a, const double4 x[3])
    {
        return a.x()*x[0] + a.y()*x[1] + a.z()*x[2];
    };
    const double4 t1 = dot(N2_, x1)/N2r1_;
    const double4 t2 = dot(N3_, x2)/N3r2_;
    if (hasApex_)
    {
        apexLane = (t1 > 0.0) & (dot(N3_, x1)/N3r2_ > 0.0);
    }
    line1Lane = ~apexLane & (dot(nI_, x1) < 0.0);
    planeLane = ~apexLane & ~line1Lane & (dot(nII_, x2) <= 0.0);
    yielding = (fB > 0.0);
    for (direction i = 0; i < 3; ++i)
    {
        const double4 onLine2 = P2_[i] + t2*r2_[i];
        const double4 onPlane = sB[i] - fB*rp_[i];
        const double4 onLine1 = P1_[i] + t1*r1_[i];
        sC[i] =
            select
            (
                yielding,
                select
                (
                    apexLane,
                    splat(P1_[i]),
                    select
                    (
                        line1Lane,
                        onLine1,
                        select(planeLane, onPlane, onLine2)
                    )
                ),
                sB[i]
            );
    }
}

Foam::packed::mask4
Foam::constitutiveModels::MohrCoulomb::elasticLanesByInvariants
(
    const packed::double4 q,
    const packed::double4 p2,
    const packed::double4 detDev
) const
{
    using namespace packed;

    // The invariant test of updateScalar (MohrCoulombScalarReturn.C)
    const double4 R = 2.0*sqrt(p2/6.0);
    const mask4 pastPi6 = (detDev < 0.0);
    const double4 gMax =
        select
        (
            pastPi6,
            splat((1 + 1e-12)*0.5*std::sqrt(3.0)*(k_ + 1)),
            splat((1 + 1e-12)*gMax_)
        );
    mask4 elastic = ((k_ - 1)*q + gMax*R - sigmaC_ <= 0.0);
    if (tensionActive_)
    {
        const double4 cosMax =
            select
            (
                pastPi6,
                splat((1 + 1e-12)*0.5*std::sqrt(3.0)),
                splat(1 + 1e-12)
            );
        elastic &= (q + cosMax*R <= sigmaT_);
    }
    return elastic;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::constitutiveModels::MohrCoulomb::updatePacked
(
    const label nLanes,
    const symmTensor* dStrain,
    symmTensor* stress,
    scalar* plasticStrain,
    returnRegion* region
) const
{
    using namespace packed;

    double4 t[6];
    trialStressLanes(nLanes, dStrain, stress, lambda_, G_, t);

    // The invariant test of updateScalar: sufficient for elastic
    const double4 q = (t[0] + t[3] + t[5])/3.0;
    const double4 d[6] = {t[0] - q, t[1], t[2], t[3] - q, t[4], t[5] - q};
    const double4 p2 =
        d[0]*d[0] + d[3]*d[3] + d[5]*d[5]
      + 2.0*(d[1]*d[1] + d[2]*d[2] + d[4]*d[4]);
    const double4 detDev =
        d[0]*(d[3]*d[5] - d[4]*d[4])
      - d[1]*(d[1]*d[5] - d[4]*d[2])
      + d[2]*(d[1]*d[4] - d[3]*d[2]);
    mask4 elastic = elasticLanesByInvariants(q, p2, detDev);

    const mask4 none = {0, 0, 0, 0};
    mask4 fallback = none;
    mask4 plastic = none;
    double4 out[6], sC[3], dPlastic = splat(0.0);
    mask4 apexLane = none, line1Lane = none, planeLane = none;

    if (!all(elastic))
    {
        double4 sB[3];
        principalValuesLanes(q, d, p2, sB);

        // The margin test and the choice of rebuild of updateScalar
        const double4 scale = abs(sB[0]) + abs(sB[2]) + sigmaC_;
        const double4 gap = min(sB[0] - sB[1], sB[1] - sB[2]);
        {
            const double4 margin =
                1e-10*scale
               *(1.0 + 1e-5*scale/max(gap, 1e-30*scale + VSMALL));
            mask4 inside = (k_*sB[0] - sB[2] - sigmaC_ <= -margin);
            if (tensionActive_)
            {
                inside &= (sB[0] <= sigmaT_ - margin);
            }
            elastic |= inside;
        }
        // Well separated values: the closed form and the projectors; two
        // close and the third apart: spectralOneApart; else (all three
        // close, near the hydrostatic axis) updateScalar's decomposition
        const mask4 projectors = ~elastic & (gap > 1e-5*scale);
        const mask4 oneApart =
            ~elastic & ~projectors
          & (max(sB[0] - sB[1], sB[1] - sB[2]) > 1e-3*scale);
        fallback = ~elastic & ~projectors & ~oneApart;
        double4 n[3][3];
        if (any(oneApart))
        {
            spectralOneApartPacked(t, sB, oneApart, n);
        }

        mask4 yielding = none;
        returnMohrCoulombPacked
        (
            sB, sC, yielding, apexLane, line1Lane, planeLane
        );
        if (tensionActive_)
        {
            // principalReturn: a result above the cut-off (also of a trial
            // inside the Mohr-Coulomb surface) takes the combined return
            fallback |= ~elastic & (sC[0] > sigmaT_);
        }
        plastic = ~elastic & ~fallback & yielding;

        if (any(plastic))
        {
            // accumulatePlasticStrain
            const double4 dS[3] = {sB[0] - sC[0], sB[1] - sC[1], sB[2] - sC[2]};
            const double4 meanDS = (dS[0] + dS[1] + dS[2])/3.0;
            const double4 dev0 = dS[0] - meanDS;
            const double4 dev1 = dS[1] - meanDS;
            const double4 dev2 = dS[2] - meanDS;
            dPlastic =
                std::sqrt(2.0/3.0)*sqrt(dev0*dev0 + dev1*dev1 + dev2*dev2)
               /(2*G_);

            rebuildStressLanes
            (
                t, sB, sC, plastic, projectors, oneApart, n, out
            );
        }
    }

    // Store lane by lane
    for (int j = 0; j < nLanes; ++j)
    {
        returnRegion rj = MohrCoulomb::elastic;
        if (fallback[j])
        {
            rj = updateScalar(dStrain[j], stress[j], plasticStrain[j]);
        }
        else if (plastic[j])
        {
            for (direction c = 0; c < 6; ++c)
            {
                stress[j][c] = out[c][j];
            }
            plasticStrain[j] += dPlastic[j];
            rj =
                apexLane[j] ? apex
              : line1Lane[j] ? compressionLine
              : planeLane[j] ? MohrCoulomb::plane
              : extensionLine;
        }
        else
        {
            for (direction c = 0; c < 6; ++c)
            {
                stress[j][c] = t[c][j];
            }
        }
        if (region)
        {
            region[j] = rj;
        }
    }
}


// ************************************************************************* //
