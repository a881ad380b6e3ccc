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

#include "lbmFreeSurface.H"
#include "nodeFieldIO.H"
#include "latticeDescriptors.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(lbmFreeSurface, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::lbmFreeSurface::exchangeTypes()
{
    lattice_.halo().exchange(type_);
}


void Foam::lbmFreeSurface::rebuild()
{
    // The kernel's runs: the obstacles' runs (the water's nodes) without
    // the gas nodes
    runs_.clear();
    interface_.clear();
    DynamicList<latticeMesh::nodeRun> runs(obstacles_.runs().size());
    for (const latticeMesh::nodeRun& r : obstacles_.runs())
    {
        label start = -1;
        for (label n = r[0]; n < r[1]; ++n)
        {
            const bool water = (type_[n] != GAS);
            if (water && start < 0)
            {
                start = n;
            }
            else if (!water && start >= 0)
            {
                runs.append(latticeMesh::nodeRun({start, n}));
                start = -1;
            }
            if (type_[n] == INTERFACE)
            {
                interface_.append(n);
            }
        }
        if (start >= 0)
        {
            runs.append(latticeMesh::nodeRun({start, r[1]}));
        }
    }
    runs_.transfer(runs);
}


Foam::scalar Foam::lbmFreeSurface::density
(
    const scalar* f,
    const label n
) const
{
    const label nBox = lattice_.nBox();
    scalar rho = 0;
    for (label q = 0; q < vs_.Q(); ++q)
    {
        rho += f[q*nBox + n];
    }
    return rho;
}


void Foam::lbmFreeSurface::moments
(
    const scalar* f,
    const label n,
    const vector& g,
    scalar& rho,
    vector& u
) const
{
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = vs_.c();
    rho = 0;
    vector j(Zero);
    for (label q = 0; q < Q; ++q)
    {
        const scalar fq = f[q*nBox + n];
        rho += fq;
        j += fq*vector(c[q]);
    }
    // Post-collision momentum is rho u + F/2 (Guo), F = n rho g (n the
    // lattice's porosity, 1 without a medium) and the other forces (a
    // drag: in a soil the largest)
    u = j/rho - 0.5*porosity(n)*g - 0.5*otherForce(n)/rho;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lbmFreeSurface::lbmFreeSurface
(
    const latticeMesh& lattice,
    const velocitySet& vs,
    const lbmUnits& units,
    const lbmObstacles& obstacles,
    const scalarList& porosity,
    const scalarList& storage,
    const scalar gasPressure,
    const scalar fillMargin,
    const scalar surfaceTension
)
:
    lattice_(lattice),
    vs_(vs),
    units_(units),
    obstacles_(obstacles),
    porosity_(porosity),
    storage_(storage),
    rhoGas_(units.rhoLattice(gasPressure)),
    fillMargin_(fillMargin),
    sigmaRho_
    (
        units.rhoLattice(surfaceTension/lattice.dx()) - units.rhoLattice(0)
    ),
    type_(lattice.nBox(), NONE),
    mass_(lattice.nBox(), 0.0),
    fill_(lattice.nBox(), 0.0),
    rhoU_(4*lattice.nBox(), 0.0),
    share_(lattice.nBox(), 0.0),
    offset_(vs.Q()),
    owned_(lattice.nBox(), false),
    stamp_(lattice.nBox(), 0),
    epoch_(0),
    nFilled_(0),
    nEmptied_(0)
{
    setForces(nullptr);
    forAll(offset_, q)
    {
        const labelVector& c = vs.c()[q];
        offset_[q] = lattice.offset(c.x(), c.y(), c.z());
    }
    for (const label n : lattice.cellNode())
    {
        owned_[n] = true;
    }
    DynamicList<label> border;
    for (const label n : lattice.cellNode())
    {
        for (label q = 1; q < vs.Q(); ++q)
        {
            if (!owned_[n - offset_[q]])
            {
                border.append(n);
                break;
            }
        }
    }
    border_.transfer(border);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::lbmFreeSurface::setFromFraction
(
    const scalarField& alpha,
    scalar* f
)
{
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    const labelList& cellNode = lattice_.cellNode();
    const scalarList& w = vs_.w();

    // (alpha is checked by the caller: finite, in [0, 1])
    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        if (obstacles_.solid(n))
        {
            continue;
        }
        const scalar rho = density(f, n);
        const scalar a = alpha[celli];
        if (a >= 1)
        {
            type_[n] = LIQUID;
            mass_[n] = capacity(rho, n);
            fill_[n] = 1;
        }
        else if (a <= 0)
        {
            type_[n] = GAS;
            mass_[n] = 0;
            fill_[n] = 0;
        }
        else
        {
            type_[n] = INTERFACE;
            mass_[n] = a*capacity(rho, n);
            fill_[n] = a;
        }
    }
    exchangeTypes();

    // Close the interface layer: a liquid node next to gas is an interface
    // node, full
    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        if (type_[n] != LIQUID)
        {
            continue;
        }
        for (label q = 1; q < Q; ++q)
        {
            if (type_[n - offset_[q]] == GAS)
            {
                type_[n] = INTERFACE;
                break;
            }
        }
    }
    exchangeTypes();
    lattice_.halo().exchange(fill_.data(), 1, nBox);

    // The gas at rest at its own density (its populations are never
    // streamed into water: only finite)
    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        if (type_[n] == GAS)
        {
            const scalar rhoG = 1 + porosity(n)*(rhoGas_ - 1);
            for (label q = 0; q < Q; ++q)
            {
                f[q*nBox + n] = w[q]*rhoG;
            }
        }
    }
    rebuild();
    checkPressureNodes();
}


void Foam::lbmFreeSurface::readState(scalar* f)
{
    const label nBox = lattice_.nBox();
    scalarList t(nBox, 0.0);
    readNodeField(lattice_, "lbmFreeSurfaceType", t.data());
    readNodeField(lattice_, "lbmFreeSurfaceMass", mass_.data());
    // The interface nodes' fill levels as the run had them (in a soil the
    // porosity they were taken with is mapped again only in the coming
    // step, after the drag has used them)
    scalarList writtenFill;
    if (foundNodeField(lattice_, "lbmFreeSurfaceFill"))
    {
        writtenFill.setSize(nBox, 0.0);
        readNodeField(lattice_, "lbmFreeSurfaceFill", writtenFill.data());
    }
    const labelList& cellNode = lattice_.cellNode();
    for (const label n : cellNode)
    {
        if (obstacles_.solid(n))
        {
            continue;
        }
        const label ti = label(t[n]);
        if
        (
            !(t[n] == ti)
         || (ti != LIQUID && ti != INTERFACE && ti != GAS)
        )
        {
            FatalErrorInFunction
                << "lbmFreeSurfaceType in " << lattice_.mesh().time().timePath()
                << " holds " << t[n] << " at node " << n << ": only "
                << label(LIQUID) << " (liquid), " << label(INTERFACE)
                << " (interface) or " << label(GAS) << " (gas) are written."
                << nl << "    The file is damaged: restart from another"
                << " written time" << exit(FatalError);
        }
        type_[n] = ti;
        const scalar C = capacity(density(f, n), n);
        if (ti == LIQUID)
        {
            mass_[n] = C;
            fill_[n] = 1;
        }
        else if (ti == GAS)
        {
            mass_[n] = 0;
            fill_[n] = 0;
        }
        else
        {
            fill_[n] =
                writtenFill.size()
              ? writtenFill[n]
              : min(max(mass_[n]/C, 0.0), 1.0);
        }
    }
    exchangeTypes();
    lattice_.halo().exchange(fill_.data(), 1, nBox);
    rebuild();
    checkPressureNodes();
}


void Foam::lbmFreeSurface::resetMasses(const scalar* f)
{
    for (const label n : lattice_.cellNode())
    {
        const label t = type_[n];
        if (t == LIQUID || t == INTERFACE)
        {
            mass_[n] = fill_[n]*capacity(density(f, n), n);
        }
    }
}


void Foam::lbmFreeSurface::writeState() const
{
    // The types, and the masses of the interface nodes (a liquid node's is
    // its density, a gas node's 0: not written, so a restart's files equal
    // a straight run's byte for byte)
    scalarList t(lattice_.nBox(), 0.0);
    scalarList m(lattice_.nBox(), 0.0);
    scalarList phi(lattice_.nBox(), 0.0);
    forAll(t, n)
    {
        t[n] = type_[n];
        if (type_[n] == INTERFACE)
        {
            m[n] = mass_[n];
            phi[n] = fill_[n];
        }
    }
    writeNodeField(lattice_, "lbmFreeSurfaceType", t.cdata());
    writeNodeField(lattice_, "lbmFreeSurfaceMass", m.cdata());
    writeNodeField(lattice_, "lbmFreeSurfaceFill", phi.cdata());
}


Foam::wordList Foam::lbmFreeSurface::stateFiles() const
{
    return wordList
    ({
        "lbmFreeSurfaceType", "lbmFreeSurfaceMass", "lbmFreeSurfaceFill"
    });
}


Foam::vector Foam::lbmFreeSurface::fillGradient(const label x) const
{
    const label Q = vs_.Q();
    const List<labelVector>& c = vs_.c();
    const scalarList& w = vs_.w();
    const scalar phi = fill_[x];
    vector grad(Zero);
    for (label q = 1; q < Q; ++q)
    {
        const label y = x + offset_[q];
        // (walls: no gradient across them)
        grad += w[q]*(type_[y] == NONE ? phi : fill_[y])*vector(c[q]);
    }
    return grad;
}


Foam::scalar Foam::lbmFreeSurface::curvature
(
    const label x,
    const vector& grad
) const
{
    // The axis nearest the normal
    label d = 0;
    for (label k = 1; k < 3; ++k)
    {
        if (mag(grad[k]) > mag(grad[d]))
        {
            d = k;
        }
    }
    if (mag(grad[d]) < SMALL)
    {
        return 0;
    }
    // The tangential axes: two in 3D, one in 2D (the third has no nodes)
    const bool is3D = (vs_.D() == 3);
    const label t1 = (d + 1) % 3;
    const label t2 = (d + 2) % 3;
    labelVector ed(Zero), e1(Zero), e2(Zero);
    ed[d] = 1;
    e1[t1] = 1;
    e2[t2] = 1;
    if (!is3D && t1 == 2)
    {
        // (2D: the tangent is the in-plane axis)
        e1 = e2;
        e2 = Zero;
    }
    const label od = lattice_.offset(ed.x(), ed.y(), ed.z());
    const label o1 = lattice_.offset(e1.x(), e1.y(), e1.z());
    const label o2 = lattice_.offset(e2.x(), e2.y(), e2.z());

    // Heights: the liquid in each column of 5 along d
    scalar H[3][3];
    const label jMax = (is3D ? 1 : 0);
    for (label i = -1; i <= 1; ++i)
    {
        for (label j = -jMax; j <= jMax; ++j)
        {
            scalar h = 0;
            for (label k = -2; k <= 2; ++k)
            {
                const label y = x + i*o1 + j*o2 + k*od;
                const label t = type_[y];
                if (t == NONE)
                {
                    return 0;
                }
                h += (t == LIQUID ? 1.0 : t == GAS ? 0.0 : fill_[y]);
            }
            H[i + 1][j + 1] = h;
        }
    }
    if (!is3D)
    {
        const scalar hx = 0.5*(H[2][1] - H[0][1]);
        const scalar hxx = H[2][1] - 2*H[1][1] + H[0][1];
        return -hxx/pow(1 + sqr(hx), 1.5);
    }
    const scalar hx = 0.5*(H[2][1] - H[0][1]);
    const scalar hy = 0.5*(H[1][2] - H[1][0]);
    const scalar hxx = H[2][1] - 2*H[1][1] + H[0][1];
    const scalar hyy = H[1][2] - 2*H[1][1] + H[1][0];
    const scalar hxy = 0.25*(H[2][2] - H[2][0] - H[0][2] + H[0][0]);
    return
       -((1 + sqr(hy))*hxx + (1 + sqr(hx))*hyy - 2*hx*hy*hxy)
       /pow(1 + sqr(hx) + sqr(hy), 1.5);
}


void Foam::lbmFreeSurface::reconstruct
(
    scalar* f,
    const vector& g,
    const bool exchange
)
{
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = vs_.c();
    const scalarList& w = vs_.w();
    const labelList& opp = vs_.opp();

    // The mass each interface node exchanges, from the populations as
    // they left the collision (before any is rebuilt)
    if (exchange)
    {
        exchangeMass(f);
    }

    // (the rebuilt populations go into gas nodes' slots only: an interface
    // node's own populations, its density and velocity, stay as they left
    // the collision)
    const bool gravity = (magSqr(g) > 0);
    for (const label x : interface_)
    {
        scalar rho;
        vector u;
        moments(f, x, g, rho, u);
        // (in a porous lattice: the equilibrium's second-order terms over
        // n, the pressure that of the pores, c_s^2 (rho - 1)/n)
        const scalar eps = porosity(x);
        const scalar u2 = magSqr(u)/eps;
        const scalar rhoPore = 1 + (rho - 1)/eps;

        const vector grad
        (
            gravity || sigmaRho_ != 0 ? fillGradient(x) : vector::zero
        );

        // The gas pressure at the surface, raised by the capillary pressure
        // sigma kappa (Laplace)
        const scalar rhoGasX =
            rhoGas_ + (sigmaRho_ != 0 ? sigmaRho_*curvature(x, grad) : 0);

        // Where the gas pressure holds. The rebuilt populations set it at
        // the middle of each link to the gas, wherever the surface lies in
        // the node: a shift of up to one cell, rho g dx of pressure in
        // the whole water at rest. With gravity, the gas density of each
        // link is the gas pressure carried from the surface (at
        // (fill - 1/2) dx along the normal n from the node) to the link's
        // middle, x - c_q/2, with the pressure gradient of a slow flow,
        // grad(p) = rho g + F_d (F_d the drag or the porous medium's
        // resistance: in a porous medium the water flows under a gradient
        // far from hydrostatic; carried hydrostatically, a slug of water
        // falling through a bed 10 cells long had its ends' pressure off
        // by 0.4 rho g dx and fell 8% slow)
        vector surface(Zero);
        const scalar magGrad = mag(grad);
        if (gravity && magGrad > SMALL)
        {
            // n = -grad/|grad| points into the gas
            surface = -(fill_[x] - 0.5)/magGrad*grad;
        }
        // (the pores' pressure gradient: the lattice's force n rho g + F_d
        // acts on n times the pore water's)
        const vector gradP = rhoPore*g + otherForce(x)/eps;

        for (label q = 1; q < Q; ++q)
        {
            const label y = x - offset_[q];
            // (only the populations the gas would send: rebuilding also
            // those arriving from the gas side of the surface, n.c_q < 0,
            // as Koerner et al. 2005, drove currents of 1 m/s in a tank at
            // rest here)
            if (type_[y] != GAS)
            {
                continue;
            }
            scalar rhoG = rhoGasX;
            if (gravity)
            {
                // x_mid - x_s, in lattice units (cs^2 = 1/3)
                const vector d(-0.5*vector(c[q]) - surface);
                rhoG += 3*(gradP & d);
            }
            if (eps != 1)
            {
                rhoG = 1 + eps*(rhoG - 1);
            }
            // f^eq_q + f^eq_-q at the gas density: the odd terms cancel
            const scalar cu = vector(c[q]) & u;
            f[q*nBox + y] =
                2*w[q]*rhoG*(1 + 4.5*cu*cu/eps - 1.5*u2)
              - f[opp[q]*nBox + x];
        }
    }
}


void Foam::lbmFreeSurface::exchangeMass
(
    const scalar* f,
    const bool boundaryLinks
)
{
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    const labelList& opp = vs_.opp();

    for (const label x : interface_)
    {
        scalar dm = 0;
        for (label q = 1; q < Q; ++q)
        {
            const label y = x - offset_[q];
            const label t = type_[y];
            scalar s = 0;
            if (boundaryLinks)
            {
                // (a boundary supplies water: the whole population, as a
                // liquid neighbour's)
                s = (t == NONE);
            }
            else if (t == LIQUID)
            {
                s = 1;
            }
            else if (t == INTERFACE)
            {
                s = 0.5*(fill_[x] + fill_[y]);
            }
            if (s != 0)
            {
                dm += s*(f[q*nBox + y] - f[opp[q]*nBox + x]);
            }
        }
        mass_[x] += dm;
    }
}


void Foam::lbmFreeSurface::exchangeBoundaryMass(const scalar* f)
{
    exchangeMass(f, true);
}


void Foam::lbmFreeSurface::spreadOverLiquid(scalar* f, scalar dm) const
{
    // Collective: every rank takes part, with or without a share (the
    // liquid counted only when there is something to spread)
    const scalar dmAll = returnReduce(dm, sumOp<scalar>());
    if (dmAll == 0)
    {
        return;
    }
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    const scalarList& w = vs_.w();
    scalar nLiquid = 0;
    for (const label n : lattice_.cellNode())
    {
        nLiquid += (type_[n] == LIQUID);
    }
    reduce(nLiquid, sumOp<scalar>());
    // (nLiquid >= 1: every giver had a liquid neighbour, which stays
    // liquid through the conversion)
    const scalar drho = dmAll/nLiquid;
    for (const label n : lattice_.cellNode())
    {
        if (type_[n] == LIQUID)
        {
            for (label q = 0; q < Q; ++q)
            {
                f[q*nBox + n] += w[q]*drho;
            }
        }
    }
}


void Foam::lbmFreeSurface::collectNear()
{
    // Every node a conversion can change is an interface node, a
    // neighbour of one, or (a neighbour of another processor's) on the
    // border: the passes of convert run over these only
    if (++epoch_ == labelMax)
    {
        stamp_ = 0;
        epoch_ = 1;
    }
    near_.clear();
    auto add = [this](const label n)
    {
        if (owned_[n] && stamp_[n] != epoch_)
        {
            stamp_[n] = epoch_;
            near_.append(n);
        }
    };
    const label Q = vs_.Q();
    for (const label x : interface_)
    {
        add(x);
        for (label q = 1; q < Q; ++q)
        {
            add(x - offset_[q]);
        }
    }
    for (const label n : border_)
    {
        add(n);
    }
}


void Foam::lbmFreeSurface::convert(scalar* f, const vector& g)
{
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = vs_.c();
    const scalarList& w = vs_.w();
    const haloExchange& halo = lattice_.halo();
    collectNear();

    scalar* rhoN = rhoU_.data();
    scalar* uN[3] =
        {rhoU_.data() + nBox, rhoU_.data() + 2*nBox, rhoU_.data() + 3*nBox};

    // 1. Interface nodes that filled or emptied (their density and
    //    velocity kept for their new neighbours)
    for (const label x : interface_)
    {
        scalar rho;
        vector u;
        moments(f, x, g, rho, u);
        rhoN[x] = rho;
        uN[0][x] = u.x();
        uN[1][x] = u.y();
        uN[2][x] = u.z();

        bool gasNear = false, liquidNear = false;
        for (label q = 1; q < Q; ++q)
        {
            const label t = type_[x - offset_[q]];
            gasNear = gasNear || t == GAS;
            liquidNear = liquidNear || t == LIQUID;
        }
        const scalar m = mass_[x];
        const scalar C = capacity(rho, x);
        if (m > (1 + fillMargin_)*C || !gasNear)
        {
            type_[x] = TO_FILL;
        }
        else if (m < -fillMargin_*C || !liquidNear)
        {
            type_[x] = TO_EMPTY;
        }
    }
    exchangeTypes();
    halo.exchange(rhoU_.data(), 4, nBox);

    // 2. Gas next to a filling node becomes interface; an emptying node
    //    next to a filling one stays interface
    for (const label n : near_)
    {
        const label t = type_[n];
        if (t != GAS && t != TO_EMPTY)
        {
            continue;
        }
        for (label q = 1; q < Q; ++q)
        {
            if (type_[n - offset_[q]] == TO_FILL)
            {
                type_[n] = (t == GAS ? NEW_INTERFACE : INTERFACE);
                break;
            }
        }
    }
    exchangeTypes();

    // 3. New interface nodes at the equilibrium of their water
    //    neighbours' mean density and velocity; liquid next to an
    //    emptying node becomes interface (full)
    for (const label n : near_)
    {
        const label t = type_[n];
        if (t == NEW_INTERFACE)
        {
            // (the mean of the pore densities, c_s^2 (rho - 1)/n the
            // pressure: a porous lattice's density differs with n)
            scalar rhoPore = 0;
            vector u(Zero);
            label k = 0;
            for (label q = 1; q < Q; ++q)
            {
                const label y = n - offset_[q];
                if (type_[y] & (INTERFACE | TO_FILL | TO_EMPTY))
                {
                    rhoPore += 1 + (rhoN[y] - 1)/porosity(y);
                    u += vector(uN[0][y], uN[1][y], uN[2][y]);
                    ++k;
                }
            }
            // (k >= 1: a neighbour filled)
            const scalar eps = porosity(n);
            const scalar rho = 1 + eps*(rhoPore/k - 1);
            u /= k;
            const scalar u2 = magSqr(u)/eps;
            for (label q = 0; q < Q; ++q)
            {
                const scalar cu = vector(c[q]) & u;
                f[q*nBox + n] =
                    w[q]*rho*(1 + 3*cu + 4.5*cu*cu/eps - 1.5*u2);
            }
            // Guo: the populations carry rho u + F/2, F = n rho g
            for (label q = 0; q < Q; ++q)
            {
                f[q*nBox + n] += 1.5*w[q]*eps*rho*(vector(c[q]) & g);
            }
            rhoN[n] = rho;
            mass_[n] = 0;
        }
        else if (t == LIQUID)
        {
            for (label q = 1; q < Q; ++q)
            {
                if (type_[n - offset_[q]] == TO_EMPTY)
                {
                    type_[n] = INTERFACE;
                    rhoN[n] = density(f, n);
                    mass_[n] = capacity(rhoN[n], n);
                    break;
                }
            }
        }
    }
    exchangeTypes();

    // 4. The excess mass: of each converting node (m - rho of a filling
    //    one, m of an emptying one) and of each interface node outside
    //    the conversion band [-fillMargin rho, (1 + fillMargin) rho] (a
    //    node kept from converting: its mass clamped to the band, so no
    //    node carries a mass far outside it for long; clamped to [0, rho]
    //    instead, as FluidX3D does, a node that drains slower than
    //    fillMargin rho per step never empties: the clamp hands its
    //    deficit on every step, a spurious pump that held a steady
    //    current of 0.1 k at the phreatic surface in a porous bed),
    //    shared evenly among the neighbours that are interface nodes (old
    //    and new), as mass (Thuerey 2007, section 4.4, without the normal
    //    weighting). Where no interface node can take it (a gas pocket
    //    closed by the surge in a corner fills at once with m ~ 0 and
    //    rho ~ 1: a deficit of a whole node), it is spread over all the
    //    liquid as a uniform change of density, at rest (the limit of the
    //    sound wave that would carry it): handed to the liquid neighbours
    //    it drove them to density ~0.7 and unstable at water's viscosity
    //    (tau - 1/2 ~ 1e-4), kept in the node's own populations to ~0.
    //    Liquid neighbours take no share otherwise: shares to liquid at
    //    every conversion drove the thin film and the surge tip unstable.
    nFilled_ = 0;
    nEmptied_ = 0;
    DynamicList<label> keep;
    scalar spread = 0;
    for (const label n : near_)
    {
        // (share_ is 0 here: cleared after each gather)
        const label t = type_[n];
        scalar excess = 0;
        if (t == TO_FILL)
        {
            excess = mass_[n] - capacity(rhoN[n], n);
        }
        else if (t == TO_EMPTY)
        {
            excess = mass_[n];
        }
        else if (t == INTERFACE)
        {
            rhoN[n] = density(f, n);
            const scalar C = capacity(rhoN[n], n);
            const scalar m = mass_[n];
            const scalar top = (1 + fillMargin_)*C;
            const scalar bottom = -fillMargin_*C;
            excess =
                (m > top ? m - top : (m < bottom ? m - bottom : 0));
        }
        if (excess == 0 && t != TO_EMPTY)
        {
            continue;
        }
        label nInterface = 0, nLiquid = 0;
        for (label q = 1; q < Q; ++q)
        {
            const label ty = type_[n - offset_[q]];
            nInterface += ((ty & (INTERFACE | NEW_INTERFACE)) != 0);
            nLiquid += (ty == LIQUID);
        }
        if (nInterface > 0)
        {
            share_[n] = excess/nInterface;
        }
        else if (nLiquid > 0 && t != INTERFACE)
        {
            spread += excess;
        }
        else if (t == TO_FILL)
        {
            // No water neighbour at all (a drop of one node): the excess
            // stays in the node's own populations
            for (label q = 0; q < Q; ++q)
            {
                f[q*nBox + n] += w[q]*excess;
            }
            rhoN[n] += excess;
            continue;
        }
        else if (t == TO_EMPTY)
        {
            // No neighbour to take it: the node stays an interface node
            // with its mass
            keep.append(n);
            continue;
        }
        else
        {
            // (an interface node with only liquid neighbours keeps its
            // mass: it fills at the next step)
            continue;
        }
        if (t == INTERFACE)
        {
            mass_[n] -= excess;
        }
    }
    halo.exchange(share_.data(), 1, nBox);

    // 5. Gather the shares (each receiver was counted by its giver) and
    //    set the new types
    for (const label n : near_)
    {
        if (type_[n] & (INTERFACE | NEW_INTERFACE))
        {
            scalar gathered = 0;
            for (label q = 1; q < Q; ++q)
            {
                gathered += share_[n - offset_[q]];
            }
            mass_[n] += gathered;
        }
    }
    spreadOverLiquid(f, spread);
    // (share_ stays 0 outside near_: cleared where this step set it)
    for (const label n : near_)
    {
        share_[n] = 0;
    }
    for (const label n : keep)
    {
        type_[n] = INTERFACE;
    }
    for (const label n : near_)
    {
        label& t = type_[n];
        if (t == TO_FILL)
        {
            t = LIQUID;
            mass_[n] = capacity(rhoN[n], n);
            ++nFilled_;
        }
        else if (t == TO_EMPTY)
        {
            t = GAS;
            mass_[n] = 0;
            ++nEmptied_;
        }
        else if (t == NEW_INTERFACE)
        {
            t = INTERFACE;
        }
    }

    // Fill levels: of the interface nodes, clamped to [0, 1] for the
    // exchange weights
    for (const label n : near_)
    {
        const label t = type_[n];
        if (t == LIQUID)
        {
            fill_[n] = 1;
        }
        else if (t == GAS)
        {
            fill_[n] = 0;
        }
        else if (t == INTERFACE)
        {
            fill_[n] = min(max(mass_[n]/capacity(density(f, n), n), 0.0), 1.0);
        }
    }
    exchangeTypes();
    halo.exchange(fill_.data(), 1, nBox);
    rebuild();
    checkPressureNodes();
}


void Foam::lbmFreeSurface::setForces(const scalar* const forces[6])
{
    for (label i = 0; i < 6; ++i)
    {
        forces_[i] = forces ? forces[i] : nullptr;
    }
}


void Foam::lbmFreeSurface::setPressureNodes
(
    const labelList& nodes,
    const wordList& patch
)
{
    pressureNodes_ = nodes;
    pressurePatch_ = patch;
}


void Foam::lbmFreeSurface::checkPressureNodes() const
{
    forAll(pressureNodes_, i)
    {
        const label n = pressureNodes_[i];
        if (type_[n] == LIQUID)
        {
            continue;
        }
        const Time& runTime = lattice_.mesh().time();
        FatalErrorInFunction
            << "The water's surface meets the pressure patch "
            << pressurePatch_[i] << " at " << lattice_.position(n)
            << " (time " << runTime.timeName() << "): the node next to it is "
            << (type_[n] == GAS ? "gas" : "an interface node") << "." << nl
            << "    With freeSurface a pressure patch must lie under the"
            << " water, one node or more below the surface: its links bring"
            << " water the surface's mass balance does not count. Lower the"
            << " patch (or give it below the surface only, e.g. on the"
            << " floor of a reservoir, whose level its pressure then"
            << " holds), or raise the water (0/alpha.water)"
            << exit(FatalError);
    }
}


Foam::scalar Foam::lbmFreeSurface::mass(const scalar* f) const
{
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    scalar m = 0;
    for (const label n : lattice_.cellNode())
    {
        const label t = type_[n];
        if (t == LIQUID)
        {
            scalar rho = 0;
            for (label q = 0; q < Q; ++q)
            {
                rho += f[q*nBox + n];
            }
            m += capacity(rho, n);
        }
        else if (t == INTERFACE)
        {
            m += mass_[n];
        }
    }
    return m;
}


Foam::scalar Foam::lbmFreeSurface::storedSum(const scalar* f) const
{
    scalar sum = 0;
    for (const label n : lattice_.cellNode())
    {
        const label t = type_[n];
        if (t == LIQUID)
        {
            sum += density(f, n);
        }
        else if (t == INTERFACE)
        {
            sum += mass_[n];
        }
    }
    return sum;
}


Foam::string Foam::lbmFreeSurface::describe(const label n) const
{
    auto typeName = [](const label t)
    {
        return
            t == LIQUID ? "liquid" : t == INTERFACE ? "interface"
          : t == GAS ? "gas" : "wall";
    };
    string s =
        word(typeName(type_[n])) + " node, mass " + Foam::name(mass_[n])
      + ", fill level " + Foam::name(fill_[n]) + "; neighbours";
    label nType[3] = {0, 0, 0};
    for (label q = 1; q < vs_.Q(); ++q)
    {
        const label t = type_[n - offset_[q]];
        nType[0] += (t == LIQUID);
        nType[1] += (t == INTERFACE);
        nType[2] += (t == GAS);
    }
    return
        s + " " + Foam::name(nType[0]) + " liquid, " + Foam::name(nType[1])
      + " interface, " + Foam::name(nType[2]) + " gas";
}


Foam::labelVector Foam::lbmFreeSurface::counts() const
{
    labelVector n(interface_.size(), nFilled_, nEmptied_);
    reduce(n, sumOp<labelVector>());
    return n;
}


Foam::scalar Foam::lbmFreeSurface::memoryBytes() const
{
    return
        sizeof(label)*type_.size()
      + sizeof(scalar)
       *(mass_.size() + fill_.size() + rhoU_.size() + share_.size());
}


// ************************************************************************* //
