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
#include "lbmBoundaries.H"
#include "latticeDescriptors.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(lbmFreeSurface, 0);
}

const Foam::Enum<Foam::lbmFreeSurface::excessMassRule>
Foam::lbmFreeSurface::excessMassRuleNames
({
    { excessMassRule::EXCESS_TO_ALL_INTERFACE, "allInterface" },
    { excessMassRule::EXCESS_TO_INTERFACE, "interface" },
});


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
    scalar rho = 0;
    for (label q = 0; q < vs_.Q(); ++q)
    {
        rho += f[layout_->at(q, n)];
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
    const List<labelVector>& c = vs_.c();
    rho = 0;
    vector j(Zero);
    for (label q = 0; q < Q; ++q)
    {
        const scalar fq = f[layout_->at(q, n)];
        rho += fq;
        j += fq*vector(c[q]);
    }
    // Post-collision momentum is rho u + F/2 (Guo), F = n rho_0 g (n the
    // lattice's porosity, 1 without a medium) and the other forces (a
    // drag: in a soil the largest)
    u = j/rho - 0.5*(porosity(n)*g + otherForce(n))/rho;
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
    const scalar surfaceTension,
    const label excessMassTo
)
:
    lattice_(lattice),
    vs_(vs),
    units_(units),
    obstacles_(obstacles),
    porosity_(porosity),
    storage_(storage),
    staticForce_(nullptr),
    rhoGas_(units.rhoLattice(gasPressure)),
    hydrostatic_(nullptr),
    hydrostaticG_(Zero),
    fillMargin_(fillMargin),
    excessMassTo_(excessMassTo),
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
    layout_(nullptr),
    owned_(lattice.nBox(), false),
    stamp_(lattice.nBox(), 0),
    epoch_(0),
    nFilled_(0),
    nEmptied_(0)
{
    setForces(nullptr);   // (and relaxK_)
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


const Foam::scalar Foam::lbmFreeSurface::tightShare = 1 - std::exp(-1.0);


void Foam::lbmFreeSurface::updatePoreDrag()
{
    // (the liquid nodes' own: an interface node's fed back on itself;
    // with the halo's, as a serial run sees them across a processor's
    // boundary)
    // (only where some node is tight: elsewhere nothing reads it, and a
    // scene without a tight medium pays a scan of relaxK_ for it)
    bool tight = false;
    if (forces_[0] && relaxK_)
    {
        for (const label n : lattice_.cellNode())
        {
            if (relaxK_[n] > tightShare)
            {
                tight = true;
                break;
            }
        }
    }
    if (!returnReduce(tight, orOp<bool>()))
    {
        poreDrag_.clear();
        return;
    }
    poreDrag_.setSize(type_.size());
    poreDrag_ = Zero;
    for (const label n : lattice_.cellNode())
    {
        if (type_[n] == LIQUID)
        {
            poreDrag_[n] = poreGradient(n);
        }
    }
    lattice_.halo().copyToHalo({haloExchange::field(poreDrag_)});
}


void Foam::lbmFreeSurface::reconstruct
(
    scalar* f,
    const vector& g,
    const bool exchange
)
{
    const label Q = vs_.Q();
    const List<labelVector>& c = vs_.c();
    updatePoreDrag();

    // The mass each interface node exchanges, from the populations as
    // they left the collision (before any is rebuilt)
    if (exchange)
    {
        exchangeMass(f);
    }

    // (the rebuilt populations go into gas nodes' slots only: an interface
    // node's own populations, its density and velocity, stay as they left
    // the collision)
    for (const label x : interface_)
    {
        scalar rho;
        vector u;
        moments(f, x, g, rho, u);
        const scalar eps = porosity(x);
        const gasAtSurface gs(gasState(x, g));

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
            f[layout_->at(q, y)] = gasPopulation
            (
                f, x, q, u, eps, gs.density(-0.5*vector(c[q]))
            );
        }
    }
}


Foam::scalar Foam::lbmFreeSurface::gasPopulation
(
    const scalar* f,
    const label x,
    const label q,
    const vector& u,
    const scalar eps,
    const scalar rhoPore
) const
{
    // (in a porous lattice: the equilibrium's second-order terms over n,
    // the pressure that of the pores, c_s^2 (rho - 1)/n)
    const scalar rhoG = eps != 1 ? 1 + eps*(rhoPore - 1) : rhoPore;
    // f^eq_q + f^eq_-q at the gas density: the odd terms cancel
    const scalar cu = vector(vs_.c()[q]) & u;
    return
        2*vs_.w()[q]*rhoG*(1 + 4.5*cu*cu/eps - 1.5*magSqr(u)/eps)
      - f[layout_->at(vs_.opp()[q], x)];
}


Foam::scalar Foam::lbmFreeSurface::gasLinkDensity
(
    const label x,
    const label q,
    const vector& g
) const
{
    return gasState(x, g).density(-0.5*vector(vs_.c()[q]));
}


void Foam::lbmFreeSurface::bodyLinkMass(const lbmBoundaries& boundaries)
{
    const labelList& node = boundaries.bodyLinkNodes();
    const scalarList& correction = boundaries.bodyLinkCorrections();
    forAll(node, k)
    {
        if (type_[node[k]] == INTERFACE)
        {
            mass_[node[k]] += correction[k];
        }
    }
}


void Foam::lbmFreeSurface::pressureLinkMass
(
    const scalar* f,
    const lbmBoundaries& boundaries
)
{
    // exchangeMass gave each interface node the whole of what its links to
    // the boundaries bring, as a liquid neighbour's. Through a pressure
    // patch the water comes over the node's wet share only: its fill
    // level (taken whole, water ran in through the patch faster than the
    // node passed it on to the interface beside it, and a tank at rest
    // beside a reservoir at its own level filled up and blew up). Where
    // the patch holds the gas's pressure or less (air outside), the link
    // is a gas link and brings none.
    const labelList& opp = vs_.opp();
    const labelList& node = boundaries.pressureLinkNodes();
    const labelList& dir = boundaries.pressureLinkDirections();
    const labelList& ghost = boundaries.pressureLinkGhosts();
    forAll(node, i)
    {
        const label x = node[i];
        if (type_[x] != INTERFACE)
        {
            continue;
        }
        const scalar s = boundaries.dryPressureLink(i, rhoGas_) ? 0 : fill_[x];
        mass_[x] +=
            (s - 1)
           *(f[layout_->remap(ghost[i])] - f[layout_->at(opp[dir[i]], x)]);
    }
}


void Foam::lbmFreeSurface::slipLinks
(
    scalar* f,
    const lbmBoundaries& boundaries,
    const vector& g,
    const bool exchange
)
{
    const labelList& opp = vs_.opp();
    const List<labelVector>& c = vs_.c();
    const labelList& node = boundaries.slipLinkNodes();
    const labelList& dir = boundaries.slipLinkDirections();
    const labelList& ghost = boundaries.slipLinkGhosts();
    const labelList& partner = boundaries.slipLinkPartners();
    forAll(node, i)
    {
        const label x = node[i];
        if (type_[x] != INTERFACE)
        {
            continue;
        }
        const label y = partner[i];
        const label t = type_[y];
        const label q = dir[i];
        const label slot = layout_->remap(ghost[i]);
        if (exchange)
        {
            // As a neighbour's link (exchangeMass): the whole from liquid,
            // the mean fill level's share from an interface node, none
            // from the gas
            const scalar s =
                t == LIQUID ? 1
              : t == INTERFACE ? 0.5*(fill_[x] + fill_[y])
              : 0;
            mass_[x] += (s - 1)*(f[slot] - f[layout_->at(opp[q], x)]);
        }
        if (t == GAS)
        {
            // The population the gas sends, as reconstruct's for a link
            // to a gas node
            scalar rho;
            vector u;
            moments(f, x, g, rho, u);
            f[slot] = gasPopulation
            (
                f, x, q, u, porosity(x),
                gasState(x, g).density(-0.5*vector(c[q]))
            );
        }
    }
}


Foam::lbmFreeSurface::gasAtSurface Foam::lbmFreeSurface::gasState
(
    const label x,
    const vector& g
) const
{
    // (the weight the lattice applies, g, or the one off it)
    const bool gravity = (magSqr(g) > 0 || magSqr(hydrostaticG_) > 0);
    const scalar eps = porosity(x);
    const vector grad
    (
        gravity || sigmaRho_ != 0 ? fillGradient(x) : vector::zero
    );

    gasAtSurface gs;
    // The gas pressure at the surface, raised by the capillary pressure
    // sigma kappa (Laplace)
    gs.rho = rhoGas_ + (sigmaRho_ != 0 ? sigmaRho_*curvature(x, grad) : 0);

    // Where the gas pressure holds. The rebuilt populations set it at the
    // middle of each link to the gas, wherever the surface lies in the
    // node: a shift of up to one cell, rho g dx of pressure in the whole
    // water at rest. With gravity, the gas density of each link is the gas
    // pressure carried from the surface (at (fill - 1/2) dx along the
    // normal n from the node) to the link's middle, x - c_q/2, with the
    // pressure gradient of a slow flow, grad(p) = rho_0 g + F_d (F_d the
    // drag or the porous medium's resistance: in a porous medium the water
    // flows under a gradient far from hydrostatic; carried hydrostatically,
    // a slug of water falling through a bed 10 cells long had its ends'
    // pressure off by 0.4 rho g dx and fell 8% slow)
    gs.surface = Zero;
    gs.gradP = Zero;
    const scalar magGrad = mag(grad);
    if (gravity)
    {
        if (magGrad > SMALL)
        {
            // n = -grad/|grad| points into the gas
            gs.surface = -(fill_[x] - 0.5)/magGrad*grad;
        }
        // (the pores' pressure gradient: the lattice's force n rho_0 g + F_d
        // acts on n times the pore water's; x_mid - x_s in lattice units,
        // cs^2 = 1/3)
        //
        // In a tight medium (the resistance taking more than 1 - 1/e of
        // the momentum per step: a = n nu dt/K > 1) the drag is that of the
        // liquid nodes beside the interface node in its medium (their
        // mean; none: no drag): the interface node's own feeds back on
        // itself through the populations rebuilt from it, and that loop
        // grew without bound (water soaking into a bed of K = 3e-7 m2 at
        // 1 cm cells, a = 4.2, stopped as unstable within 60 steps; 1e-6,
        // a = 1.25, ran). Elsewhere the node's own
        vector drag(Zero);
        if (relaxK_ && poreDrag_.size() && relaxK_[x] > tightShare)
        {
            label nLiquid = 0;
            const label Q = vs_.Q();
            for (label q = 1; q < Q; ++q)
            {
                const label y = x + offset_[q];
                if
                (
                    type_[y] == LIQUID
                 && mag(porosity(y) - eps) <= 0.1*eps
                )
                {
                    drag += poreDrag_[y];
                    ++nLiquid;
                }
            }
            drag = nLiquid ? drag/nLiquid : vector::zero;
        }
        else
        {
            drag = poreGradient(x);
        }
        gs.gradP = 3*(g + drag);
    }
    if (hydrostatic_)
    {
        // The populations carry p_rgh = p - p_h: the gas pressure at the
        // surface less p_h there (p_h linear: 3 g.d of lattice density
        // over d), carried from there with the rest of the slow flow's
        // gradient (the lattice's g then holds only a weight along
        // periodic directions). The sum at the link's
        // middle is the gas pressure carried as above with rho_0 g + F_d
        gs.rho -=
            units_.rhoLattice((*hydrostatic_)[x]) - 1
          + 3*(hydrostaticG_ & gs.surface);
    }
    return gs;
}


void Foam::lbmFreeSurface::exchangeMass
(
    const scalar* f,
    const bool boundaryLinks
)
{
    const label Q = vs_.Q();
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
                dm += s*(f[layout_->at(q, y)] - f[layout_->at(opp[q], x)]);
            }
        }
        mass_[x] += dm;
    }
}


void Foam::lbmFreeSurface::exchangeBoundaryMass(const scalar* f)
{
    exchangeMass(f, true);
}


void Foam::lbmFreeSurface::setHydrostatic
(
    const scalarList& pH,
    const vector& g
)
{
    hydrostatic_ = &pH;
    hydrostaticG_ = units_.accelerationToLattice(g);
}


void Foam::lbmFreeSurface::setForces
(
    const scalar* const forces[6],
    const scalar* relaxK
)
{
    for (label i = 0; i < 6; ++i)
    {
        forces_[i] = forces ? forces[i] : nullptr;
    }
    relaxK_ = forces ? relaxK : nullptr;
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
       *(mass_.size() + fill_.size() + rhoU_.size() + share_.size())
      + sizeof(vector)*poreDrag_.size();
}


// ************************************************************************* //
