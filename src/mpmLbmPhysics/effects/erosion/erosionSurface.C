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
    erosion: the soil's surface eroded by the water's shear (a surface law:
    excessShearStress, Shields).

    The surface. A water node n (owned, nodal solid fraction phi_n below
    surfaceSolidFraction phi_s) is on the surface when a neighbour inward
    along an axis d, n - sign(m_d) e_d, is at or above phi_s, m the
    outward normal -grad(phi)/|grad(phi)|; e is the nearest such axis to
    m. The surface lies between n and n - e, delta = (phi_s - phi_n)/
    (phi_(n-e) - phi_n) cells from n.

    The wall shear stress. The water's viscous stress sigma (the lattice's
    own non-equilibrium moment, latticeBoltzmannFluid::viscousStress) gives
    the tangential traction t = sigma.m - (m.sigma.m) m, m the normal, at
    up to four nodes along e clear of soil (phi < phi_s/20), from n,
    n + e or n + 2e on, within four nodes of n. In the water beside a wall
    the traction is linear along the normal (the momentum balance of a
    slab of a fully developed flow: d tau/dn = dp/ds), so the least-squares
    line through them is taken to the surface. Beside a pressure patch the
    stress is the next node inward's (the boundary's extrapolated
    populations are not the flow's). (The nodes inside the diffuse surface
    feel the porous drag, whose momentum sink bends the profile: they are
    skipped. The non-equilibrium stress also has an odd-even ripple of
    about 1% along a wall's normal: the fit over four nodes averages it.)

    The eroded mass. Each surface node erodes the law's rate times its
    share of the surface's area, dx^(D-1) sum |m_d| over the axes d it
    crosses the surface along (see surfaceDemand), in the step's time (a
    surface node no point reaches, with a low surfaceSolidFraction, hands
    it to its neighbour inward). The mass
    is taken from the points in the node's support in proportion to their
    weight there (the outer points go first; a weight on a node beyond a
    wall counts for the node it folds into, as the soil's own transfers
    do); a point asked for more than it has gives all and goes, the others
    at its nodes giving the rest. (Shares in proportion to weight x mass
    would shrink a point geometrically, never to nothing: removed at a
    threshold, its remainder, many steps' demand, overshot the law by 3-8%
    on the hole erosion test.) The soil leaves whole, grains and pores at
    the point's dry density: the point shrinks (its mass, volume and
    initial volume by the same factor) and keeps its porosity, stress and
    wave speed. (Were its grains taken and its volume kept, a point near
    empty would still carry its stress on next to no mass: its wave speed,
    and the soil's stable step with it, would run away.) A point left with
    less than minVolumeFraction of the largest point's initial volume is
    removed and its mass given to the water.

    Bonelli & Brivois (2008), Int. J. Numer. Anal. Meth. Geomech. 32,
    1573-1595: the surface's normal velocity is m_dot/rho_d, m_dot the
    eroded mass per area and time, rho_d the soil's dry density.

\*---------------------------------------------------------------------------*/

#include "erosionEffect.H"
#include "physicsScene.H"
#include "soilEffect.H"
#include "materialPointSoil.H"
#include "shapeFunction.H"
#include "soilWalls.H"
#include "nodeFieldIO.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::erosion::findOpenNodes()
{
    const latticeMesh& lattice = fluid_.lattice();
    const List<unsigned char>& kind = lattice.kind();
    const label stride[3] =
        {1, lattice.stride().y(), lattice.stride().z()};
    const labelList nodes(fluid_.boundaries().pressureNodes());

    DynamicList<label> open(nodes.size());
    DynamicList<label> inward(nodes.size());
    for (const label n : nodes)
    {
        // The axis along which the node has the outside on one side and
        // the lattice on the other
        for (label d = 0; d < lattice.nDim(); ++d)
        {
            label found = -1;
            for (const label s : {-1, 1})
            {
                const label out = n + s*stride[d];
                const label in = n - s*stride[d];
                if
                (
                    out >= 0 && out < kind.size() && in >= 0
                 && in < kind.size() && kind[out] == latticeMesh::WALL
                 && kind[in] != latticeMesh::WALL
                 && kind[in] != latticeMesh::UNUSED
                )
                {
                    found = in;
                }
            }
            if (found >= 0)
            {
                open.append(n);
                inward.append(found);
                break;
            }
        }
    }
    openNodes_.transfer(open);
    openInward_.transfer(inward);
    anyOpen_ = returnReduce(openNodes_.size() > 0, orOp<bool>());
}


void Foam::physicsEffects::erosion::surfaceDemand()
{
    const latticeMesh& lattice = fluid_.lattice();
    const haloExchange& halo = lattice.halo();
    const List<unsigned char>& kind = lattice.kind();
    const label nDim = lattice.nDim();
    const label stride[3] =
        {1, lattice.stride().y(), lattice.stride().z()};

    phi_ = soil_.solidFraction();
    fluid_.viscousStress(sigma_);
    halo.copyToHalo({haloExchange::field(phi_), haloExchange::field(sigma_)});

    // The populations of a node beside a pressure patch are the boundary
    // scheme's (Guo, Zheng & Shi's extrapolation), and so is their
    // non-equilibrium stress: beside the slot's ends of the hole erosion
    // test it read 22-37% low, the ends lagged and narrowed the slot. The
    // flow's own stress there is that of the next node inward (zero
    // gradient along the patch's normal, as the boundary assumes)
    if (anyOpen_)
    {
        forAll(openNodes_, i)
        {
            sigma_[openNodes_[i]] = sigma_[openInward_[i]];
        }
        halo.copyToHalo({haloExchange::field(sigma_)});
    }

    auto inside = [&](const label n)
    {
        return
            n >= 0 && n < kind.size()
         && (
                kind[n] == latticeMesh::OWNED
             || kind[n] == latticeMesh::HALO
            );
    };

    const scalar phiS = surfaceSolidFraction_;
    const scalar phiClear = 0.05*phiS;
    const label nFit = 4;
    const label reach = haloWidth(scene_.mesh());
    const scalar dt = scene_.mesh().time().deltaTValue();
    const scalar columnArea = lattice.cellVolume()/lattice.dx();

    wallShear_ = Zero;
    demand_ = 0;
    handOff_ = 0;
    // The mass node k's pore water can still take
    auto room = [&](const label k)
    {
        return
            (
                maxConcentration_*max(1 - phi_[k], scalar(0.01))*wetFraction(k)
              - Phi(k)
            )*lattice.cellVolume();
    };
    // (with a free surface: only where there is water; a dry surface is
    // not eroded, and the gas's nodes carry no stress)
    auto wet = [this](const label a)
    {
        return !surface_ || surface_->water(a);
    };
    for (const label n : lattice.cellNode())
    {
        if (!(phi_[n] < phiS) || !wet(n))
        {
            continue;
        }

        // The outward normal from the solid fraction's gradient (a
        // one-sided difference beside the domain's edge)
        vector grad(Zero);
        for (label d = 0; d < nDim; ++d)
        {
            const label up = n + stride[d];
            const label down = n - stride[d];
            const scalar pUp = inside(up) ? phi_[up] : phi_[n];
            const scalar pDown = inside(down) ? phi_[down] : phi_[n];
            grad[d] = 0.5*(pUp - pDown);
        }
        const scalar magGrad = mag(grad);
        if (!(magGrad > SMALL))
        {
            continue;
        }
        const vector normal = -grad/magGrad;

        // The axes along which the level lies between n and its neighbour
        // inward, and the surface's area they stand for: each such
        // crossing along axis d stands for a face dx^(D-1) of the
        // surface's projection on the plane normal to d, an area
        // dx^(D-1)/|m_d| of the surface (D the lattice's dimensions); with
        // the axes weighted by m_d^2 (their sum is 1) a crossing along d
        // counts dx^(D-1) |m_d|, and
        // the area is right on average for any orientation, a node where
        // the level crosses along two axes (a staircase's corner)
        // counting both. (Counted along the axis nearest the normal alone,
        // dx^(d-1)/|m.e|, the level's crossings along the other axis near
        // 45 degrees were nobody's: a quarter of a pipe 4 cells in radius
        // had 11.2 mm of its 12.8 mm of wall, and eroded 12% slow.) The
        // stress is fitted along the crossing axis nearest the normal
        label axis = -1;
        scalar areaFactor = 0;
        for (label d = 0; d < nDim; ++d)
        {
            if (normal[d] == 0)
            {
                continue;
            }
            const label in = n - (normal[d] > 0 ? stride[d] : -stride[d]);
            if (inside(in) && phi_[in] >= phiS)
            {
                areaFactor += mag(normal[d]);
                if (axis < 0 || mag(normal[d]) > mag(normal[axis]))
                {
                    axis = d;
                }
            }
        }
        if (axis < 0)
        {
            continue;
        }
        const label step = normal[axis] > 0 ? stride[axis] : -stride[axis];
        const label in = n - step;
        const scalar delta = (phiS - phi_[n])/(phi_[in] - phi_[n]);

        // The water nodes outward clear of the soil: the first, k0 <= 2
        // nodes out, and up to three more within the halo's reach
        auto traction = [&](const label a)
        {
            const vector t = sigma_[a] & normal;
            return vector(t - (normal & t)*normal);
        };
        label k0 = -1;
        for (label k = 0; k <= 2 && k0 < 0; ++k)
        {
            const label a = n + k*step;
            if (!inside(a) || !wet(a))
            {
                break;
            }
            if (phi_[a] < phiClear)
            {
                k0 = k;
            }
        }
        if (k0 < 0)
        {
            // Not clear within reach (a narrow gap): the surface node
            k0 = 0;
        }

        // The least-squares line through them (the non-equilibrium stress
        // carries an odd-even ripple of about 1% along a wall's normal:
        // four nodes average it out), at the surface
        label m = 0;
        scalar sx = 0, sxx = 0;
        vector st(Zero), sxt(Zero);
        for (label k = k0; k < k0 + nFit && k <= reach; ++k)
        {
            const label a = n + k*step;
            if
            (
                !inside(a) || !wet(a)
             || (k > k0 && !(phi_[a] < phiClear))
            )
            {
                break;
            }
            const vector t = traction(a);
            ++m;
            sx += k;
            sxx += k*k;
            st += t;
            sxt += k*t;
        }
        vector tw = traction(n);
        if (m >= 2)
        {
            const scalar det = m*sxx - sx*sx;
            const vector slope = (m*sxt - sx*st)/det;
            const vector intercept = (st - slope*sx)/m;
            tw = intercept - delta*slope;
        }
        wallShear_[n] = tw;

        // The node whose points give the mass: the surface node, or, where
        // no point reaches it (a surfaceSolidFraction below the solid
        // fraction of the soil's outermost nodes: the water node beyond
        // them has none, and with its demand there nothing eroded), its
        // neighbour inward, whose points are the soil's surface
        const label giver = phi_[n] > 0 ? n : in;

        // At most what that node's pore water can still carry (a demand
        // handed inward: capped where its node's owner has them all)
        const scalar rate = law_->surfaceRate(mag(tw));
        if (rate > 0)
        {
            const scalar ask = rate*columnArea*areaFactor*dt;
            if (giver == n)
            {
                demand_[n] = max(min(ask, room(n)), scalar(0));
            }
            else
            {
                handOff_[giver] += ask;
            }
        }
    }

    // (a node handed a demand may be a halo node: to its owner, where the
    // pore water's room is known; a giver is never a surface node, its
    // solid fraction being at or above the level)
    halo.addToOwners({haloExchange::field(handOff_)});
    for (const label k : lattice.cellNode())
    {
        if (handOff_[k] > 0)
        {
            demand_[k] += max(min(handOff_[k], room(k)), scalar(0));
        }
    }
}


void Foam::physicsEffects::erosion::erodeSurface()
{
    surfaceDemand();

    bool any = false;
    for (const label n : fluid_.lattice().cellNode())
    {
        if (demand_[n] > 0)
        {
            any = true;
            break;
        }
    }
    for (scalarList& source : sources_)
    {
        source = 0;
    }
    if (!returnReduce(any, orOp<bool>()))
    {
        return;
    }

    const latticeMesh& lattice = fluid_.lattice();
    const haloExchange& halo = lattice.halo();
    const bool parallel = Pstream::parRun();
    materialPointSoil& mpm = soil_.mpm();
    materialPoints& pts = mpm.points();
    const soilWalls& walls = mpm.walls();
    const scalar Vcell = lattice.cellVolume();

    // The demand where the points see it (their supports reach the halo)
    halo.copyToHalo({haloExchange::field(demand_)});

    // f(node, N) for each node of the weights sw that has a demand (a
    // node beyond a wall counts as the one it folds into)
    auto forDemandNodes = [&](const shapeWeights& sw, auto&& f)
    {
        sw.forEachNode
        (
            [&](label i, label j, label k, scalar N, const vector&)
            {
                const label node = walls.image(lattice.node(i, j, k));
                if (demand_[node] > 0)
                {
                    f(node, N);
                }
            }
        );
    };

    // Each surface node's sum of the weights of the points it takes from
    weightSum_ = 0;
    shapeWeights sw;
    forAll(pts.x, p)
    {
        mpm.nodeWeights(p, sw);
        forDemandNodes(sw, [&](label node, scalar N){ weightSum_[node] += N; });
    }
    if (parallel)
    {
        halo.addToOwners({haloExchange::field(weightSum_)});
    }
    halo.copyToHalo({haloExchange::field(weightSum_)});

    // A point's share of the nodes' demands, f(node, share) for each node
    // it gives to
    auto forEachShare = [&](const label p, auto&& f)
    {
        mpm.nodeWeights(p, sw);
        forDemandNodes
        (
            sw,
            [&](label node, scalar N)
            {
                if (weightSum_[node] > 0)
                {
                    f(node, N/weightSum_[node]);
                }
            }
        );
    };

    // The points the demand empties: those it asks for all they have (or
    // all but less than the removal volume). Their shortfall is asked of
    // the other points at their nodes (the law's rate stays exact).
    // emptiedMass_: the emptied points' mass per node, in the proportions
    // they were asked; emptiedWeight_: their weights. Their mass enters
    // the water at once.
    emptiedMass_ = 0;
    emptiedWeight_ = 0;
    List<bool> emptied(max(pts.size(), label(0)), false);
    DynamicList<label> gone;
    forAll(pts.x, p)
    {
        scalar asked = 0;
        forEachShare(p, [&](label node, scalar w){ asked += demand_[node]*w; });
        const scalar m = pts.m[p];
        if (!(asked > 0) || (m - min(asked, m))/m*pts.V0[p] >= removeVolume_)
        {
            continue;
        }
        emptied[p] = true;
        gone.append(p);
        scalarList& source = sources_[suspensionOf(p)];
        forEachShare
        (
            p,
            [&](label node, scalar w)
            {
                const scalar part = m*demand_[node]*w/asked;
                emptiedMass_[node] += part;
                emptiedWeight_[node] += w*weightSum_[node];
                source[node] += part/Vcell;
            }
        );
        eroded_[suspensionOf(p)] += m;
    }
    if (returnReduce(gone.size(), sumOp<label>()))
    {
        if (parallel)
        {
            halo.addToOwners
            ({
                haloExchange::field(emptiedMass_),
                haloExchange::field(emptiedWeight_)
            });
        }
        halo.copyToHalo
        ({
            haloExchange::field(emptiedMass_),
            haloExchange::field(emptiedWeight_)
        });
    }

    // What is left of each node's demand, shared by the others in
    // proportion to their weights
    forAll(demand_, n)
    {
        if (demand_[n] > 0)
        {
            const scalar left = max(demand_[n] - emptiedMass_[n], scalar(0));
            const scalar others = weightSum_[n] - emptiedWeight_[n];
            // (weightSum_ becomes the factor of a point's weight)
            weightSum_[n] =
                others > SMALL*weightSum_[n] ? left/others/demand_[n] : 0;
        }
    }

    // Each other point gives; the eroded mass enters the water at the
    // nodes that asked for it
    forAll(pts.x, p)
    {
        const scalar m = pts.m[p];
        if (emptied[p])
        {
            continue;
        }

        scalar asked = 0;
        mpm.nodeWeights(p, sw);
        forDemandNodes
        (
            sw,
            [&](label node, scalar N)
            {
                asked += demand_[node]*weightSum_[node]*N;
            }
        );
        if (!(asked > 0))
        {
            continue;
        }
        // Asked for more than it has, or for all but a sliver, it gives
        // all and goes (short of the rest, which the next step's demand
        // takes from the others; a sliver, below minVolumeFraction, more)
        const scalar keep = (m - min(asked, m))/m;
        const bool goes = !(keep*pts.V0[p] >= removeVolume_);
        const scalar given = goes ? m : m - keep*m;
        const scalar scale = given/asked;
        scalarList& source = sources_[suspensionOf(p)];
        forDemandNodes
        (
            sw,
            [&](label node, scalar N)
            {
                source[node] += scale*demand_[node]*weightSum_[node]*N/Vcell;
            }
        );
        eroded_[suspensionOf(p)] += given;

        // The soil leaves whole, at the point's density: the point shrinks
        // (V and V0 alike: its deformation is unchanged), its porosity and
        // stress stay, and its stiffness per mass with them (its wave
        // speed: the soil's stable step)
        if (goes)
        {
            emptied[p] = true;
            continue;
        }
        pts.m[p] = m - given;
        pts.V[p] *= keep;
        pts.V0[p] *= keep;
    }
    gone.clear();
    forAll(emptied, p)
    {
        if (emptied[p])
        {
            gone.append(p);
        }
    }

    // The water's nodes own what the halo images received
    const List<unsigned char>& kind = lattice.kind();
    for (scalarList& source : sources_)
    {
        if (parallel)
        {
            halo.addToOwners({haloExchange::field(source)});
        }
        forAll(source, n)
        {
            if (kind[n] != latticeMesh::OWNED)
            {
                source[n] = 0;
            }
        }
    }

    removed_ += gone.size();
    mpm.removePoints(gone);
    soil_.pointsChanged();
}


void Foam::physicsEffects::erosion::writeWallShearStress() const
{
    writeNodeField
    (
        fluid_.lattice(), "wallShearStress", wallShear_, dimPressure, false
    );
}


// ************************************************************************* //
