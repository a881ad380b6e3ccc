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
    soilForce_.setSize(nBox, Zero);

    Info<< "Buoyancy: pore pressure on the soil -phi grad(p) and on the"
        << " water -(1 - phi) grad(p); the soil's stress is effective"
        << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::buoyancy::evolve()
{
    const latticeMesh& lattice = fluid_.lattice();
    const label nBox = lattice.nBox();
    const label Q = fluid_.velocities().Q();
    const scalarList& f = fluid_.populations();
    const scalarList& eps = fluid_.porosity();
    const List<unsigned char>& kind = lattice.kind();
    const labelList& cellNode = lattice.cellNode();

    // Absolute pore pressure c_s^2 rho/eps (lattice units)
    for (const label n : cellNode)
    {
        scalar rho = 0;
        for (label q = 0; q < Q; ++q)
        {
            rho += f[q*nBox + n];
        }
        pressure_[n] = rho/(3*eps[n]);
    }

    // Central differences between owned nodes (one-sided next to a wall
    // or a halo, whose populations are not current here): summed over the
    // nodes, p D(eps) - phi D(p) telescopes (summation by parts)
    const label nDim = lattice.nDim();
    const scalar toNewton =
        lattice.cellVolume()/fluid_.units().forceDensityToLattice();
    scalarList& Fx = fluid_.forceX();
    scalarList& Fy = fluid_.forceY();
    scalarList& Fz = fluid_.forceZ();
    soilForce_ = Zero;
    maxForce_ = 0;
    for (const label n : cellNode)
    {
        vector gradP(Zero), gradEps(Zero);
        for (direction d = 0; d < nDim; ++d)
        {
            const label off = lattice.offset(d == 0, d == 1, d == 2);
            const bool up = (kind[n + off] == latticeMesh::OWNED);
            const bool down = (kind[n - off] == latticeMesh::OWNED);
            const label hi = up ? n + off : n;
            const label lo = down ? n - off : n;
            if (hi != lo)
            {
                const scalar h = scalar(hi - lo)/off;
                gradP[d] = (pressure_[hi] - pressure_[lo])/h;
                gradEps[d] = (eps[hi] - eps[lo])/h;
            }
        }
        const vector fFluid = pressure_[n]*gradEps;
        Fx[n] = fFluid.x();
        Fy[n] = fFluid.y();
        Fz[n] = fFluid.z();
        const scalar phi = 1 - eps[n];
        if (phi > 0)
        {
            soilForce_[n] = -toNewton*phi*gradP;
            maxForce_ = max(maxForce_, mag(soilForce_[n]));
        }
    }
    soil_.addNodeForces(soilForce_);
    maxForce_ /= lattice.cellVolume();
}


Foam::scalar Foam::physicsEffects::buoyancy::memoryBytes() const
{
    return scalar(fluid_.lattice().nBox())*(sizeof(scalar) + sizeof(vector));
}


Foam::string Foam::physicsEffects::buoyancy::progress() const
{
    return
        "buoyancy up to "
      + Foam::name(returnReduce(maxForce_, maxOp<scalar>())) + " N/m3";
}


// ************************************************************************* //
