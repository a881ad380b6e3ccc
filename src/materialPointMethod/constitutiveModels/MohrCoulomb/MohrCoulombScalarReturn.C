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
    MohrCoulomb: the point-at-a-time return (updateScalar) with the
    library's arc cosine and a full spectral decomposition, and the
    combined return of the tension cut-off: the packed update's fallback
    and its reference in the tests.

\*---------------------------------------------------------------------------*/

// Eigen before the OpenFOAM headers (macro hygiene)
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "MohrCoulomb.H"

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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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


// updateScalar: the principal values sB of the trial stress (descending),
// and how the returned stress is rebuilt with its principal directions:
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

    // The principal values and how the stress is rebuilt: see above
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


// ************************************************************************* //
