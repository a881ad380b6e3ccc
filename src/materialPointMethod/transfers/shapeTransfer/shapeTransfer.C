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

#include "shapeTransfer.H"
#include "transferKernels.H"

#include <algorithm>
#include <type_traits>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Shape>
template<class Kernel>
inline void Foam::shapeTransfer<Shape>::withDimension
(
    const materialPointSoil& soil,
    Kernel&& k
)
{
    if (soil.lattice_.nDim() == 3)
    {
        k(std::integral_constant<label, 3>());
    }
    else
    {
        k(std::integral_constant<label, 2>());
    }
}


template<class Shape>
inline bool Foam::shapeTransfer<Shape>::hasLoads
(
    const materialPointSoil& soil
)
{
    return soil.pointForce_.size() || soil.pointStress_.size();
}


template<class Shape>
template<bool Loads>
inline void Foam::shapeTransfer<Shape>::pointLoads
(
    const materialPointSoil& soil,
    const label p,
    const vector& g,
    vector& mg,
    symmTensor& sigma
)
{
    mg = soil.points_.m[p]*g;
    sigma = soil.points_.sigma[p];
    // (a template flag, so that a scene without loads tests nothing per
    // point)
    if constexpr (Loads)
    {
        if (soil.pointForce_.size())
        {
            mg += soil.pointForce_[p];
        }
        if (soil.pointStress_.size())
        {
            sigma += soil.pointStress_[p];
        }
    }
}


template<class Shape>
template<Foam::label D>
inline void Foam::shapeTransfer<Shape>::pointWeights
(
    const materialPointSoil& soil,
    const label p,
    const vector& xl,
    shapeWeights& sw
)
{
    tensorProductWeights<Shape, D>
    (
        xl,
        Shape::usesHalfLength ? soil.points_.halfLength[p] : vector::zero,
        sw
    );
}


template<class Shape>
template<Foam::label D, bool Apic, bool Forces, bool Loads>
void Foam::shapeTransfer<Shape>::p2gPoints
(
    materialPointSoil& soil,
    const vector& g
)
{
    using namespace transferKernels;
    // (the sums and their factors A_a, R, B_a: see shapeTransfer.H)
    constexpr label S = Shape::supportSize;
    constexpr label SZ = (D == 3 ? S : 1);
    constexpr label W = (Forces ? 8 : 4);
    const scalar dx = soil.lattice_.dx();
    const scalar invDx = 1.0/dx;
    const label sy = soil.lattice_.stride().y();
    const label sz = soil.lattice_.stride().z();
    // (Loads: some points carry a force or a stress of their own: see
    // pointLoads)
    const label nBox = soil.gridMass_.size();

    // (sized once for 8 values per node, whatever W: MUSL maps with and
    // without forces in one sub-step)
    // (cleared, and copied to the grid below, in the nodes of gridBox_
    // only: the points reach no other, and the grid is zero outside it)
    soil.p2gScratch_.setSize(8*nBox + 8);
    scalar* __restrict__ rec = cacheLineAligned(soil.p2gScratch_.data());
    soil.gridBox_.forRows
    (
        soil.lattice_.stride(),
        [&](const label begin, const label end)
        {
            std::fill(rec + W*begin, rec + W*end, 0.0);
        }
    );

    const label nPoints = soil.points_.size();
    for (label p = 0; p < nPoints; ++p)
    {
        const vector xl(soil.latticeCoordinates(soil.points_.x[p]));
        shapeWeights sw;
        pointWeights<D>(soil, p, xl, sw);
        const scalar mp = soil.points_.m[p];
        const vector mv(mp*soil.points_.v[p]);
        const scalar* wx = sw.w[0];
        const scalar* dwx = sw.dw[0];

        v4d Alo[S];
        v8d A8[S], B8[S];
        tensor mCdx(Zero);
        scalar ry[S], rz[SZ];
        if constexpr (Apic)
        {
            mCdx = (mp*dx)*soil.points_.C[p];
            const vector cx(column(mCdx, 0));
            for (label a = 0; a < S; ++a)
            {
                const vector momA(mv + cx*(sw.first.x() + a - xl.x()));
                Alo[a] = v4(mp, momA.x(), momA.y(), momA.z());
                ry[a] = sw.first.y() + a - xl.y();
            }
            for (label c = 0; c < SZ; ++c)
            {
                rz[c] = sw.first.z() + c - xl.z();
            }
        }
        else
        {
            for (label a = 0; a < S; ++a)
            {
                Alo[a] = v4(mp, mv.x(), mv.y(), mv.z());
            }
        }

        vector By(Zero), Bz(Zero);
        if constexpr (Forces)
        {
            vector mg;
            symmTensor sigma;
            pointLoads<Loads>(soil, p, g, mg, sigma);
            const symmTensor Bs(-(soil.points_.V[p]*invDx)*sigma);
            By = vector(Bs.xy(), Bs.yy(), Bs.yz());
            Bz = vector(Bs.xz(), Bs.yz(), Bs.zz());
            for (label a = 0; a < S; ++a)
            {
                A8[a] = v8(Alo[a], v4(mg.x(), mg.y(), mg.z(), 0));
                B8[a] = v8
                (
                    v4(0, 0, 0, 0),
                    v4(Bs.xx(), Bs.xy(), Bs.xz(), 0)*dwx[a]
                );
            }
        }

        const label base =
            soil.lattice_.node(sw.first.x(), sw.first.y(), sw.first.z());
        for (label c = 0; c < SZ; ++c)
        {
            const scalar wz = sw.w[2][c];
            const scalar dwz = sw.dw[2][c];
            for (label b = 0; b < S; ++b)
            {
                const scalar wy = sw.w[1][b];
                const scalar wyz = wy*wz;
                const label row = base + b*sy + c*sz;

                v4d Rlo = v4(0, 0, 0, 0);
                if constexpr (Apic)
                {
                    const vector momRow
                    (
                        wyz
                       *(
                            column(mCdx, 1)*ry[b]
                          + (D == 3 ? column(mCdx, 2)*rz[c] : vector::zero)
                        )
                    );
                    Rlo = v4(0, momRow.x(), momRow.y(), momRow.z());
                }
                v4d Rhi = v4(0, 0, 0, 0);
                if constexpr (Forces)
                {
                    vector forceRow(By*(sw.dw[1][b]*wz));
                    if constexpr (D == 3)
                    {
                        forceRow += Bz*(wy*dwz);
                    }
                    Rhi = v4(forceRow.x(), forceRow.y(), forceRow.z(), 0);
                }

                scalar* __restrict__ r = rec + W*row;
                if constexpr (Forces)
                {
                    // The whole record at once: (A_a, B_a) as eight values
                    // (B_a's lower half zero)
                    const v8d R = v8(Rlo, Rhi);
                    if constexpr (Apic)
                    {
                        for (label a = 0; a < S; ++a)
                        {
                            v8d* node = reinterpret_cast<v8d*>(r + W*a);
                            *node += wx[a]*(wyz*A8[a] + R) + wyz*B8[a];
                        }
                    }
                    else
                    {
                        // A_a is the same for every a without APIC: its
                        // row term once per row, two operations per node
                        // (the same sums, operation for operation)
                        const v8d T = wyz*A8[0] + R;
                        for (label a = 0; a < S; ++a)
                        {
                            v8d* node = reinterpret_cast<v8d*>(r + W*a);
                            *node += wx[a]*T + wyz*B8[a];
                        }
                    }
                }
                else if constexpr (Apic)
                {
                    for (label a = 0; a < S; ++a)
                    {
                        v4d* lo = reinterpret_cast<v4d*>(r + W*a);
                        *lo += wx[a]*(wyz*Alo[a] + Rlo);
                    }
                }
                else
                {
                    const v4d T = wyz*Alo[0] + Rlo;
                    for (label a = 0; a < S; ++a)
                    {
                        v4d* lo = reinterpret_cast<v4d*>(r + W*a);
                        *lo += wx[a]*T;
                    }
                }
            }
        }
    }

    recordsToGrid<Forces>
    (
        rec, soil.gridMass_, soil.gridMomentum_, soil.gridForce_,
        soil.gridBox_, soil.lattice_.stride()
    );
}


template<class Shape>
template<Foam::label D, bool Loads>
void Foam::shapeTransfer<Shape>::p2gForcePoints
(
    materialPointSoil& soil,
    const vector& g
)
{
    using namespace transferKernels;
    // The force part of p2gPoints (USF: after the stress update)
    constexpr label S = Shape::supportSize;
    constexpr label SZ = (D == 3 ? S : 1);
    const scalar invDx = 1.0/soil.lattice_.dx();
    const label sy = soil.lattice_.stride().y();
    const label sz = soil.lattice_.stride().z();
    // (Loads: some points carry a force or a stress of their own: see
    // pointLoads)
    vector* __restrict__ force = soil.gridForce_.data();

    const label nPoints = soil.points_.size();
    for (label p = 0; p < nPoints; ++p)
    {
        shapeWeights sw;
        pointWeights<D>
        (
            soil, p, soil.latticeCoordinates(soil.points_.x[p]), sw
        );
        vector mg;
        symmTensor sigma;
        pointLoads<Loads>(soil, p, g, mg, sigma);
        const symmTensor B(-(soil.points_.V[p]*invDx)*sigma);
        const vector Bx(B.xx(), B.xy(), B.xz());
        const vector By(B.xy(), B.yy(), B.yz());
        const vector Bz(B.xz(), B.yz(), B.zz());
        const scalar* wx = sw.w[0];
        vector forceA[S];
        for (label a = 0; a < S; ++a)
        {
            forceA[a] = Bx*sw.dw[0][a];
        }
        const label base =
            soil.lattice_.node(sw.first.x(), sw.first.y(), sw.first.z());
        for (label c = 0; c < SZ; ++c)
        {
            const scalar wz = sw.w[2][c];
            const scalar dwz = sw.dw[2][c];
            for (label b = 0; b < S; ++b)
            {
                const scalar wy = sw.w[1][b];
                const scalar wyz = wy*wz;
                vector forceRow(By*(sw.dw[1][b]*wz));
                if constexpr (D == 3)
                {
                    forceRow += Bz*(wy*dwz);
                }
                const label row = base + b*sy + c*sz;
                for (label a = 0; a < S; ++a)
                {
                    force[row + a] +=
                        (wx[a]*wyz)*mg + wyz*forceA[a] + wx[a]*forceRow;
                }
            }
        }
    }
}


template<class Shape>
template<Foam::label D, bool Flip>
void Foam::shapeTransfer<Shape>::g2pPoints
(
    materialPointSoil& soil,
    const scalar dt
)
{
    using namespace transferKernels;
    // Per point: v = sum N v_n, L = sum v_n gradN/dx (and FLIP's
    // sum N (v_n - v_n,old)), from supportSums; in blocks of pointBlock
    // points, each followed by its constitutive update (USL)
    constexpr label S = Shape::supportSize;
    const scalar invDx = 1.0/soil.lattice_.dx();
    const bool stressHere =
        (soil.update_ == materialPointSoil::updateType::USL);
    const bool apic =
        (soil.transfer_ == materialPointSoil::transferType::APIC);
    const bool parallel = Pstream::parRun();
    const scalar alpha = soil.flipShare(dt);
    const labelVector& stride = soil.lattice_.stride();
    const double* vel =
        Flip
      ? padVelocityPairs
        (
            soil.gridVelocity_, soil.gridVelocityOld_, soil.velocityPairs_,
            soil.pointsBox_, stride
        )
      : padVelocities
        (
            soil.gridVelocity_, soil.velocity4_, soil.pointsBox_, stride
        );
    symmTensor* dStrain = soil.strainIncrement_.data();
    soil.leavingPoint_.clear();
    soil.leavingProc_.clear();

    const label nPoints = soil.points_.size();
    for (label start = 0; start < nPoints; start += pointBlock)
    {
        const label end = min(start + pointBlock, nPoints);
        for (label p = start; p < end; ++p)
        {
            shapeWeights sw;
            pointWeights<D>
            (
                soil, p, soil.latticeCoordinates(soil.points_.x[p]), sw
            );
            vector vPic, dv(Zero);
            const tensor L
            (
                velocityGradient<S, D, Flip>
                (
                    sw, soil.lattice_, invDx, vel, vPic, dv
                )
            );

            if constexpr (Flip)
            {
                soil.points_.v[p] =
                    alpha*(soil.points_.v[p] + dv) + (1 - alpha)*vPic;
            }
            else
            {
                soil.points_.v[p] = vPic;
                if (apic)
                {
                    soil.points_.C[p] = L;
                }
            }

            if (stressHere)
            {
                soil.updatePointStress(p, L, dt, dStrain[p - start]);
            }

            const vector xOld(soil.points_.x[p]);
            soil.points_.x[p] += dt*vPic;
            if (soil.walls_->clamp(soil.points_.x[p], xOld))
            {
                if (soil.nClamped_++ == 0)
                {
                    soil.firstClamped_ = soil.points_.id[p];
                    soil.firstClampedAt_ = soil.points_.x[p];
                    soil.firstClampedSpeed_ = mag(vPic);
                }
            }
            if (parallel)
            {
                soil.noteLeaving(p);
            }
        }

        if (stressHere)
        {
            soil.updateConstitutive(start, end);
        }
    }
}


template<class Shape>
template<Foam::label D>
void Foam::shapeTransfer<Shape>::stressPoints
(
    materialPointSoil& soil,
    const List<vector>& vel,
    const scalar dt
)
{
    using namespace transferKernels;
    constexpr label S = Shape::supportSize;
    const scalar invDx = 1.0/soil.lattice_.dx();
    const double* vel4 = padVelocities
    (
        vel, soil.velocity4_, soil.pointsBox_, soil.lattice_.stride()
    );
    symmTensor* dStrain = soil.strainIncrement_.data();
    const label nPoints = soil.points_.size();
    for (label start = 0; start < nPoints; start += pointBlock)
    {
        const label end = min(start + pointBlock, nPoints);
        for (label p = start; p < end; ++p)
        {
            shapeWeights sw;
            pointWeights<D>
            (
                soil, p, soil.latticeCoordinates(soil.points_.x[p]), sw
            );
            vector vPic, dv(Zero);
            soil.updatePointStress
            (
                p,
                velocityGradient<S, D, false>
                (
                    sw, soil.lattice_, invDx, vel4, vPic, dv
                ),
                dt,
                dStrain[p - start]
            );
        }
        soil.updateConstitutive(start, end);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Shape>
void Foam::shapeTransfer<Shape>::p2g
(
    materialPointSoil& soil,
    const vector& g,
    const bool apic,
    const bool withForces
) const
{
    withDimension
    (
        soil,
        [&](auto D)
        {
            constexpr label d = decltype(D)::value;
            const bool loads = withForces && hasLoads(soil);
            if (apic && loads)
            {
                p2gPoints<d, true, true, true>(soil, g);
            }
            else if (apic && withForces)
            {
                p2gPoints<d, true, true, false>(soil, g);
            }
            else if (apic)
            {
                p2gPoints<d, true, false, false>(soil, g);
            }
            else if (loads)
            {
                p2gPoints<d, false, true, true>(soil, g);
            }
            else if (withForces)
            {
                p2gPoints<d, false, true, false>(soil, g);
            }
            else
            {
                p2gPoints<d, false, false, false>(soil, g);
            }
        }
    );
}


template<class Shape>
void Foam::shapeTransfer<Shape>::p2gForces
(
    materialPointSoil& soil,
    const vector& g
) const
{
    withDimension
    (
        soil,
        [&](auto D)
        {
            constexpr label d = decltype(D)::value;
            if (hasLoads(soil)) { p2gForcePoints<d, true>(soil, g); }
            else                { p2gForcePoints<d, false>(soil, g); }
        }
    );
}


template<class Shape>
void Foam::shapeTransfer<Shape>::g2p
(
    materialPointSoil& soil,
    const scalar dt,
    const bool flip
) const
{
    withDimension
    (
        soil,
        [&](auto D)
        {
            constexpr label d = decltype(D)::value;
            if (flip) { g2pPoints<d, true>(soil, dt); }
            else      { g2pPoints<d, false>(soil, dt); }
        }
    );
}


template<class Shape>
void Foam::shapeTransfer<Shape>::updateStresses
(
    materialPointSoil& soil,
    const List<vector>& vel,
    const scalar dt
) const
{
    withDimension
    (
        soil,
        [&](auto D) { stressPoints<decltype(D)::value>(soil, vel, dt); }
    );
}


// ************************************************************************* //
