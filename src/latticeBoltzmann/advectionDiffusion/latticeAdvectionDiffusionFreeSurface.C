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

// The scalar below a free surface: it follows the surface's conversions and
// crosses the links that touch interface nodes by their fill levels

#include "latticeAdvectionDiffusion.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeAdvectionDiffusion::followSurface()
{
    if (!surface_ || !initialised_)
    {
        return;
    }
    const label nBox = lattice_.nBox();
    const scalar w0 = w0_;
    const scalar wi = 0.5*cs2_;
    scalarList& g = current();

    // Nodes the water reached start empty; nodes it left give their
    // scalar, in equal shares, to their water neighbours (the fluid's
    // conversion leaves every emptied node at least one: an interface
    // neighbour, or a liquid one that turns interface)
    givers_.clear();
    for (const label n : lattice_.cellNode())
    {
        const bool now = surface_->water(n);
        if (now == wasWater_[n])
        {
            continue;
        }
        if (!now)
        {
            scalar held = 0;
            for (label q = 0; q < Q_; ++q)
            {
                held += g[q*nBox + n];
            }
            label nWater = 0;
            for (const label o : neighbours_)
            {
                nWater += surface_->water(n + o);
            }
            if (held != 0)
            {
                if (nWater)
                {
                    share_[n] = held/nWater;
                    givers_.append(n);
                }
                else
                {
                    stranded_ += held*lattice_.cellVolume();
                }
            }
        }
        // (both lattices: the other holds this node's older populations,
        // which a restart would not have)
        scalarList& other = AisCurrent_ ? gB_ : gA_;
        for (label q = 0; q < Q_; ++q)
        {
            g[q*nBox + n] = 0;
            other[q*nBox + n] = 0;
        }
        wasWater_[n] = now;
    }
    lattice_.halo().exchange(share_.data(), 1, nBox);

    // Each owned water node takes the shares of its neighbours that gave
    // (owned, or another processor's through the halo), as a source: the
    // lattice weights
    const List<unsigned char>& kind = lattice_.kind();
    auto give = [&](const label x)
    {
        const scalar s = share_[x];
        for (const label o : neighbours_)
        {
            const label y = x + o;
            if
            (
                y >= 0 && y < nBox && kind[y] == latticeMesh::OWNED
             && surface_->water(y)
            )
            {
                g[y] += w0*s;
                for (label q = 1; q < Q_; ++q)
                {
                    g[q*nBox + y] += wi*s;
                }
            }
        }
    };
    for (const label x : givers_)
    {
        give(x);
    }
    for (const label x : haloNodes_)
    {
        if (share_[x] != 0)
        {
            give(x);
            share_[x] = 0;
        }
    }
    for (const label x : givers_)
    {
        share_[x] = 0;
    }
}


void Foam::latticeAdvectionDiffusion::surfaceLinks(scalar* g) const
{
    // The links that touch an interface node. A packet p_sr that node s
    // sends towards r crosses by the fraction min(phi_s, phi_r)/phi_s of
    // its fill level (the wet part of the face between them) and the rest
    // returns to s: each packet crosses or returns, so the content is
    // conserved and no population turns negative, and as
    // phi_s a_sr = min(phi_s, phi_r) = phi_r a_rs, a uniform
    // concentration C = Phi/(n phi) exchanges nothing (detailed balance:
    // a full node and a half-full one at the same C). Towards the gas
    // (phi 0) everything returns: the surface closes the scalar in.
    const label nBox = lattice_.nBox();
    const List<unsigned char>& kind = lattice_.kind();
    auto level = [this](const label n)
    {
        return max(surface_->fill(n), scalar(1e-6));
    };

    // x receives along q from y = x - c_q: the slot g[q, y]; y receives
    // along -q from x: the slot g[-q, x]
    auto exchange = [&](const label x, const label y, const label q)
    {
        const label qb = oppositeOf(q);
        scalar& sx = g[q*nBox + y];
        scalar& sy = g[qb*nBox + x];
        const scalar pyx = sx;
        const scalar pxy = sy;
        const scalar fx = level(x);
        const scalar fy = level(y);
        const scalar m = min(fx, fy);
        const scalar ayx = m/fy;
        const scalar axy = m/fx;
        sx = ayx*pyx + (1 - axy)*pxy;
        sy = axy*pxy + (1 - ayx)*pyx;
    };

    for (const label x : surface_->interfaceNodes())
    {
        for (label q = 1; q < Q_; ++q)
        {
            const label y = x - offset_[q];
            if (surface_->gasNode(y))
            {
                g[q*nBox + y] = g[oppositeOf(q)*nBox + x];
            }
            else if
            (
                surface_->water(y)
             && !(kind[y] == latticeMesh::OWNED && surface_->interface(y)
                  && y < x)
            )
            {
                exchange(x, y, q);
            }
        }
    }
    // (another processor's interface nodes next to this one's liquid)
    for (const label h : haloNodes_)
    {
        if (!(surface_->water(h) && surface_->fill(h) < 1))
        {
            continue;
        }
        for (label q = 1; q < Q_; ++q)
        {
            const label y = h - offset_[q];
            if
            (
                y >= 0 && y < nBox && kind[y] == latticeMesh::OWNED
             && surface_->liquid(y)
            )
            {
                exchange(h, y, q);
            }
        }
    }
}


// ************************************************************************* //
