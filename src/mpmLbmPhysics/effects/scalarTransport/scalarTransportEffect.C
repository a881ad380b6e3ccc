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

#include "scalarTransportEffect.H"
#include "optionalEntry.H"
#include "freeSurfaceEffect.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(scalarTransport, 0);
    addToRunTimeSelectionTable(physicsEffect, scalarTransport, scene);
    addToMemberFunctionSelectionTable
    (
        physicsEffect,
        scalarTransport,
        haloWidth,
        mesh
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::scalarTransport::scalarTransport(physicsScene& scene)
:
    physicsEffect(scene),
    dict_
    (
        IOobject
        (
            "scalarTransportProperties",
            scene.mesh().time().constant(),
            scene.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    transport_
    (
        fluid_.lattice(),
        fluid_.units(),
        optionalEntry<word>(dict_, "field", "C"),
        dict_,
        fluid_.boundaries(),
        fluid_.U(),
        freeSurface::of(scene),
        &fluid_.obstacles()
    ),
    u_(fluid_.lattice().nBox(), Zero)
{
    if (suspensionSettling::selected(dict_))
    {
        // (the water's own viscosity unless nuFluid says otherwise: the
        // lattice's may be raised for stability, and a Stokes velocity
        // falls with it: a new user's probe, 2026-12-07, raised nu to
        // 1e-5 and settled ten times slower, unsaid)
        if (!foundEntry(dict_, "nuFluid"))
        {
            Info<< "Settling with the lattice's viscosity nu "
                << fluid_.units().nu() << " m2/s (constant/fluidProperties):"
                << " where nu was raised for stability, give the water's"
                << " as nuFluid in constant/scalarTransportProperties" << nl;
        }
        settling_.reset
        (
            new suspensionSettling
            (
                dict_,
                fluid_.units().rho0(),
                optionalEntry<scalar>(dict_, "nuFluid", fluid_.units().nu()),
                transport_
            )
        );
    }

    if (optionalEntry<bool>(dict_, "writeBalance", false))
    {
        wordList columns({"content", "sourced"});
        // (the processor patches aside: nothing crosses them)
        const polyBoundaryMesh& patches = scene.mesh().boundaryMesh();
        for (label patchi = 0; patchi < patches.nNonProcessor(); ++patchi)
        {
            columns.append("out_" + patches[patchi].name());
        }
        if (settling_.valid())
        {
            columns.append("deposited");
        }
        columns.append("defect");
        balanceFile_ = newStepFile
        (
            scene.mesh(), "scalarTransport", "balance",
            "Balance of " + transport_.field().name()
          + " [its units x m3]: content, added by sources since the"
            " case's start, out through each patch since then (negative:"
            " in), deposited at walls by settling since then (with a"
            " settlingModel), relative defect (a restart carries the"
            " totals on from the written time's uniform/"
          + transport_.field().name() + "Balance)",
            columns
        );
    }

    transport_.report(Info);
    if (settling_.valid())
    {
        settling_->model().report(Info);
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::sceneStageList Foam::physicsEffects::scalarTransport::stages() const
{
    sceneStageList joined({sceneStage::transport});
    if (balanceFile_.valid() || transport_.surface())
    {
        // (with a free surface: the scalar follows its conversions)
        joined.append(sceneStage::endStep);
    }
    return joined;
}


void Foam::physicsEffects::scalarTransport::evolve(const sceneStage stage)
{
    if (stage == sceneStage::transport)
    {
        // The water's velocity after its step (the macroscopic, Guo
        // velocity), superficial, in lattice units
        fluid_.nodalVelocity(u_);
        const lbmUnits& units = fluid_.units();
        for (vector& v : u_)
        {
            v = units.toLattice(v);
        }
        if (settling_.valid())
        {
            transport_.prepare(u_, porosity());
            settling_->update(transport_, porosity());
        }
        transport_.step(u_, porosity());
    }
    else if (stage == sceneStage::endStep)
    {
        transport_.followSurface();
        if (balanceFile_.valid())
        {
            writeBalance();
        }
    }
}


void Foam::physicsEffects::scalarTransport::writeBalance()
{
    const scalar content = transport_.content();
    const scalar sourced = transport_.sourced();
    const scalarList out = transport_.patchOutflow();
    const scalar defect = transport_.balanceDefect();
    // (collective: every processor, before the master writes)
    const scalar deposited = settling_.valid() ? transport_.deposited() : 0;
    if (balanceFile_->writeToFile())
    {
        OFstream& os = balanceFile_->file();
        balanceFile_->writeCurrentTime(os);
        os  << tab << content << tab << sourced;
        for (const scalar o : out)
        {
            os  << tab << o;
        }
        if (settling_.valid())
        {
            os  << tab << deposited;
        }
        os  << tab << defect << endl;
    }
}


Foam::string Foam::physicsEffects::scalarTransport::plan() const
{
    return
        "one lattice step per step (D" + Foam::name(fluid_.lattice().nDim())
      + "Q" + Foam::name(transport_.Q()) + ", tau "
      + Foam::name(transport_.tau()) + ")";
}


void Foam::physicsEffects::scalarTransport::updateFields()
{
    transport_.updateField(porosity());
}


void Foam::physicsEffects::scalarTransport::write()
{
    transport_.writePopulations();
}


Foam::wordList Foam::physicsEffects::scalarTransport::stateFiles() const
{
    return transport_.populationFiles();
}


Foam::scalar Foam::physicsEffects::scalarTransport::updatesPerStep() const
{
    return fluid_.nNodes();
}


Foam::scalar Foam::physicsEffects::scalarTransport::updatesDone() const
{
    return scalar(fluid_.nNodes())*transport_.nSteps();
}


Foam::scalar Foam::physicsEffects::scalarTransport::memoryBytes() const
{
    return
        transport_.memoryBytes()
      + returnReduce
        (
            scalar(u_.byteSize())
          + (settling_.valid() ? settling_->memoryBytes() : 0),
            sumOp<scalar>()
        );
}


Foam::string Foam::physicsEffects::scalarTransport::progress() const
{
    return
        transport_.field().name() + " balance defect "
      + Foam::name(transport_.balanceDefect())
      + ", min " + Foam::name(transport_.minPhi());
}


// ************************************************************************* //
