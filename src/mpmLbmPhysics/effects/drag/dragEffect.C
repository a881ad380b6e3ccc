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

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::drag::drag(physicsScene& scene)
:
    physicsEffect(scene),
    dict_
    (
        IOobject
        (
            "couplingProperties",
            scene.mesh().time().constant(),
            scene.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    coupling_(couplingType::oneWay),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    soil_(scene.effect<physicsEffects::soil>("soil").mpm()),
    model_(dragModel::New(dragDict(dict_, fluid_))),
    maxForce_(0)
{
    const word type(dict_.get<word>("drag"));
    if (!couplingTypeNames.found(type))
    {
        FatalIOErrorInFunction(dict_)
            << "drag " << type << " is not allowed: choose one of "
            << couplingTypeNames.sortedToc() << exit(FatalIOError);
    }
    coupling_ = couplingTypeNames[type];
    if (coupling_ == couplingType::twoWay)
    {
        FatalIOErrorInFunction(dict_)
            << "drag twoWay is not available yet in this version: use oneWay"
            << " (the soil moves the water)" << exit(FatalIOError);
    }
    fluid_.enableForceField();

    Info<< "Drag between soil and water: " << couplingTypeNames[coupling_]
        << nl;
    model_->report(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::drag::evolve()
{
    soil_.nodalFields(phi_, soilVelocity_);
    fluid_.nodalVelocity(fluidVelocity_, true);

    const lbmUnits& units = fluid_.units();
    const scalar dt = units.dt();
    const scalar rhoF = units.rho0();
    scalarList& k = fluid_.relaxCoefficient();
    scalarList& Ux = fluid_.relaxUx();
    scalarList& Uy = fluid_.relaxUy();
    scalarList& Uz = fluid_.relaxUz();

    // The lattice relaxes each node's streamed momentum j towards rho v_s by
    // the implicit fraction a/(1 + a) in the collision itself (no lag
    // behind the streaming, which made an explicit force oscillate)
    maxForce_ = 0;
    for (const label n : fluid_.lattice().cellNode())
    {
        if (phi_[n] <= 0)
        {
            k[n] = 0;
            continue;
        }
        const vector slip = soilVelocity_[n] - fluidVelocity_[n];
        const scalar beta = model_->beta(phi_[n], mag(slip));
        const scalar a = beta*dt/rhoF;
        k[n] = a/(1 + a);
        const vector vs = units.toLattice(soilVelocity_[n]);
        Ux[n] = vs.x();
        Uy[n] = vs.y();
        Uz[n] = vs.z();
        maxForce_ = max(maxForce_, (rhoF/dt)*k[n]*mag(slip));
    }
}


Foam::scalar Foam::physicsEffects::drag::memoryBytes() const
{
    return
        scalar(fluid_.lattice().nBox())
       *(sizeof(scalar) + 2*sizeof(vector) + 3*sizeof(scalar));
}


Foam::string Foam::physicsEffects::drag::progress() const
{
    return
        "drag force up to "
      + Foam::name(returnReduce(maxForce_, maxOp<scalar>())) + " N/m3";
}


// ************************************************************************* //
