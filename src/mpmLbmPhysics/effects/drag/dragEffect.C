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

#include "dragEffect.H"
#include "optionalEntry.H"
#include "lbmFreeSurface.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "soilEffect.H"
#include "dragRelaxation.H"
#include "selectEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(drag, 0);
    addToRunTimeSelectionTable(physicsEffect, drag, scene);
    addToMemberFunctionSelectionTable(physicsEffect, drag, haloWidth, mesh);
}
}

const Foam::Enum<Foam::physicsEffects::drag::couplingType>
Foam::physicsEffects::drag::couplingTypeNames
({
    { couplingType::oneWay, "oneWay" },
    { couplingType::twoWay, "twoWay" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The coupling dictionary with the water's density and (unless given) its
// viscosity, as the drag model reads them
Foam::dictionary dragDict
(
    const Foam::dictionary& coupling,
    const Foam::latticeBoltzmannFluid& fluid
)
{
    Foam::dictionary d(coupling);
    d.set("rhoFluid", fluid.units().rho0());
    if (!foundEntry(d, "muFluid"))
    {
        d.add("muFluid", fluid.units().rho0()*fluid.units().nu());
    }
    return d;
}


// constant/dragProperties, after refusing a case that still has the file
// under its old name (it would otherwise be silently ignored)
Foam::IOobject dragPropertiesIO(const Foam::fvMesh& mesh)
{
    using namespace Foam;
    IOobject oldIO
    (
        "couplingProperties",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (oldIO.typeHeaderOk<IOdictionary>(true))
    {
        FatalIOErrorInFunction(IOdictionary(oldIO))
            << "constant/couplingProperties is the old name of the drag's"
            << " dictionary: rename it to constant/dragProperties (effect"
            << " <name> reads constant/<name>Properties)"
            << exit(FatalIOError);
    }
    oldIO.rename("dragProperties");
    return oldIO;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::drag::drag(physicsScene& scene)
:
    physicsEffect(scene),
    dict_(dragPropertiesIO(scene.mesh())),
    coupling_(selectEntry(couplingTypeNames, "drag", dict_)),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    soil_(scene.effect<physicsEffects::soil>("soil")),
    model_(dragModel::New(dragDict(dict_, fluid_))),
    deltaT_(0),
    maxForce_(0)
{
    fluid_.enableForceField();

    if (twoWay())
    {
        // The water collides with the impulse the soil exchanged with it
        // in its sub-steps
        fluid_.enableGivenDrag();
        soil_.mpm().setGridExchange(*this);
        if (optionalEntry<bool>(dict_, "writeMomentum", false))
        {
            wordList columns;
            for (const char* phase : {"water", "soil", "total"})
            {
                for (const char* xyz : {"X", "Y", "Z"})
                {
                    columns.append(word(phase) + xyz);
                }
            }
            momentumFile_ = newStepFile
            (
                scene.mesh(), "momentumBalance", "momentum",
                "Momentum of the water, the soil and both [kg m/s]", columns
            );
            writeMomentum();
        }
    }

    Info<< "Drag between soil and water: " << couplingTypeNames[coupling_];
    if (twoWay())
    {
        Info<< " (exchanged exactly in each of the soil's sub-steps, with"
            << " the water streamed into its nodes; the water collides with"
            << " the opposite impulse)";
    }
    Info<< nl;
    model_->report(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::sceneStageList Foam::physicsEffects::drag::stages() const
{
    sceneStageList joined({sceneStage::exchange});
    if (momentumFile_.valid())
    {
        joined.append(sceneStage::endStep);
    }
    return joined;
}


void Foam::physicsEffects::drag::evolve(const sceneStage stage)
{
    switch (stage)
    {
        case sceneStage::exchange: mapExchange(); break;
        case sceneStage::endStep: writeMomentum(); break;
        default: break;
    }
}


void Foam::physicsEffects::drag::writeMomentum()
{
    // Collective (the momenta are sums over the processors)
    const vector water = fluid_.momentum();
    const vector soil = soil_.mpm().momentum();
    if (momentumFile_->writeToFile())
    {
        OFstream& os = momentumFile_->file();
        momentumFile_->writeCurrentTime(os);
        for (const vector& v : {water, soil, water + soil})
        {
            os  << tab << v.x() << tab << v.y() << tab << v.z();
        }
        os  << endl;
    }
}


void Foam::physicsEffects::drag::mapExchange()
{
    const scalarList& phi = soil_.solidFraction();
    const List<vector>& soilVelocity = soil_.nodeVelocity();
    fluid_.nodalVelocity(fluidVelocity_, true);

    const lbmUnits& units = fluid_.units();
    const scalar dt = units.dt();
    const scalar rhoF = units.rho0();
    const bool porous = fluid_.porous();

    // With a free surface the drag acts only where there is water: in an
    // interface node on its fill level's share of the node (the soil there
    // feels fill times the drag of a full node; the water's own momentum
    // is fill times the lattice node's, so its velocity changes as in a
    // full node), not at all in the gas (dry soil)
    const lbmFreeSurface* fs = fluid_.freeSurface();

    nodes_.clear();
    beta_.clear();
    eps_.clear();
    fill_.clear();
    maxForce_ = 0;
    for (const label n : fluid_.lattice().cellNode())
    {
        // (below a thousandth of a node's water, none: the exchange
        // divides by the water's mass)
        const scalar fill = (fs ? fs->fill(n) : 1);
        if (phi[n] <= 0 || fill < 1e-3)
        {
            if (!twoWay())
            {
                fluid_.clearRelaxation(n);
            }
            continue;
        }

        // The water's mass per volume (porous flow: the pores' share) and
        // its velocity in the pores (the lattice's is superficial there)
        const scalar eps = 1 - phi[n];
        const scalar mF = porous ? eps*rhoF : rhoF;
        const vector vF =
            porous ? fluidVelocity_[n]/eps : fluidVelocity_[n];
        const vector slip = soilVelocity[n] - vF;
        const scalar beta = model_->beta(phi[n], mag(slip));
        maxForce_ = max(maxForce_, beta*mag(slip));

        if (twoWay())
        {
            // Exchanged in the soil's sub-steps (begin, exchange, end)
            nodes_.append(n);
            beta_.append(beta);
            eps_.append(porous ? eps : 1);
            fill_.append(fill);
            continue;
        }

        const scalar a = beta*dt/mF;
        const dragRelaxation relax = dragRelaxation::oneWay(a);

        // (porous: towards the superficial velocity eps v_s)
        fluid_.setRelaxation
        (
            n,
            relax.kappa(),
            relax.s(),
            units.toLattice(porous ? eps*soilVelocity[n] : soilVelocity[n])
        );
    }
}


void Foam::physicsEffects::drag::begin(const scalar deltaT)
{
    // The water streamed into each node with soil (the fluid's
    // streamPrepare has completed its populations): as the lattice's
    // relaxation takes it (lbmKernel.H), its momentum q0 = (p + j)/2 and
    // the impulse of its step other than the drag G = (j - p) + F_o, in
    // lattice units; here in SI per node. The lattice's momentum density
    // rho u (u superficial with porousFlow) is the water's mass per volume
    // eps rho0 rho times its velocity in the pores u/eps, and the drag of
    // the relaxation, beta/(eps rho0) (rho eps v_s - rho u), is
    // beta rho (v_s - u/eps): the coefficient beta rho, as one-way, so
    // that a steady state is the same
    const lbmUnits& units = fluid_.units();
    const scalar V = fluid_.lattice().cellVolume();
    // An impulse density of the lattice [lattice units per step] as a
    // force on the node over the step [N]
    const scalar toForce = V/units.forceDensityToLattice();
    const label nNodes = nodes_.size();

    deltaT_ = deltaT;
    C_.setSize(nNodes);
    waterMass_.setSize(nNodes);
    waterVelocity_.setSize(nNodes);
    waterForce_.setSize(nNodes);
    impulse_.setSize(nNodes);
    forAll(nodes_, k)
    {
        scalar rho;
        vector j, p, Fo;
        fluid_.streamedState(nodes_[k], rho, j, p, Fo);
        const scalar eps = eps_[k];
        const scalar fill = fill_[k];
        C_[k] = fill*beta_[k]*rho*V;
        waterMass_[k] = fill*eps*units.rho0()*rho*V;
        waterVelocity_[k] = units.toPhysical(0.5*(p + j)/rho)/eps;
        waterForce_[k] = (fill*toForce)*((j - p) + Fo);
        impulse_[k] = Zero;
    }
}


void Foam::physicsEffects::drag::exchange
(
    const scalar dt,
    const scalarList& mass,
    const List<vector>& velocity,
    List<vector>& force
)
{
    // Each node's soil and water exchange the drag over the sub-step as
    // two bodies, each with its other forces held over it
    // (dragRelaxation::twoBodyImpulse); the soil takes the opposite
    // impulse as a force over the sub-step
    forAll(nodes_, k)
    {
        const label n = nodes_[k];
        const scalar mF = waterMass_[k];
        const scalar mS = mass[n];
        vector J(Zero);
        if (mS > VSMALL)
        {
            J = dragRelaxation::twoBodyImpulse
            (
                C_[k],
                mS,
                mF,
                waterVelocity_[k] - velocity[n],
                waterForce_[k]/mF - force[n]/mS,
                dt
            );
            force[n] -= J/dt;
            impulse_[k] += J;
        }
        waterVelocity_[k] += (dt*waterForce_[k] + J)/mF;
    }
}


void Foam::physicsEffects::drag::end()
{
    // The impulse each node's water received, as the lattice's impulse
    // density of the step: it collides with it (given drag), exactly the
    // opposite of what the soil received
    const lbmUnits& units = fluid_.units();
    const scalar toImpulse =
        deltaT_*fluid_.lattice().cellVolume()/units.forceDensityToLattice();
    for (const label n : fluid_.lattice().cellNode())
    {
        fluid_.setDragImpulse(n, Zero);
    }
    forAll(nodes_, k)
    {
        // (on the lattice node, whose momentum is that of a full node)
        fluid_.setDragImpulse(nodes_[k], impulse_[k]/(toImpulse*fill_[k]));
    }
}


Foam::scalar Foam::physicsEffects::drag::memoryBytes() const
{
    // With the soil's solid fraction and velocity per node it maps;
    // twoWay: per node with soil (at most every node) five scalars and
    // three vectors
    return
        scalar(fluid_.lattice().nBox())
       *(
            sizeof(scalar) + 2*sizeof(vector)
          + (twoWay() ? 5*sizeof(scalar) + 3*sizeof(vector) : 0)
        );
}


Foam::string Foam::physicsEffects::drag::progress() const
{
    return
        "drag force up to "
      + Foam::name(returnReduce(maxForce_, maxOp<scalar>())) + " N/m3";
}


// ************************************************************************* //
