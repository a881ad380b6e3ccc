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

// The conversions of nodes that filled or emptied, and their excess mass

#include "lbmFreeSurface.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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
                f[layout_->at(q, n)] += w[q]*drho;
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
                f[layout_->at(q, n)] =
                    w[q]*rho*(1 + 3*cu + 4.5*cu*cu/eps - 1.5*u2);
            }
            // Guo: the populations carry rho u + F/2, F = n rho g
            for (label q = 0; q < Q; ++q)
            {
                f[layout_->at(q, n)] += 1.5*w[q]*eps*rho*(vector(c[q]) & g);
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
    //    shared evenly among the interface neighbours, old and new
    //    (Koerner et al. 2005), as mass (Thuerey 2007, section 4.4,
    //    without the normal weighting). With EXCESS_TO_INTERFACE only
    //    among those that were interface nodes before this step's
    //    conversions: a new one held no water, and a share pushes water
    //    into the gas where no flux brought it. At a sharp edge that fed
    //    the gas nodes under the edge: water draining through a slot in a
    //    plate spread along the plate's underside as a film, 1.6 and 2.6
    //    slot widths wide at 8 and 16 cells across the slot (time means),
    //    its discharge coefficient 0.84 and 0.92; to the old interface
    //    nodes only 1.26 and 1.10 slot widths and 0.79 and 0.77 (Kirchhoff
    //    0.611; tests/validation/slotDischarge). But a surge's front then
    //    advances slower on coarse grids: the dam break's late front speed
    //    -17.6% and -11.9% of Martin & Moyce's at 20 and 40 cells per a,
    //    against -13% and -6.1% (-2.4% against -3.3% at 80), so Koerner
    //    et al.'s rule stays the default. (Sharing with the new nodes
    //    downstream of the giver only, c.u > 0, tried too: the dam break
    //    as the default, the slot's film gone, but its discharge
    //    coefficient 0.82 and 0.90.) Where no interface node can take it
    //    (a gas pocket closed by the surge in a corner fills at once with
    //    m ~ 0 and rho ~ 1: a deficit of a whole node), it is spread over
    //    all the liquid as a uniform change of density, at rest (the
    //    limit of the sound wave that would carry it): handed to the
    //    liquid neighbours it drove them to density ~0.7 and unstable at
    //    water's viscosity (tau - 1/2 ~ 1e-4), kept in the node's own
    //    populations to ~0.
    //    Liquid neighbours take no share otherwise: shares to liquid at
    //    every conversion drove the thin film and the surge tip unstable.
    const label receivers =
        excessMassTo_ == EXCESS_TO_INTERFACE
      ? INTERFACE
      : (INTERFACE | NEW_INTERFACE);
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
            nInterface += ((ty & receivers) != 0);
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
                f[layout_->at(q, n)] += w[q]*excess;
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
        if (type_[n] & receivers)
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
}


// ************************************************************************* //
