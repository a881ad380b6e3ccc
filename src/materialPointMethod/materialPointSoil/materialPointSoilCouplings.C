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

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// What the couplings (drag, buoyancy, loads, erosion) read from the soil's
// grid and put on its points and sub-steps

void Foam::materialPointSoil::nodalFields
(
    scalarList& phi,
    List<vector>& velocity
)
{
    const label nBox = lattice_.nBox();
    phi.setSize(nBox);
    velocity.setSize(nBox);
    phi = 0;
    velocity = Zero;
    scalarList& mass = nodeMass_;
    mass.setSize(nBox);
    mass = 0;

    if (periodic_)
    {
        checkPeriodicReach();
    }
    forAll(points_.x, p)
    {
        const scalar Vs = points_.V[p]*(1 - points_.porosity[p]);
        const scalar mp = points_.m[p];
        const vector& vp = points_.v[p];
        shapeWeights sw;
        pointWeights(p, sw);
        sw.forEachNode
        (
            [&](label i, label j, label k, scalar N, const vector&)
            {
                const label n = lattice_.node(i, j, k);
                phi[n] += N*Vs;
                mass[n] += N*mp;
                velocity[n] += N*mp*vp;
            }
        );
    }
    // What the points gave the nodes beyond walls belongs, mirrored, to the
    // nodes inside (as in the soil's own transfers): without this the
    // solid fraction would dip at every wall
    walls_->fold(velocity, mass, walls_->wholeBox());
    walls_->fold(phi, walls_->wholeBox());

    // Parallel: the halo nodes' shares to their owners
    const bool parallel = Pstream::parRun();
    if (parallel)
    {
        lattice_.halo().addToOwners
        ({
            haloExchange::field(phi),
            haloExchange::field(mass),
            haloExchange::field(velocity)
        });
    }

    const scalar invV = 1.0/lattice_.cellVolume();
    forAll(phi, n)
    {
        phi[n] = min(phi[n]*invV, 0.99);
        velocity[n] = mass[n] > VSMALL ? velocity[n]/mass[n] : Zero;
    }

    // ... and the totals back into the halo: addNodeForces shares a halo
    // node's force by its total mass
    if (parallel)
    {
        lattice_.halo().copyToHalo
        ({
            haloExchange::field(phi),
            haloExchange::field(mass),
            haloExchange::field(velocity)
        });
    }
}


void Foam::materialPointSoil::preparePointForces()
{
    // (sized to the points of now: removed or arrived points since the
    // last step reset them; the forces of this step are added after)
    if (!hasPointForces_ || pointForce_.size() != points_.size())
    {
        pointForce_.setSize(points_.size());
        pointForce_ = Zero;
    }
    hasPointForces_ = true;
    if (hasPointStresses_ && pointStress_.size() != points_.size())
    {
        pointStress_.setSize(points_.size());
        pointStress_ = Zero;
    }
}


Foam::List<Foam::vector>* Foam::materialPointSoil::travellingForces()
{
    return hasPointForces_ && pointForce_.size() ? &pointForce_ : nullptr;
}


Foam::List<Foam::symmTensor>* Foam::materialPointSoil::travellingStresses()
{
    return
        hasPointStresses_ && pointStress_.size() ? &pointStress_ : nullptr;
}


void Foam::materialPointSoil::addNodeForces(const List<vector>& nodeForce)
{
    // Each node's force goes to the points in proportion to the mass they
    // gave it, N m_p/m_n, with the weights of nodalFields (the points have
    // not moved since): the shares of a node sum to one, so the points
    // receive exactly the total force, and through P2G, the grid update
    // and G2P the impulse dt sum(f) reaches the points' momentum exactly
    // (partition of unity)
    preparePointForces();

    // Parallel: the points near a processor boundary take shares of the
    // neighbour's nodes, whose forces are copied into the halo
    List<vector> haloForce;
    if (Pstream::parRun())
    {
        haloForce = nodeForce;
        lattice_.halo().copyToHalo({haloExchange::field(haloForce)});
    }
    const List<vector>& force = Pstream::parRun() ? haloForce : nodeForce;

    // (a point's weight on a node beyond a wall was folded into the node
    // inside: it takes its share of that node's force through it; in
    // parallel that node may be a halo node)
    forAll(points_.x, p)
    {
        const scalar mp = points_.m[p];
        vector f(Zero);
        shapeWeights sw;
        pointWeights(p, sw);
        sw.forEachNode
        (
            [&](label i, label j, label k, scalar N, const vector&)
            {
                const label n = walls_->image(lattice_.node(i, j, k));
                if (nodeMass_[n] > 0)
                {
                    f += (N*mp/nodeMass_[n])*force[n];
                }
            }
        );
        pointForce_[p] += f;
    }
}


void Foam::materialPointSoil::addPointTractions
(
    const UList<label>& pointIndices,
    const vector& f,
    const symmTensor& s
)
{
    hasPointStresses_ = true;
    preparePointForces();
    for (const label p : pointIndices)
    {
        pointForce_[p] += f;
        pointStress_[p] += s;
    }
}


void Foam::materialPointSoil::clearPointForces()
{
    pointForce_ = Zero;
    pointStress_ = Zero;
}


void Foam::materialPointSoil::setGridExchange(soilGridExchange& exchange)
{
    if (gridExchange_ && gridExchange_ != &exchange)
    {
        FatalErrorInFunction
            << "The soil exchanges momentum with one coupling in its"
            << " sub-steps; a second one asked to" << abort(FatalError);
    }
    gridExchange_ = &exchange;
}


void Foam::materialPointSoil::addModulus(const scalar K, const word& why)
{
    addedModulus_ += K;
    Info<< "    soil stable time step with " << why << ": "
        << stableDt() << " s (added modulus " << K << " Pa)" << nl;
}


// ************************************************************************* //
