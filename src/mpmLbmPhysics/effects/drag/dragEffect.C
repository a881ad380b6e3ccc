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
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(drag, 0);
    addToRunTimeSelectionTable(physicsEffect, drag, scene);
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
    coupling_(couplingType::oneWay),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    soil_(scene.effect<physicsEffects::soil>("soil").mpm()),
    model_(dragModel::New(dragDict(dict_, fluid_))),
    maxForce_(0),
    writeMomentum_(false)
{
    const word type(dict_.get<word>("drag"));
    if (!couplingTypeNames.found(type))
    {
        FatalIOErrorInFunction(dict_)
            << "drag " << type << " is not allowed: choose one of "
            << couplingTypeNames.sortedToc() << exit(FatalIOError);
    }
    coupling_ = couplingTypeNames[type];
    fluid_.enableForceField();

    if (twoWay())
    {
        scene.effect<physicsEffects::soil>("soil").advanceAfterWater();
        nodeForce_.setSize(fluid_.lattice().nBox(), Zero);
        writeMomentum_ = dict_.getOrDefault<bool>("writeMomentum", false);
        if (writeMomentum_)
        {
            const fileName dir
            (
                scene.mesh().time().globalPath()/"postProcessing"
               /"momentumBalance"
            );
            if (Pstream::master())
            {
                mkDir(dir);
                momentumFile_.reset(new OFstream(dir/"momentum.dat"));
                momentumFile_()
                    << "# time waterX waterY waterZ soilX soilY soilZ"
                    << " totalX totalY totalZ [kg m/s]" << nl;
                momentumFile_().precision(17);
            }
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

void Foam::physicsEffects::drag::writeMomentum()
{
    const vector water = fluid_.momentum();
    const vector soil = soil_.momentum();
    if (momentumFile_.valid())
    {
        OFstream& os = momentumFile_();
        os  << scene_.mesh().time().value();
        for (const vector& v : {water, soil, water + soil})
        {
            os  << ' ' << v.x() << ' ' << v.y() << ' ' << v.z();
        }
        os  << nl;
        os.flush();
    }
}


void Foam::physicsEffects::drag::evolve()
{
    soil_.nodalFields(phi_, soilVelocity_);
    fluid_.nodalVelocity(fluidVelocity_, true);

    const lbmUnits& units = fluid_.units();
    const scalar dt = units.dt();
    const scalar rhoF = units.rho0();
    const scalar Vnode = fluid_.lattice().cellVolume();
    const bool porous = fluid_.porous();
    const scalarList& soilMass = soil_.nodeMass();

    scalarList& kappa = fluid_.relaxCoefficient();
    scalarList& s = fluid_.relaxS();
    scalarList& Ux = fluid_.relaxUx();
    scalarList& Uy = fluid_.relaxUy();
    scalarList& Uz = fluid_.relaxUz();

    // Porous flow: the water fills the soil's pores
    if (porous)
    {
        scalarList& eps = porosity_;
        eps.setSize(phi_.size());
        forAll(eps, n)
        {
            eps[n] = 1 - phi_[n];
        }
        if (fluid_.displacement())
        {
            // The fall of the porosity the soil's coming step will make,
            // -dt div(phi v_s) (central differences; no flux through a
            // wall), given to the water ahead of it
            const latticeMesh& lattice = fluid_.lattice();
            const List<unsigned char>& kind = lattice.kind();
            const labelVector& stride = lattice.stride();
            const scalar c = dt/(2*lattice.dx());
            predictedFall_.setSize(phi_.size());
            predictedFall_ = 0;
            for (const label n : lattice.cellNode())
            {
                scalar div = 0;
                for (direction a = 0; a < lattice.nDim(); ++a)
                {
                    const scalar own = phi_[n]*soilVelocity_[n][a];
                    const label up = n + stride[a];
                    const label down = n - stride[a];
                    const scalar fUp =
                        kind[up] == latticeMesh::WALL
                      ? -own : phi_[up]*soilVelocity_[up][a];
                    const scalar fDown =
                        kind[down] == latticeMesh::WALL
                      ? -own : phi_[down]*soilVelocity_[down][a];
                    div += fUp - fDown;
                }
                predictedFall_[n] = -c*div;
            }
            fluid_.setPorosity(eps, &predictedFall_);
        }
        else
        {
            fluid_.setPorosity(eps);
        }
    }

    maxForce_ = 0;
    for (const label n : fluid_.lattice().cellNode())
    {
        if (phi_[n] <= 0)
        {
            kappa[n] = 0;
            s[n] = 1;
            Ux[n] = Uy[n] = Uz[n] = 0;
            continue;
        }

        // The water's mass per volume (porous flow: the pores' share) and
        // its velocity in the pores (the lattice's is superficial there)
        const scalar eps = 1 - phi_[n];
        const scalar mF = porous ? eps*rhoF : rhoF;
        const vector vF =
            porous ? fluidVelocity_[n]/eps : fluidVelocity_[n];
        const vector slip = soilVelocity_[n] - vF;
        const scalar beta = model_->beta(phi_[n], mag(slip));
        const scalar a = beta*dt/mF;

        scalar k;
        if (twoWay())
        {
            // Relative velocity decays by exp(-beta dt (1/mS + 1/mF)); the
            // water takes the soil's share mS/(mS + mF) of it
            const scalar mS = soilMass[n]/Vnode;
            k = -std::expm1(-a*(1 + mF/mS))*mS/(mS + mF);
        }
        else
        {
            k = -std::expm1(-a);
        }
        kappa[n] = k;
        s[n] = a > SMALL ? k/a : 1;

        // (porous: towards the superficial velocity eps v_s)
        const vector Ur =
            units.toLattice(porous ? eps*soilVelocity_[n] : soilVelocity_[n]);
        Ux[n] = Ur.x();
        Uy[n] = Ur.y();
        Uz[n] = Ur.z();
        maxForce_ = max(maxForce_, beta*mag(slip));
    }
}


void Foam::physicsEffects::drag::evolveLate()
{
    // The impulse density the lattice gave the water at each node this
    // step, reversed, as a force on the node over the step [N]
    const lbmUnits& units = fluid_.units();
    const scalar toForce =
        fluid_.lattice().cellVolume()/units.forceDensityToLattice();
    nodeForce_ = Zero;
    for (const label n : fluid_.lattice().cellNode())
    {
        if (phi_[n] > 0)
        {
            nodeForce_[n] = -toForce*fluid_.dragImpulse(n);
        }
    }
    soil_.addNodeForces(nodeForce_);
}


void Foam::physicsEffects::drag::endStep()
{
    if (writeMomentum_)
    {
        writeMomentum();
    }
}


Foam::scalar Foam::physicsEffects::drag::memoryBytes() const
{
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
