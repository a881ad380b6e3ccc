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

// Porous flow: the porosity the water sees, the displacement source, the
// storage a free surface fills

#include "latticeBoltzmannFluid.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::latticeBoltzmannFluid::setEquilibrium
(
    const label n,
    const scalar eps,
    const scalar rhoShift,
    const scalar rhoScale
)
{
    const label Q = velocitySet_->Q();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& w = velocitySet_->w();
    scalarList& f = current();
    scalar rhoHeld = 0;
    vector j(Zero);
    for (label q = 0; q < Q; ++q)
    {
        rhoHeld += f[layout_.at(q, n)];
        j += f[layout_.at(q, n)]*vector(c[q]);
    }
    const scalar rho = rhoShift + rhoScale*rhoHeld;
    const vector u = j/rhoHeld;
    for (label q = 0; q < Q; ++q)
    {
        const scalar cu = vector(c[q]) & u;
        f[layout_.at(q, n)] =
            w[q]*rho*(1 + 3*cu + (4.5*cu*cu - 1.5*magSqr(u))/eps);
    }
    return rho;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeBoltzmannFluid::enablePorosity()
{
    enableForceField();
    if (porosity_.empty())
    {
        porosity_.setSize(lattice_.nBox(), 1.0);
    }
}


void Foam::latticeBoltzmannFluid::enableDisplacement()
{
    displacement_ = true;
    reservoirNodes_ = boundaries_->pressureNodes();
}


void Foam::latticeBoltzmannFluid::addDisplacementSource
(
    const scalarList& eps,
    const scalarList* predictedFall
)
{
    // For a matrix at rest the Guo-Zhao lattice carries
    // d(rho)/dt + div(rho u) = 0. The pore water's mass per mixture volume,
    // n rho_f = rho - (1 - n), obeys d(n rho_f)/dt + div(rho_f u) = 0:
    // where the porosity falls by delta (soil moving in), the lattice
    // density must rise by delta for the water there to keep its mass, and
    // the pressure this makes pushes the displaced water to the neighbours
    // (mixture continuity, div(u + phi v_s) = 0). Added as an isotropic
    // share w_q delta: no momentum. Without it the water ignores the
    // soil's motion: a lifted column rises into water that does not move
    // aside, and the column and the water above it part.
    //
    // The soil's coming step is given to the water ahead of it: the
    // populations hold the water of the porosity less the predicted fall,
    // and each call adds the difference between the actual fall and the
    // predicted one (the mass stays exact). The soil then takes, while it
    // moves, the pressure of its own motion; given a step late, the
    // pressure pushed back on motion already made, and on a submerged bed
    // of coarse sand (weak drag) a standing wave grew from round-off
    // (tests/validation/submergedBed).
    //
    // At a node next to a pressure patch the displaced water goes to (or
    // comes from) the reservoir beyond the patch, which holds the
    // pressure: no source there. (As a source the patch would have to feed
    // it through the node's own velocity, which the extrapolation copies:
    // it would take a pressure deficit of about 3/2 of the source per step,
    // and a column lifting off an inlet would stall on its own suction.)
    const label Q = velocitySet_->Q();
    const scalarList& w = velocitySet_->w();
    scalarList& f = current();
    // (the momentum the nodes carry, summed again from the changed
    // populations: round-off as the two-lattice step has it)
    momentumStale_ = true;
    if (heldPorosity_.empty())
    {
        heldPorosity_ = porosity_;
    }
    auto held = [&](const label n)
    {
        return eps[n] - (predictedFall ? (*predictedFall)[n] : 0);
    };
    for (const label n : reservoirNodes_)
    {
        heldPorosity_[n] = held(n);
    }
    // With a free surface: none in the gas (no water to push); a liquid
    // or interface node's water (rho - (1 - n), or its mass) stays, its
    // pressure rising with the source pushes it to the neighbours
    //
    // Added before the collision, w_q delta is the second-order mass
    // source: the collision then gives f - (f - f_eq(rho))/tau + w_q delta
    // (rho the sum before the source; at rest f_eq is linear in rho),
    // which is the scheme with the source (1 - 1/(2 tau)) w_q delta and the
    // equilibrium at rho + delta/2 (as Guo, Zheng & Shi 2002 centre a
    // force). The water's density in this step is that time-centred
    // rho + delta/2, the populations' sum less delta/2: the pore pressure
    // the buoyancy reads (displacementSource). Read with the whole delta,
    // the pressure of the coming step's compression, of order
    // rho_w c V dphi/n at a face moving at V (c = dx/dt), resisted the
    // motion: a porous block 8 cells thick settled at 0.73 of Darcy's
    // speed with c = 250 m/s and 0.91 with 125 m/s (tau 0.53), and at
    // dx/64 the tank's acoustic mode grew; read centred, 1.13 at both
    // (a first-order error of the faces' cells), and the mode decays
    // (tests/validation/settlingBlock).
    displacementSource_.setSize(lattice_.nBox());
    displacementSource_ = 0;
    scalar added = 0;
    for (const label n : lattice_.cellNode())
    {
        const scalar heldNew = held(n);
        const scalar source = heldPorosity_[n] - heldNew;
        heldPorosity_[n] = heldNew;
        if (source != 0 && !(freeSurface_ && freeSurface_->gas(n)))
        {
            for (label q = 0; q < Q; ++q)
            {
                f[layout_.at(q, n)] += w[q]*source;
            }
            added += source;
            displacementSource_[n] = source;
        }
    }
    displacedMass_ += added;
}


void Foam::latticeBoltzmannFluid::setPorosity
(
    const scalarList& eps,
    const scalarList* predictedFall
)
{
    enablePorosity();
    if (!porosityInitialised_ && writtenPorosity_.size())
    {
        // Restart: the populations hold the porosity written with them
        heldPorosity_.transfer(writtenPorosity_);
        porosityInitialised_ = true;
    }

    if (porosityInitialised_ && displacement_)
    {
        addDisplacementSource(eps, predictedFall);
    }
    for (const label n : lattice_.cellNode())
    {
        porosity_[n] = eps[n];
    }
    // The halo's too: the free surface reads its neighbours' porosity (a
    // node that turns from gas to interface starts at the mean pore
    // density of its water neighbours; with the halo's porosity left from
    // the start, a node at a processor boundary started at another density
    // than serially, 1.4e-4 of its fill level in a dam of material points)
    halo_.exchange(porosity_.data(), 1, lattice_.nBox());
    if (freeSurface_ && storageFollowsPorosity_)
    {
        // The free surface's storage: the porosity whose water the
        // populations hold (with displacement less the predicted fall: the
        // source raises rho as it lowers that porosity, and a node's water
        // rho - (1 - n) stays)
        storage_ =
            (displacement_ && heldPorosity_.size())
          ? heldPorosity_ : porosity_;
    }
    if (porosityInitialised_)
    {
        return;
    }

    porosityInitialised_ = true;
    if (restarted_ || nSteps_ > 0)
    {
        return;
    }

    // The pore pressure p is c_s^2 (rho - 1)/eps: the density that holds
    // the initial p is 1 + eps (rho(p) - 1); the velocity is superficial.
    // (From the populations, which hold rho(p) and U at equilibrium: the
    // fields have been rewritten with Guo's velocity since.)
    momentumStale_ = true;
    scalar mass = 0;
    for (const label n : lattice_.cellNode())
    {
        const scalar eps = porosity_[n];
        mass += setEquilibrium(n, eps, 1 - eps, eps);
    }
    scalarList& f = current();
    if (freeSurface_)
    {
        // (the water in the pores: each node's share of it as its fill
        // level had it)
        freeSurface_->resetMasses(f.cdata());
        mass = freeSurface_->mass(f.cdata());
    }
    mass0_ = returnReduce(mass, sumOp<scalar>());
    updateFields();
    Info<< "Porous flow: the water initialised with the pore pressure p"
        << " and the superficial velocity U" << nl << endl;
}


void Foam::latticeBoltzmannFluid::setStorage(const scalarList& storage)
{
    if (freeSurface_)
    {
        FatalErrorInFunction
            << "the storage porosity is set after the free surface started"
            << " from it: build the porous medium first" << abort(FatalError);
    }
    storage_ = storage;
    storageFollowsPorosity_ = false;
}


// ************************************************************************* //
