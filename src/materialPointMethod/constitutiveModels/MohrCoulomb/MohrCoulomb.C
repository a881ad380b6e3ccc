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

// Eigen before the OpenFOAM headers (macro hygiene)
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "MohrCoulomb.H"
#include "addToRunTimeSelectionTable.H"
#include "unitConversion.H"
#include "packedDouble4.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace constitutiveModels
{
    defineTypeNameAndDebug(MohrCoulomb, 0);
    addToRunTimeSelectionTable(constitutiveModel, MohrCoulomb, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Principal values of a symmetric tensor, descending, in closed form
//  (trigonometric solution of the characteristic cubic; Smith 1961,
//  Commun. ACM 4, 168). Absolute error a few ulps of the deviator's size p
//  where the values are well apart; near a repeated pair the arc cosine is
//  ill-conditioned and the error grows to about eps p^2/gap.
inline Foam::vector principalValues(const Foam::symmTensor& A)
{
    using namespace Foam;
    const scalar q = tr(A)/3;
    const scalar offDiag = sqr(A.xy()) + sqr(A.xz()) + sqr(A.yz());
    const scalar p2 =
        sqr(A.xx() - q) + sqr(A.yy() - q) + sqr(A.zz() - q) + 2*offDiag;
    if (p2 <= 0)
    {
        return vector(q, q, q);
    }
    const scalar p = std::sqrt(p2/6);
    const symmTensor B((A - q*symmTensor::I)/p);
    const scalar r = min(max(det(B)/2, scalar(-1)), scalar(1));
    const scalar angle = std::acos(r)/3;
    // cos(angle + 2 pi/3) = -cos(angle)/2 - sqrt(3)/2 sin(angle): one sincos
    const scalar c = std::cos(angle);
    const scalar s = std::sin(angle);
    const scalar s1 = q + 2*p*c;
    const scalar s3 = q - p*(c + std::sqrt(3.0)*s);
    return vector(s1, 3*q - s1 - s3, s3);
}


//- Principal values (descending) and directions of a symmetric A whose
//  closed-form values sApprox have one value well apart from the other two
inline void spectralOneApart
(
    const Foam::symmTensor& A,
    const Foam::vector& sApprox,
    Foam::vector& sB,
    Foam::vector& n1,
    Foam::vector& n2,
    Foam::vector& n3
)
{
    using namespace Foam;

    // The value apart: the smallest when the largest two are close. Its
    // closed-form value is accurate (the closed form's error near a pair
    // lies in the pair's split, not in the third value)
    const bool lowApart =
        (sApprox.x() - sApprox.y()) < (sApprox.y() - sApprox.z());
    const scalar lambda = lowApart ? sApprox.z() : sApprox.x();

    // Its direction: the largest cross product of two rows of A - lambda I
    const vector r0(A.xx() - lambda, A.xy(), A.xz());
    const vector r1(A.xy(), A.yy() - lambda, A.yz());
    const vector r2(A.xz(), A.yz(), A.zz() - lambda);
    const vector c01(r0 ^ r1), c02(r0 ^ r2), c12(r1 ^ r2);
    const scalar m01 = magSqr(c01), m02 = magSqr(c02), m12 = magSqr(c12);
    vector na =
        (m01 >= m02 && m01 >= m12) ? c01 : (m02 >= m12 ? c02 : c12);
    na /= mag(na);

    // An orthonormal basis u, v of the plane normal to it
    const vector absN(cmptMag(na));
    const vector axis =
        (absN.x() <= absN.y() && absN.x() <= absN.z())
      ? vector(1, 0, 0)
      : (absN.y() <= absN.z() ? vector(0, 1, 0) : vector(0, 0, 1));
    vector u(na ^ axis);
    u /= mag(u);
    const vector v(na ^ u);

    // The 2 x 2 problem [a b; b d] in that plane, one Jacobi rotation
    const vector Au(A & u), Av(A & v);
    const scalar a = u & Au;
    const scalar b = u & Av;
    const scalar d = v & Av;
    scalar la = a, ld = d;
    vector e1(u), e2(v);
    if (b != 0)
    {
        const scalar tau = (d - a)/(2*b);
        const scalar t =
            (tau >= 0 ? 1 : -1)/(mag(tau) + std::sqrt(1 + tau*tau));
        const scalar c = 1/std::sqrt(1 + t*t);
        const scalar s = t*c;
        la = a - t*b;
        ld = d + t*b;
        e1 = c*u - s*v;
        e2 = s*u + c*v;
    }
    if (la < ld)
    {
        std::swap(la, ld);
        std::swap(e1, e2);
    }

    if (lowApart)
    {
        sB = vector(la, ld, lambda);
        n1 = e1;
        n2 = e2;
        n3 = na;
    }
    else
    {
        sB = vector(lambda, la, ld);
        n1 = na;
        n2 = e1;
        n3 = e2;
    }
}

} // End anonymous namespace


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
    if (coeffs_.found("tensionCutoff"))
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{

// Solve the n x n system (n <= 3) A x = b by Cramer's rule; false when A is
// singular relative to the product of its row norms (Hadamard's bound)
bool solveSmall
(
    const int n,
    const Foam::scalar A[3][3],
    const Foam::scalar b[3],
    Foam::scalar x[3]
)
{
    using Foam::scalar;

    scalar M[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    scalar r[3] = {0, 0, 0};
    scalar bound = 1;
    for (int i = 0; i < n; ++i)
    {
        scalar rowNorm2 = 0;
        for (int j = 0; j < n; ++j)
        {
            M[i][j] = A[i][j];
            rowNorm2 += A[i][j]*A[i][j];
        }
        r[i] = b[i];
        bound *= std::sqrt(rowNorm2);
    }

    auto det3 = [](const scalar m[3][3])
    {
        return
            m[0][0]*(m[1][1]*m[2][2] - m[1][2]*m[2][1])
          - m[0][1]*(m[1][0]*m[2][2] - m[1][2]*m[2][0])
          + m[0][2]*(m[1][0]*m[2][1] - m[1][1]*m[2][0]);
    };

    const scalar det = det3(M);
    if (!(std::abs(det) > 1e-10*bound))
    {
        return false;
    }

    for (int k = 0; k < n; ++k)
    {
        scalar Mk[3][3];
        for (int i = 0; i < 3; ++i)
        {
            for (int j = 0; j < 3; ++j)
            {
                Mk[i][j] = (j == k) ? r[i] : M[i][j];
            }
        }
        x[k] = det3(Mk)/det;
    }
    return true;
}

} // End anonymous namespace



Foam::constitutiveModels::MohrCoulomb::returnRegion
Foam::constitutiveModels::MohrCoulomb::returnMohrCoulomb
(
    const vector& sB,
    vector& sC
) const
{
    // Yield check on the trial stress
    const scalar fB = yieldFunction(sB);
    if (fB <= 0)
    {
        sC = sB;
        return elastic;
    }

    // Clausen et al. (2007), region tests in the order apex, line 1, plane,
    // line 2. t1, t2: positions along the lines of the line returns
    // (sigma = P + t r, t > 0 beyond the apex), from the projection of the
    // trial stress along the two flow directions of each line onto it.
    const vector s1(sB - P1_);

    if (hasApex_)
    {
        const vector& s = s1;  // P1 = P2 = apex
        const scalar t1 = (N2_ & s)/N2r1_;
        const scalar t2 = (N3_ & s)/N3r2_;
        if (t1 > 0 && t2 > 0)
        {
            sC = P1_;
            return apex;
        }
    }

    if ((nI_ & s1) < 0)
    {
        // Line 1, triaxial compression: s1 = s2
        const scalar t1 = (N2_ & s1)/N2r1_;
        sC = P1_ + t1*r1_;
        return compressionLine;
    }

    const vector s2(sB - P2_);

    if ((nII_ & s2) <= 0)
    {
        sC = sB - fB*rp_;
        return plane;
    }

    // Line 2, triaxial extension: s2 = s3
    const scalar t2 = (N3_ & s2)/N3r2_;
    sC = P2_ + t2*r2_;
    return extensionLine;
}


Foam::constitutiveModels::MohrCoulomb::returnRegion
Foam::constitutiveModels::MohrCoulomb::returnTension
(
    const vector& sB,
    const vector& sMC,
    vector& sC
) const
{
    // Multi-plane return (Clausen et al. 2006): find the active set A of at
    // most three planes with
    //     sC = sB - sum_{j in A} dl_j D b_j,  a_i.sC = c_i (i in A),
    //     dl_j >= 0, every plane satisfied, s1 >= s2 >= s3.
    // The Mohr-Coulomb return alone violated the cut-off, so a Rankine plane
    // is active. Sets with fewer planes are tried first. The Mohr-Coulomb
    // planes of the other three sectors join these only at the apex, which
    // the cut-off removes.

    const scalar scale =
        max
        (
            max(mag(sB.x()), max(mag(sB.y()), mag(sB.z()))),
            max(sigmaC_, sigmaT_)
        );
    const scalar tol = 1e-10*scale;

    for (int nActive = 1; nActive <= 3; ++nActive)
    {
        for (int set = 1; set < 64; ++set)
        {
            // At least one Rankine plane (bits 3-5)
            if (!(set & 070))
            {
                continue;
            }

            int idx[3];
            int n = 0;
            for (int i = 0; i < 6; ++i)
            {
                if (set & (1 << i))
                {
                    if (n < 3)
                    {
                        idx[n] = i;
                    }
                    ++n;
                }
            }
            if (n != nActive)
            {
                continue;
            }

            // A dl = f(sB) with A_ij = a_i.D b_j (unsymmetric when psi !=
            // phi); Cramer's rule, singular sets skipped
            scalar A[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
            scalar rhs[3] = {0, 0, 0};
            scalar dl[3] = {0, 0, 0};
            for (int i = 0; i < n; ++i)
            {
                rhs[i] = (a_[idx[i]] & sB) - c_[idx[i]];
                for (int j = 0; j < n; ++j)
                {
                    A[i][j] = a_[idx[i]] & Db_[idx[j]];
                }
            }
            if (!solveSmall(n, A, rhs, dl))
            {
                continue;
            }

            vector s(sB);
            bool ok = true;
            for (int j = 0; j < n; ++j)
            {
                const vector dS(dl[j]*Db_[idx[j]]);
                if (dl[j]*mag(Db_[idx[j]]) < -tol)
                {
                    ok = false;
                }
                s -= dS;
            }
            if (!ok || s.x() < s.y() - tol || s.y() < s.z() - tol)
            {
                continue;
            }
            for (int i = 0; i < 6 && ok; ++i)
            {
                ok = ((a_[i] & s) - c_[i] <= tol);
            }
            if (ok)
            {
                sC = s;
                return tension;
            }
        }
    }

    // Fallback, not expected: Rankine return (associated) of the admissible
    // Mohr-Coulomb state. Flowing along D e1 (and D e2) lowers every
    // Mohr-Coulomb plane function, so the result satisfies both criteria.
    const scalar Mod = lambda_ + 2*G_;
    scalar d1 = (sMC.x() - sigmaT_)/Mod;
    vector s(sigmaT_, sMC.y() - lambda_*d1, sMC.z() - lambda_*d1);
    if (s.y() > sigmaT_)
    {
        const scalar det = sqr(Mod) - sqr(lambda_);
        d1 = (Mod*(sMC.x() - sigmaT_) - lambda_*(sMC.y() - sigmaT_))/det;
        const scalar d2 =
            (Mod*(sMC.y() - sigmaT_) - lambda_*(sMC.x() - sigmaT_))/det;
        s = vector(sigmaT_, sigmaT_, sMC.z() - lambda_*(d1 + d2));
        if (s.z() > sigmaT_)
        {
            s = sigmaT_*vector::one;
        }
    }
    if (yieldFunction(s) > tol)
    {
        s = sigmaT_*vector::one;
    }
    sC = s;

    if (debug)
    {
        InfoInFunction
            << "Split return for trial " << sB << " -> " << sC << endl;
    }

    return tensionSplit;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::constitutiveModels::MohrCoulomb::returnRegion
Foam::constitutiveModels::MohrCoulomb::principalReturn
(
    const vector& sB,
    vector& sC
) const
{
    const returnRegion region = returnMohrCoulomb(sB, sC);

    if (tensionActive_ && sC.x() > sigmaT_)
    {
        const vector sMC(sC);
        return returnTension(sB, sMC, sC);
    }

    return region;
}


Foam::constitutiveModels::MohrCoulomb::returnRegion
Foam::constitutiveModels::MohrCoulomb::updateScalar
(
    const symmTensor& dStrain,
    symmTensor& stress,
    scalar& plasticStrain
) const
{
    const symmTensor trial(stress + elasticIncrement(dStrain));

    // Cheap sufficient elastic test on the invariants. With the Lode
    // angle theta in [0, pi/3] (cos 3 theta of the sign of det(dev)),
    //     s1 = p + R cos(theta),  s3 = p + R cos(theta + 2 pi/3),
    //     R = 2 sqrt(J2/3),
    //     f = (k - 1) p + R g(theta) - sigma_c,
    //     g = (k + 1/2) cos(theta) + sqrt(3)/2 sin(theta)
    //       <= sqrt(k^2 + k + 1)                         (its maximum)
    //       <= sqrt(3)/2 (k + 1)  where det(dev) < 0      (theta >= pi/6,
    // past the maximum, which lies below pi/6 for k >= 1), and
    // s1 <= p + R (sqrt(3)/2 where det(dev) < 0). Bounds raised by 1e-12
    // for round-off. Points at rest and most unloading points pass it and
    // skip the principal values
    {
        const scalar p = tr(trial)/3;
        const symmTensor s(dev(trial));
        const scalar R = 2*sqrt((s && s)/6);
        const bool pastPi6 = det(s) < 0;
        const scalar gMax =
            (1 + 1e-12)*(pastPi6 ? 0.5*sqrt(3.0)*(k_ + 1) : gMax_);
        const scalar cosMax = (1 + 1e-12)*(pastPi6 ? 0.5*sqrt(3.0) : 1);
        if
        (
            (k_ - 1)*p + gMax*R - sigmaC_ <= 0
         && (!tensionActive_ || p + cosMax*R <= sigmaT_)
        )
        {
            stress = trial;
            return elastic;
        }
    }

    // Principal values in closed form. Their error is a few ulps of the
    // stress scale where they are well apart, and grows as eps scale^2/gap
    // where two come close (the arc cosine of the closed form is
    // ill-conditioned there; Kopp 2008, Int. J. Mod. Phys. C 19:523). A
    // state inside the surface by a margin far above that error is
    // elastic: 1e-10 of the scale, widened where the values are close.
    const vector sApprox(principalValues(trial));
    const scalar scale = mag(sApprox.x()) + mag(sApprox.z()) + sigmaC_;
    const scalar gap =
        min(sApprox.x() - sApprox.y(), sApprox.y() - sApprox.z());
    {
        const scalar margin =
            1e-10*scale*(1 + 1e-5*scale/max(gap, 1e-30*scale + VSMALL));
        if
        (
            yieldFunction(sApprox) <= -margin
         && (!tensionActive_ || sApprox.x() <= sigmaT_ - margin)
        )
        {
            stress = trial;
            return elastic;
        }
    }

    // The principal values sB of the trial stress (descending), and how the
    // returned stress is rebuilt with its principal directions:
    // - well separated values (both gaps above 1e-5 of the scale): the
    //   closed-form values, and the spectral projectors of the trial stress
    //       P_i = prod_{j != i} (A - s_j I)/(s_i - s_j),
    //       sigma = A + D2 I + (D1 - D2) P1 + (D3 - D2) P3,
    //       D_i = sC_i - sB_i  (P2 = I - P1 - P3),
    //   without eigenvectors. The projectors' error is eps |A|/gap
    //   relative (below 1e-10 here), and D1 - D2, D3 - D2 stay within the
    //   gaps of an order-keeping return (checked against the QR
    //   reconstruction in Test-constitutiveModels);
    // - two values close, the third apart from them by more than 1e-3 of
    //   the scale (near a triaxial line): the third's direction from the
    //   cross products of the rows of A - s I (error eps |A|/gap), the
    //   close pair and their directions from the 2 x 2 problem in the
    //   plane normal to it by one Jacobi rotation (exactly orthonormal,
    //   values to round-off; Golub & Van Loan 2013, section 8.5);
    // - all three close (near the hydrostatic axis): Eigen's iterative
    //   (QR) decomposition.
    const bool projectors = (gap > 1e-5*scale);
    vector sB(sApprox), n1(Zero), n2(Zero), n3(Zero);
    if (!projectors)
    {
        const scalar gapApart =
            max(sApprox.x() - sApprox.y(), sApprox.y() - sApprox.z());
        if (gapApart > 1e-3*scale)
        {
            spectralOneApart(trial, sApprox, sB, n1, n2, n3);
        }
        else
        {
            Eigen::Matrix3d A;
            A <<
                trial.xx(), trial.xy(), trial.xz(),
                trial.xy(), trial.yy(), trial.yz(),
                trial.xz(), trial.yz(), trial.zz();

            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);

            if (eig.info() != Eigen::Success)
            {
                FatalErrorInFunction
                    << "No principal stresses of the trial stress " << trial
                    << " (material " << name_ << ")" << abort(FatalError);
            }

            // (ascending)
            const Eigen::Vector3d& ev = eig.eigenvalues();
            const Eigen::Matrix3d& V = eig.eigenvectors();
            sB = vector(ev(2), ev(1), ev(0));
            n1 = vector(V(0, 2), V(1, 2), V(2, 2));
            n2 = vector(V(0, 1), V(1, 1), V(2, 1));
            n3 = vector(V(0, 0), V(1, 0), V(2, 0));
        }
    }

    vector sC;
    const returnRegion region = principalReturn(sB, sC);

    if (region == elastic)
    {
        stress = trial;
        return region;
    }

    accumulatePlasticStrain(sB, sC, plasticStrain);

    if (sC.x() == sC.y() && sC.y() == sC.z())
    {
        // Apex: hydrostatic whatever the directions (exactly zero at the
        // origin)
        stress = symmTensor(sC.x(), 0, 0, sC.x(), 0, sC.x());
    }
    else if (projectors)
    {
        const scalar d1 = sC.x() - sB.x();
        const scalar d2 = sC.y() - sB.y();
        const scalar d3 = sC.z() - sB.z();
        const symmTensor A1(trial - sB.x()*symmTensor::I);
        const symmTensor A2(trial - sB.y()*symmTensor::I);
        const symmTensor A3(trial - sB.z()*symmTensor::I);
        const symmTensor P1
        (
            symm(A2 & A3)/((sB.x() - sB.y())*(sB.x() - sB.z()))
        );
        const symmTensor P3
        (
            symm(A1 & A2)/((sB.z() - sB.x())*(sB.z() - sB.y()))
        );
        stress = trial + d2*symmTensor::I + (d1 - d2)*P1 + (d3 - d2)*P3;
    }
    else
    {
        // Rotate back with the trial directions
        stress = sC.x()*sqr(n1) + sC.y()*sqr(n2) + sC.z()*sqr(n3);
    }

    return region;
}


void Foam::constitutiveModels::MohrCoulomb::accumulatePlasticStrain
(
    const vector& sB,
    const vector& sC,
    scalar& plasticStrain
) const
{
    // Equivalent deviatoric plastic strain of D^-1 (sB - sC): its
    // deviatoric part is dev(sB - sC)/(2G)
    const vector dS(sB - sC);
    const vector devDS(dS - ((dS.x() + dS.y() + dS.z())/3)*vector::one);
    plasticStrain += sqrt(2.0/3.0)*mag(devDS)/(2*G_);
}


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

} // End anonymous namespace


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

    // The trial stress of each lane: lane j < nLanes is point j, the
    // others repeat point 0 (their results are dropped)
    double4 t[6];
    {
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
        // stress + (lambda tr(dStrain)) I + 2 G dStrain, as elasticIncrement
        const double4 lambdaTr = lambda_*(e[0] + e[3] + e[5]);
        for (direction c = 0; c < 6; ++c)
        {
            t[c] =
                s[c]
              + (isDiagonal(c) ? lambdaTr + (2*G_)*e[c] : (2*G_)*e[c]);
        }
    }

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
    mask4 elastic;
    {
        const double4 R = 2.0*sqrt(p2/6.0);
        const mask4 pastPi6 = (detDev < 0.0);
        const double4 gMax =
            select
            (
                pastPi6,
                splat((1 + 1e-12)*0.5*std::sqrt(3.0)*(k_ + 1)),
                splat((1 + 1e-12)*gMax_)
            );
        elastic = ((k_ - 1)*q + gMax*R - sigmaC_ <= 0.0);
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
    }

    const mask4 none = {0, 0, 0, 0};
    mask4 fallback = none;
    mask4 plastic = none;
    double4 out[6], sC[3], dPlastic = splat(0.0);
    mask4 apexLane = none, line1Lane = none, planeLane = none;

    if (!all(elastic))
    {
        // Principal values in closed form (principalValues above, with
        // the polynomial arc cosine, sine and cosine)
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
        double4 sB[3] = {s1, select(spread, 3.0*q - s1 - s3, q), s3};

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

        // The Mohr-Coulomb return (returnMohrCoulomb), every region
        // formed and the first that holds taken: apex, line 1, plane,
        // line 2
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
        const mask4 yielding = (fB > 0.0);
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
