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
    if (!d.found("muFluid"))
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
    maxForce_(0)
{
    fluid_.enableForceField();

    if (twoWay())
    {
        nodeForce_.setSize(fluid_.lattice().nBox(), Zero);
        if (dict_.getOrDefault<bool>("writeMomentum", false))
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
        Info<< " (the soil advances after the water and receives its"
            << " reaction)";
    }
    Info<< nl;
    model_->report(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::sceneStageList Foam::physicsEffects::drag::stages() const
{
    sceneStageList joined({sceneStage::exchange});
    if (twoWay())
    {
        joined.append(sceneStage::lateExchange);
    }
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
        case sceneStage::exchange: exchange(); break;
        case sceneStage::lateExchange: lateExchange(); break;
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


void Foam::physicsEffects::drag::exchange()
{
    const scalarList& phi = soil_.solidFraction();
    const List<vector>& soilVelocity = soil_.nodeVelocity();
    const scalarList& soilMass = soil_.nodeMass();
    fluid_.nodalVelocity(fluidVelocity_, true);

    const lbmUnits& units = fluid_.units();
    const scalar dt = units.dt();
    const scalar rhoF = units.rho0();
    const scalar Vnode = fluid_.lattice().cellVolume();
    const bool porous = fluid_.porous();

    maxForce_ = 0;
    for (const label n : fluid_.lattice().cellNode())
    {
        if (phi[n] <= 0)
        {
            fluid_.clearRelaxation(n);
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
        const scalar a = beta*dt/mF;

        const dragRelaxation relax =
            twoWay()
          ? dragRelaxation::twoWay(a, soilMass[n]/Vnode, mF)
          : dragRelaxation::oneWay(a);

        // (porous: towards the superficial velocity eps v_s)
        fluid_.setRelaxation
        (
            n,
            relax.kappa(),
            relax.s(),
            units.toLattice(porous ? eps*soilVelocity[n] : soilVelocity[n])
        );
        maxForce_ = max(maxForce_, beta*mag(slip));
    }
}


void Foam::physicsEffects::drag::lateExchange()
{
    // The impulse density the lattice gave the water at each node this
    // step, reversed, as a force on the node over the step [N]
    const scalarList& phi = soil_.solidFraction();
    const lbmUnits& units = fluid_.units();
    const scalar toForce =
        fluid_.lattice().cellVolume()/units.forceDensityToLattice();
    nodeForce_ = Zero;
    for (const label n : fluid_.lattice().cellNode())
    {
        if (phi[n] > 0)
        {
            nodeForce_[n] = -toForce*fluid_.dragImpulse(n);
        }
    }
    soil_.addNodeForces(nodeForce_);
}


Foam::scalar Foam::physicsEffects::drag::memoryBytes() const
{
    // With the soil's solid fraction and velocity per node it maps
    return
        scalar(fluid_.lattice().nBox())
       *(sizeof(scalar) + (twoWay() ? 3 : 2)*sizeof(vector));
}


Foam::string Foam::physicsEffects::drag::progress() const
{
    return
        "drag force up to "
      + Foam::name(returnReduce(maxForce_, maxOp<scalar>())) + " N/m3";
}


// ************************************************************************* //
