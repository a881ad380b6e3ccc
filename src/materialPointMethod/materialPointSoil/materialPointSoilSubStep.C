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

#include "materialPointSoil.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

// The soil's sub-step: P2G, the grid's update and G2P, on the nodes the
// points reach (gridBox_, pointsBox_) and the halo's routes within them

void Foam::materialPointSoil::updateGridBox()
{
    // The points' bounding box over all processors, in global coordinates,
    // so that every processor confines the same nodes and a halo node and
    // its owner are both in or both out
    vector lo(vector::uniform(GREAT));
    vector hi(vector::uniform(-GREAT));
    for (const vector& x : points_.x)
    {
        lo = min(lo, x);
        hi = max(hi, x);
    }
    reduce(lo, minOp<vector>());
    reduce(hi, maxOp<vector>());

    nodeBox reached;
    if (lo.x() <= hi.x())
    {
        // A point reaches the nodes within reach of its nearest one; the
        // walls fold a node beyond them into an image up to ghostReach
        // further; one more for the rounding
        const scalar margin = shape_->reach() + 1 + walls_->ghostReach();
        const vector cLo(latticeCoordinates(lo));
        const vector cHi(latticeCoordinates(hi));
        const labelVector& boxN = lattice_.boxN();
        labelVector bLo(Zero), bHi(boxN);
        for (direction d = 0; d < 3; ++d)
        {
            if (lattice_.periodic()[d] || (d == 2 && lattice_.twoD()))
            {
                continue;
            }
            // (bounded as reals first: a point far off must not overflow
            // the label)
            bLo[d] = label(max(std::floor(cLo[d]) - margin, scalar(0)));
            bHi[d] = label
            (
                min(std::floor(cHi[d]) + margin + 1, scalar(boxN[d]))
            );
        }
        reached = nodeBox(bLo, bHi);
    }
    gridBox_ = nodeBox::hull(pointsBox_, reached);
    pointsBox_ = reached;
}


void Foam::materialPointSoil::sortPoints()
{
    // The points that share a cell, and those of the next cells, share
    // most of their support's nodes: in the lattice's node order (x
    // fastest) the transfers find the node records and velocities they
    // need in the cache. Points are made in that order, but a flow
    // scatters them (measured from 5.5 s of the paper's 3D case, serial:
    // 3% faster sorted; the sub-step there is 14% slower than at the start
    // for reasons the order does not explain). A stable counting
    // sort by cell, once per step (a point moves a fraction of a cell per
    // step): the same state gives the same order, so a restart repeats
    // the run exactly.
    const label n = points_.size();
    if (n < 2)
    {
        return;
    }
    labelList key(n);
    label lo = labelMax, hi = 0;
    bool sorted = true;
    for (label p = 0; p < n; ++p)
    {
        // (a point outside this processor's box is about to be refused by
        // the migration check: first in the order meanwhile)
        key[p] = max(walls_->cellNodeOf(points_.x[p]), label(0));
        lo = min(lo, key[p]);
        hi = max(hi, key[p]);
        sorted = sorted && (p == 0 || key[p] >= key[p - 1]);
    }
    if (sorted)
    {
        return;
    }
    labelList start(hi - lo + 2, Zero);
    for (const label k : key)
    {
        ++start[k - lo + 1];
    }
    for (label i = 1; i < start.size(); ++i)
    {
        start[i] += start[i - 1];
    }
    labelList order(n);
    for (label p = 0; p < n; ++p)
    {
        order[start[key[p] - lo]++] = p;
    }
    points_.reorder
    (
        order,
        travellingForces(),
        travellingStresses()
    );
}


const Foam::haloExchange::routes& Foam::materialPointSoil::haloRoutes() const
{
    if (!haloRoutesSet_ || haloBox_ != pointsBox_)
    {
        // (the box is the same on every processor, in global terms: both
        // ends of a route agree)
        haloRoutes_ = lattice_.halo().confine
        (
            [&](const label n)
            {
                return pointsBox_.contains(lattice_.boxIjk(n));
            }
        );
        haloBox_ = pointsBox_;
        haloRoutesSet_ = true;
    }
    return haloRoutes_;
}


void Foam::materialPointSoil::p2gMassMomentum(const bool withForces)
{
    updateGridBox();
    kernels_->p2g
    (
        *this,
        rampedGravity(),
        transfer_ == transferType::APIC,
        withForces
    );
}


void Foam::materialPointSoil::gridVelocityFromMomentum
(
    List<vector>& vel
) const
{
    gridBox_.forRows
    (
        lattice_.stride(),
        [&](const label begin, const label end)
        {
            for (label n = begin; n < end; ++n)
            {
                vel[n] =
                    gridMass_[n] > VSMALL
                  ? gridMomentum_[n]/gridMass_[n]
                  : Zero;
            }
        }
    );
}


void Foam::materialPointSoil::subStep(const scalar dt)
{
    if (periodic_)
    {
        checkPeriodicReach();
    }

    const bool usf = (update_ == updateType::USF);
    const bool parallel = Pstream::parRun();
    const haloExchange& halo = lattice_.halo();
    p2gMassMomentum(!usf);
    walls_->fold(gridMomentum_, gridMass_, pointsBox_);
    if (!usf)
    {
        walls_->fold(gridForce_, pointsBox_);
    }
    if (parallel)
    {
        // What the points gave the halo nodes belongs to their owners
        if (usf)
        {
            halo.addToOwners
            (
                {
                    haloExchange::field(gridMass_),
                    haloExchange::field(gridMomentum_)
                },
                haloRoutes()
            );
        }
        else
        {
            halo.addToOwners
            (
                {
                    haloExchange::field(gridMass_),
                    haloExchange::field(gridMomentum_),
                    haloExchange::field(gridForce_)
                },
                haloRoutes()
            );
        }
    }
    gridVelocityFromMomentum(gridVelocityOld_);
    if (parallel && (usf || transfer_ == transferType::FLIP))
    {
        // (read in the halo by USF's stress update and FLIP's G2P only)
        halo.copyToHalo
        (
            {haloExchange::field(gridVelocityOld_)}, haloRoutes()
        );
    }
    walls_->mirror(gridVelocityOld_, pointsBox_);

    if (usf)
    {
        kernels_->updateStresses(*this, gridVelocityOld_, dt);
        kernels_->p2gForces(*this, rampedGravity());
        walls_->fold(gridForce_, pointsBox_);
        if (parallel)
        {
            halo.addToOwners
            (
                {haloExchange::field(gridForce_)}, haloRoutes()
            );
        }
    }

    if (localDamping_ > 0)
    {
        pointsBox_.forRows
        (
            lattice_.stride(),
            [&](const label begin, const label end)
            {
                for (label n = begin; n < end; ++n)
                {
                    vector& f = gridForce_[n];
                    const vector& v = gridVelocityOld_[n];
                    for (direction d = 0; d < 3; ++d)
                    {
                        f[d] -=
                            localDamping_*mag(f[d])
                           *((v[d] > 0) - (v[d] < 0));
                    }
                }
            }
        );
    }
    if (gridExchange_)
    {
        gridExchange_->exchange(dt, gridMass_, gridVelocityOld_, gridForce_);
    }
    gridBox_.forRows
    (
        lattice_.stride(),
        [&](const label begin, const label end)
        {
            for (label n = begin; n < end; ++n)
            {
                gridVelocity_[n] =
                    gridMass_[n] > VSMALL
                  ? gridVelocityOld_[n] + dt*gridForce_[n]/gridMass_[n]
                  : Zero;
            }
        }
    );
    walls_->applyContact(gridVelocity_, gridMass_, pointsBox_);
    if (parallel)
    {
        halo.copyToHalo
        (
            {haloExchange::field(gridVelocity_)}, haloRoutes()
        );
    }
    walls_->mirror(gridVelocity_, pointsBox_);

    kernels_->g2p(*this, dt, transfer_ == transferType::FLIP);

    if (parallel)
    {
        migrate();
    }

    if (update_ == updateType::MUSL)
    {
        // The points have moved (the second mapping's weights are those of
        // the new positions)
        if (periodic_)
        {
            checkPeriodicReach();
        }
        p2gMassMomentum(false);
        walls_->fold(gridMomentum_, gridMass_, pointsBox_);
        if (parallel)
        {
            halo.addToOwners
            (
                {
                    haloExchange::field(gridMass_),
                    haloExchange::field(gridMomentum_)
                },
                haloRoutes()
            );
        }
        List<vector>& vel = gridVelocityMusl_;
        vel.setSize(gridVelocity_.size(), Zero);
        gridVelocityFromMomentum(vel);
        walls_->applyContact(vel, gridMass_, pointsBox_);
        if (parallel)
        {
            halo.copyToHalo({haloExchange::field(vel)}, haloRoutes());
        }
        walls_->mirror(vel, pointsBox_);
        kernels_->updateStresses(*this, vel, dt);
    }
}


// ************************************************************************* //
