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

#include "buoyancyEffect.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "soilEffect.H"
#include "porousFlowEffect.H"
#include "dragEffect.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(buoyancy, 0);
    addToRunTimeSelectionTable(physicsEffect, buoyancy, scene);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::buoyancy::buoyancy(physicsScene& scene)
:
    physicsEffect(scene),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    soil_(scene.effect<physicsEffects::soil>("soil").mpm()),
    maxForce_(0)
{
    if (!scene.effect<physicsEffects::drag>("drag").twoWay())
    {
        FatalErrorInFunction
            << "buoyancy needs drag twoWay (constant/couplingProperties):"
            << " with oneWay the water does not act on the soil"
            << exit(FatalError);
    }
    if
    (
        scene.has("porousFlow")
     && scene.effect<physicsEffects::porousFlow>("porousFlow").medium()
     != physicsEffects::porousFlow::mediumType::soil
    )
    {
        FatalErrorInFunction
            << "buoyancy needs porousFlow with medium soil (the soil's"
            << " porosity on the lattice), not a fixed medium"
            << exit(FatalError);
    }
    fluid_.enableForceField();
    const label nBox = fluid_.lattice().nBox();
    pressure_.setSize(nBox, 0.0);
    porosity_.setSize(nBox, 1.0);
    soilForce_.setSize(nBox, Zero);

    Info<< "Buoyancy: pore pressure on the soil -phi grad(p) and on the"
        << " water -(1 - phi) grad(p); the soil's stress is effective" << nl;

    // The pore water stiffens the soil: under a fast load it cannot drain
    // and the skeleton's p-wave modulus M becomes Biot's undrained M + K_f/n
    // (incompressible grains), with K_f = rho c_s^2 the lattice water's
    // bulk modulus. The soil's explicit step must resolve that wave.
    // The pressure reaches the soil once per water step and stays constant
    // over its sub-steps: measured on a submerged bed (tests/validation/
    // submergedBed), the soil with K_f/n still grew unstable after 3 s at
    // CFL 0.5 and was stable with about half that step, so 4 K_f/n is used.
    const lbmUnits& units = fluid_.units();
    const scalar Kf = units.rho0()*sqr(units.soundSpeed());
    const scalar nMin = max(soil_.minPorosity(), 0.01);
    soil_.addModulus(4*Kf/nMin, "the undrained pore water (4 K_f/n)");
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::buoyancy::evolve()
{
    const latticeMesh& lattice = fluid_.lattice();
    const label nBox = lattice.nBox();
    const velocitySet& vs = fluid_.velocities();
    const label Q = vs.Q();
    const List<labelVector>& c = vs.c();
    const scalarList& w = vs.w();
    const scalarList& f = fluid_.populations();
    const scalarList& eps = fluid_.porosity();
    const List<unsigned char>& kind = lattice.kind();
    const labelList& cellNode = lattice.cellNode();

    // Pore pressure c_s^2 (rho - 1)/n (lattice units, relative to the
    // reference) and the porosity, with their halo images
    for (const label n : cellNode)
    {
        scalar rho = 0;
        for (label q = 0; q < Q; ++q)
        {
            rho += f[q*nBox + n];
        }
        pressure_[n] = (rho - 1)/(3*eps[n]);
        porosity_[n] = eps[n];
    }
    lattice.halo().exchange(pressure_.data(), 1, nBox);
    lattice.halo().exchange(porosity_.data(), 1, nBox);

    // The streaming of a water at rest gives node n the impulse
    // sum_q w_q c_q rho(n - c_q) = -grad(c_s^2 rho) = -grad(n p): the
    // lattice's own gradient stencil. With the same stencil,
    //     D(p)  = 3 sum_q w_q c_q p(n - c_q)                  = -grad(p)
    //     F_w   = 3 sum_q w_q c_q p(n - c_q) (n(n) - n(n - c_q))
    // so that the water feels exactly n(n) D(p) = -n grad(p), and the soil
    // phi D(p) = -phi grad(p). A wall mirrors the node (as bounce-back does
    // for a water at rest). Summed over the nodes the two telescope:
    // momentum is conserved.
    labelList offset(Q);
    forAll(c, q)
    {
        offset[q] = lattice.offset(c[q].x(), c[q].y(), c[q].z());
    }
    const scalar toNewton =
        lattice.cellVolume()/fluid_.units().forceDensityToLattice();
    scalarList& Fx = fluid_.forceX();
    scalarList& Fy = fluid_.forceY();
    scalarList& Fz = fluid_.forceZ();
    soilForce_ = Zero;
    maxForce_ = 0;
    for (const label n : cellNode)
    {
        vector D(Zero), Fw(Zero);
        for (label q = 0; q < Q; ++q)
        {
            label m = n - offset[q];
            const unsigned char k = kind[m];
            if (k != latticeMesh::OWNED && k != latticeMesh::HALO)
            {
                m = n;
            }
            const vector wc = (3*w[q]*pressure_[m])*vector(c[q]);
            D += wc;
            Fw += wc*(porosity_[n] - porosity_[m]);
        }
        Fx[n] = Fw.x();
        Fy[n] = Fw.y();
        Fz[n] = Fw.z();
        const scalar phi = 1 - porosity_[n];
        if (phi > 0)
        {
            soilForce_[n] = (toNewton*phi)*D;
            maxForce_ = max(maxForce_, mag(soilForce_[n]));
        }
    }
    soil_.addNodeForces(soilForce_);
    maxForce_ /= lattice.cellVolume();
}


Foam::scalar Foam::physicsEffects::buoyancy::memoryBytes() const
{
    return scalar(fluid_.lattice().nBox())*(2*sizeof(scalar) + sizeof(vector));
}


Foam::string Foam::physicsEffects::buoyancy::progress() const
{
    return
        "buoyancy up to "
      + Foam::name(returnReduce(maxForce_, maxOp<scalar>())) + " N/m3";
}


// ************************************************************************* //
