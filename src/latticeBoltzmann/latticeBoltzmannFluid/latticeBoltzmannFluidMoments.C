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
    latticeBoltzmannFluid: what the populations give (the fields U, p, rho,
    the nodal velocity, the viscous stress, momentum and mass) and their
    output; the lattice's set-up and step are in latticeBoltzmannFluid.C.

\*---------------------------------------------------------------------------*/

#include "latticeBoltzmannFluid.H"
#include "nodeFieldIO.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::latticeBoltzmannFluid::nodePressure(const label n) const
{
    if (freeSurface_ && freeSurface_->gas(n))
    {
        // (the gas's populations are not the water's)
        return units_.pressure(freeSurface_->rhoGas());
    }
    const label Q = velocitySet_->Q();
    const scalarList& f = current();
    scalar rho = 0;
    for (label q = 0; q < Q; ++q)
    {
        rho += f[layout_.at(q, n)];
    }
    const scalar eps = porosity_.size() ? porosity_[n] : 1.0;
    return
        units_.pressure(pressureDensity(n, rho))/eps + hydrostaticPressure(n);
}


void Foam::latticeBoltzmannFluid::wallForce
(
    const boolList& selectedPatches,
    const boolList& selectedBodies,
    const point& CofR,
    const scalar pRef,
    vector& force,
    vector& moment
)
{
    // The halo's populations as the next step's pull reads them (a slip
    // link takes its population from a neighbour); the next step
    // exchanges the same values again
    scalarList& f = current();
    exchangeHalo(f.data());
    const vector g = latticeAcceleration();
    const scalar* porosity = porosity_.size() ? porosity_.cdata() : nullptr;
    if (freeSurface_)
    {
        // The wall slots as the next step fills them, on a copy (the
        // fill is the step's: the gas's populations into the interface
        // nodes, then the boundaries and the slip links, no mass
        // exchanged)
        scratch_ = f;
        setFreeSurfaceForces();
        freeSurface_->reconstruct(scratch_.data(), g, false);
        boundaries_->fill
        (
            scratch_.data(), layout_, porosity, freeSurface_.get(), g
        );
        freeSurface_->slipLinks(scratch_.data(), boundaries_(), g, false);
    }

    vector P, M, Prest, Mrest;
    boundaries_->wallMomentum
    (
        freeSurface_ ? scratch_.cdata() : f.cdata(),
        layout_,
        porosity,
        g,
        freeSurface_.get(),
        selectedPatches,
        selectedBodies,
        CofR,
        P,
        M,
        Prest,
        Mrest
    );
    // Lattice momentum per step to newtons: rho0 V (dx/dt)/dt, V the
    // volume of a node (the cell; a 2D mesh's thickness included)
    const scalar rhoRef = units_.rhoLattice(pRef);
    const scalar toN =
        units_.rho0()*lattice_.cellVolume()*units_.velocityScale()
       /units_.dt();
    force = toN*(P - rhoRef*Prest);
    moment = toN*(M - rhoRef*Mrest);
    reduce(force, sumOp<vector>());
    reduce(moment, sumOp<vector>());
}


void Foam::latticeBoltzmannFluid::viscousStress(List<symmTensor>& sigma)
{
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& w = velocitySet_->w();

    // The populations the next step collides: the current ones pulled,
    // with the halo and the boundaries' wall slots
    scratch_ = current();
    exchangeHalo(scratch_.data());
    if (freeSurface_)
    {
        // (the gas's populations into the interface nodes, as the step
        // rebuilds them; the mass exchange is the step's own)
        setFreeSurfaceForces();
        freeSurface_->reconstruct
        (
            scratch_.data(),
            latticeAcceleration(),
            false
        );
    }
    boundaries_->fill
    (
        scratch_.data(),
        layout_,
        porosity_.size() ? porosity_.cdata() : nullptr,
        freeSurface_.get(),
        latticeAcceleration()
    );
    if (freeSurface_)
    {
        freeSurface_->slipLinks
        (
            scratch_.data(),
            boundaries_(),
            latticeAcceleration(),
            false
        );
    }

    const scalar factor = 1 - 0.5/units_.tau();
    const scalar toPa = units_.rho0()*sqr(units_.velocityScale());
    scalarList f(Q);
    sigma.setSize(nBox);
    sigma = Zero;
    for (const label n : lattice_.cellNode())
    {
        if (!water(n))
        {
            continue;
        }
        scalar rho = 0;
        vector j(Zero);
        for (label q = 0; q < Q; ++q)
        {
            f[q] = scratch_[layout_.at(q, n - offset_[q])];
            rho += f[q];
            j += f[q]*vector(c[q]);
        }
        const vector F = nodeForce(n);
        const vector u = (j + 0.5*F)/rho;
        const scalar eps = porosity_.size() ? porosity_[n] : 1.0;
        const scalar u2 = magSqr(u)/eps;

        symmTensor Pi(Zero);
        for (label q = 0; q < Q; ++q)
        {
            const vector cq(c[q]);
            const scalar cu = cq & u;
            const scalar feq =
                w[q]*rho*(1 + 3*cu + 4.5*cu*cu/eps - 1.5*u2);
            Pi += (f[q] - feq)*sqr(cq);
        }
        sigma[n] = -factor*toPa*(Pi + symm(F*u));
    }
}


void Foam::latticeBoltzmannFluid::writeViscousStress()
{
    List<symmTensor> sigma;
    viscousStress(sigma);
    writeNodeField(lattice_, "viscousStress", sigma, dimPressure, false);
}


Foam::vector Foam::latticeBoltzmannFluid::momentum() const
{
    const label Q = velocitySet_->Q();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& f = current();
    vector j(Zero);
    for (const label n : lattice_.cellNode())
    {
        if (!water(n))
        {
            continue;
        }
        for (label q = 0; q < Q; ++q)
        {
            j += f[layout_.at(q, n)]*vector(c[q]);
        }
    }
    reduce(j, sumOp<vector>());
    return j*units_.rho0()*units_.velocityScale()*lattice_.cellVolume();
}


Foam::scalar Foam::latticeBoltzmannFluid::massDefect() const
{
    // Against the initial mass plus what the displacement source added.
    // With a free surface: the liquid's populations and the interface
    // nodes' masses, summed only when asked (a pass over the populations)
    // (the free surface's water, rho - (1 - n) per liquid node, does not
    // change with the displacement source: the source raises rho as the
    // pores shrink)
    Vector2D<scalar> m
    (
        freeSurface_ ? freeSurface_->mass(current().cdata()) : stats_.mass,
        freeSurface_ ? 0 : displacedMass_
    );
    reduce(m, sumOp<Vector2D<scalar>>());
    // (no water at the start, e.g. a free surface that has none yet: 0)
    const scalar m0 = mass0_ + m.y();
    return m0 > 0 ? m.x()/m0 - 1.0 : 0;
}


Foam::scalar Foam::latticeBoltzmannFluid::memoryBytes() const
{
    return returnReduce
    (
        scalar(sizeof(scalar))
       *(
            fA_.size() + fB_.size() + 11*Fx_.size() + porosity_.size()
          + heldPorosity_.size() + displacementSource_.size()
         )
      + (freeSurface_ ? freeSurface_->memoryBytes() : 0),
        sumOp<scalar>()
    );
}


Foam::label Foam::latticeBoltzmannFluid::nNodes() const
{
    return returnReduce(lattice_.nOwned(), sumOp<label>());
}


void Foam::latticeBoltzmannFluid::updateFields()
{
    // A function object may read the fields at every step, so a refresh
    // should cost about a lattice step: written as one pass per node (its
    // nine to twenty-seven dependent additions, five divisions, and the
    // units re-read at every cell, as the stores may alias them) it cost
    // about five, and probes written every ten steps took 40% of a run.
    // Here the moments are summed direction by direction over blocks of
    // cells held in the first-level cache (independent sums the compiler
    // vectorises), and each block finished with two divisions per cell.
    const label Q = velocitySet_->Q();
    const List<labelVector>& c = velocitySet_->c();
    const labelList& cellNode = lattice_.cellNode();
    const label nCells = cellNode.size();
    const label* __restrict__ node = cellNode.cdata();
    const scalar* __restrict__ f = current().cdata();

    vectorField& U = U_.primitiveFieldRef();
    scalarField& p = p_.primitiveFieldRef();
    scalarField& rhoPhys = rho_.primitiveFieldRef();

    // Post-collision momentum is rho u + F/2. In a porous medium u is the
    // superficial velocity (the Darcy flux) and p the pore pressure
    // c_s^2 (rho - 1)/eps relative to the reference (units_.pressure, its
    // factor hoisted), with displacement the coming step's time-centred
    // one (pressureDensity)
    const scalar uScale = units_.velocityScale();
    const scalar rho0 = units_.rho0();
    const scalar pScale = rho0*sqr(uScale)/3.0;
    const scalar* __restrict__ eps =
        porosity_.size() ? porosity_.cdata() : nullptr;
    const lbmObstacles& bodies = obstacles_();
    const lbmFreeSurface* surface = freeSurface_.get();
    const scalar pGas = surface ? units_.pressure(surface->rhoGas()) : 0;

    constexpr label blockSize = 256;
    scalar rhoB[blockSize], jxB[blockSize], jyB[blockSize], jzB[blockSize];
    for (label start = 0; start < nCells; start += blockSize)
    {
        const label m = min(blockSize, nCells - start);
        const label* __restrict__ nb = node + start;
        for (label i = 0; i < m; ++i)
        {
            rhoB[i] = 0;
            jxB[i] = 0;
            jyB[i] = 0;
            jzB[i] = 0;
        }
        for (label q = 0; q < Q; ++q)
        {
            const scalar* __restrict__ fq = f + layout_.base(q);
            const scalar cx = c[q].x();
            const scalar cy = c[q].y();
            const scalar cz = c[q].z();
            for (label i = 0; i < m; ++i)
            {
                const scalar v = fq[nb[i]];
                rhoB[i] += v;
                jxB[i] += cx*v;
                jyB[i] += cy*v;
                jzB[i] += cz*v;
            }
        }
        for (label i = 0; i < m; ++i)
        {
            const label celli = start + i;
            const label n = nb[i];
            if (bodies.solid(n))
            {
                // Inside a body: no water
                U[celli] = Zero;
                p[celli] = 0;
                rhoPhys[celli] = rho0;
                continue;
            }
            if (surface && surface->gas(n))
            {
                // Gas: no water, at the gas pressure
                U[celli] = Zero;
                p[celli] = pGas;
                rhoPhys[celli] = 0;
                continue;
            }
            const scalar rho = rhoB[i];
            const scalar epsN = eps ? eps[n] : 1.0;
            U[celli] =
                (vector(jxB[i], jyB[i], jzB[i]) - 0.5*nodeForce(n))
               *(uScale/rho);
            p[celli] =
                (pressureDensity(n, rho) - 1.0)*pScale/epsN
              + hydrostaticPressure(n);
            rhoPhys[celli] = (rho - (1 - epsN))*rho0;
        }
    }

    U_.correctBoundaryConditions();
    if (boundaries_->hasAbsorbing())
    {
        // OpenFOAM's advective is not evaluated (it would need a flux
        // field): the patches take the lattice's boundary pressure
        const boolList& absorbing = boundaries_->absorbingPatches();
        volScalarField::Boundary& bf = p_.boundaryFieldRef();
        const label nReq = UPstream::nRequests();
        forAll(bf, patchi)
        {
            if (!absorbing[patchi])
            {
                bf[patchi].initEvaluate(Pstream::defaultCommsType);
            }
        }
        if
        (
            Pstream::parRun()
         && Pstream::defaultCommsType == Pstream::commsTypes::nonBlocking
        )
        {
            UPstream::waitRequests(nReq);
        }
        forAll(bf, patchi)
        {
            if (!absorbing[patchi])
            {
                bf[patchi].evaluate(Pstream::defaultCommsType);
            }
        }
        boundaries_->setAbsorbingValues(units_, p_);
    }
    else
    {
        p_.correctBoundaryConditions();
    }
    rho_.correctBoundaryConditions();
}


void Foam::latticeBoltzmannFluid::nodalVelocity
(
    List<vector>& u,
    const bool carried
) const
{
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& f = current();

    u.setSize(nBox);
    u = Zero;
    for (const label n : lattice_.cellNode())
    {
        if (!water(n))
        {
            continue;
        }
        scalar rho = 0;
        vector j(Zero);
        for (label q = 0; q < Q; ++q)
        {
            const scalar fq = f[layout_.at(q, n)];
            rho += fq;
            j += fq*vector(c[q]);
        }
        if (!carried)
        {
            j -= 0.5*nodeForce(n);
        }
        u[n] = units_.toPhysical(j/rho);
    }
}


Foam::scalar Foam::latticeBoltzmannFluid::populationSum() const
{
    if (freeSurface_)
    {
        // (the liquid's populations and the interface nodes' masses as
        // stored: what a restart reads back before the porosity of a soil
        // is mapped again, which the water's mass itself depends on)
        return freeSurface_->storedSum(current().cdata());
    }
    const label Q = velocitySet_->Q();
    const scalarList& f = current();
    scalar sum = 0;
    for (const label n : lattice_.cellNode())
    {
        if (obstacles_->solid(n))
        {
            // (a body's slots hold its walls' returning populations)
            continue;
        }
        for (label q = 0; q < Q; ++q)
        {
            sum += f[layout_.at(q, n)];
        }
    }
    return sum;
}


Foam::wordList Foam::latticeBoltzmannFluid::populationFiles() const
{
    const label Q = velocitySet_->Q();
    wordList names(Q);
    for (label q = 0; q < Q; ++q)
    {
        names[q] = "lbmF" + Foam::name(q);
    }
    if (displacement_)
    {
        names.append("lbmPorosity");
    }
    names.append("uniform/lbmHydrostatic");
    if (boundaries_->hasAbsorbing())
    {
        names.append("uniform"/outletStateFile);
    }
    if (freeSurface_)
    {
        names.append(freeSurface_->stateFiles());
    }
    return names;
}


void Foam::latticeBoltzmannFluid::writePopulations() const
{
    // The water's populations; a node without water (inside a body, or
    // gas) at rest at the reference density: its slots hold what the
    // boundaries and the streaming last left there, which no step reads
    // (a body's links are filled each step, a gas node that fills is set
    // from its neighbours), and which would differ between the layouts
    const label Q = velocitySet_->Q();
    const scalarList& w = velocitySet_->w();
    const scalarList& f = current();
    const labelList& cellNode = lattice_.cellNode();
    scalarList fq(lattice_.nBox(), 0.0);
    for (label q = 0; q < Q; ++q)
    {
        for (const label n : cellNode)
        {
            fq[n] = water(n) ? f[layout_.at(q, n)] : w[q];
        }
        writeNodeField(lattice_, "lbmF" + Foam::name(q), fq.cdata());
    }
    writeHydrostaticState();

    if (displacement_)
    {
        // The porosity the populations hold (a restart continues the
        // displacement source from it)
        writeNodeField
        (
            lattice_,
            "lbmPorosity",
            (heldPorosity_.size() ? heldPorosity_ : porosity_).cdata()
        );
    }

    if (freeSurface_)
    {
        freeSurface_->writeState();
        if (dragX_.size())
        {
            // The drag of the last step, whose half the populations carry:
            // the next step's surface takes the water's velocity less it
            // (a restart continues bit for bit)
            writeNodeField(lattice_, "lbmDragX", dragX_.cdata());
            writeNodeField(lattice_, "lbmDragY", dragY_.cdata());
            writeNodeField(lattice_, "lbmDragZ", dragZ_.cdata());
        }
    }

    if (boundaries_->hasAbsorbing())
    {
        // (every processor writes its own: a processor with no outlet link
        // an empty list)
        const fileName dir(mesh_.time().timePath()/"uniform");
        mkDir(dir);
        OFstream os(dir/outletStateFile);
        os.precision(17);
        os  << "// Boundary densities (lattice units) of the pressure links of"
            << " outlets that let waves leave" << nl
            << "rho " << boundaries_->absorbingState() << ";" << nl;
        if (!os.good())
        {
            FatalErrorInFunction
                << "Could not write " << os.name() << exit(FatalError);
        }
    }
}


// ************************************************************************* //
