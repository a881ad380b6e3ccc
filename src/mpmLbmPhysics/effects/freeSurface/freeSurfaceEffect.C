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

#include "freeSurfaceEffect.H"
#include "optionalEntry.H"
#include "selectEntry.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "porousFlowEffect.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(freeSurface, 0);
    addToRunTimeSelectionTable(physicsEffect, freeSurface, scene);
    addToMemberFunctionSelectionTable
    (
        physicsEffect, freeSurface, haloWidth, mesh
    );
}
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::label Foam::physicsEffects::freeSurface::haloWidth(const fvMesh& mesh)
{
    const IOdictionary dict(dictIO(mesh));
    return (optionalEntry<scalar>(dict, "surfaceTension", 0) > 0 ? 2 : 1);
}


const Foam::lbmFreeSurface* Foam::physicsEffects::freeSurface::of
(
    physicsScene& scene
)
{
    if (!scene.has("freeSurface"))
    {
        return nullptr;
    }
    return scene.effect<freeSurface>("freeSurface").fluid_.freeSurface();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::IOobject Foam::physicsEffects::freeSurface::dictIO
(
    const fvMesh& mesh
)
{
    return IOobject
    (
        "freeSurfaceProperties",
        mesh.time().constant(),
        mesh,
        IOobject::READ_IF_PRESENT,
        IOobject::NO_WRITE
    );
}


void Foam::physicsEffects::freeSurface::checkAlpha() const
{
    const fileName file(alpha_.objectPath());
    label nLiquid = 0;
    forAll(alpha_, celli)
    {
        const scalar a = alpha_[celli];
        if (!(a >= 0 && a <= 1))
        {
            FatalErrorInFunction
                << "alpha.water in " << file << " is " << a << " in cell "
                << celli << " at " << alpha_.mesh().C()[celli] << nl
                << "    The liquid fraction must lie in [0, 1] (1 water,"
                << " 0 gas): set it with setFields or setExprFields"
                << exit(FatalError);
        }
        // (as the surface sets its nodes: round-off above 0 is gas)
        if (a > lbmFreeSurface::alphaRoundOff)
        {
            ++nLiquid;
        }
    }
    if (returnReduce(nLiquid, sumOp<label>()) == 0)
    {
        FatalErrorInFunction
            << "alpha.water in " << file << " is 0 everywhere (at most "
            << lbmFreeSurface::alphaRoundOff << "): freeSurface"
            << " has no water to simulate." << nl
            << "    Set the water's cells to 1 (setFields with a"
            << " boxToCell, as for interFoam), or remove freeSurface from"
            << " effects in constant/physicsProperties for a full lattice"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::freeSurface::freeSurface(physicsScene& scene)
:
    physicsEffect(scene),
    dict_(dictIO(scene.mesh())),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    alpha_
    (
        IOobject
        (
            "alpha.water",
            scene.mesh().time().timeName(),
            scene.mesh(),
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        scene.mesh()
    )
{
    if (scene.has("porousFlow"))
    {
        // (built first: the free surface starts from its porosity)
        scene.effect<physicsEffects::porousFlow>("porousFlow");
    }

    // Every boundary works where the surface meets it: walls, inlets and
    // pressure patches read only their own node's populations (the
    // interface nodes count what their links bring); a slip wall's link
    // pairs its node with the node beside it along the wall, and
    // exchanges mass with it as with a neighbour (the gas's population
    // where that node is gas: lbmFreeSurface::slipLinks)

    const scalar gasPressure = optionalEntry<scalar>(dict_, "gasPressure", 0);
    const scalar fillMargin = optionalEntry<scalar>(dict_, "fillMargin", 1e-3);
    const scalar surfaceTension =
        optionalEntry<scalar>(dict_, "surfaceTension", 0);
    // Where the conversions' excess mass goes: every interface neighbour
    // (allInterface, Koerner et al. 2005) or the old ones only (interface:
    // a jet leaves a sharp edge without creeping under it), see
    // lbmFreeSurface::convert
    const lbmFreeSurface::excessMassRule excessRule = selectEntry
    (
        lbmFreeSurface::excessMassRuleNames, "excessMassTo", dict_, true,
        lbmFreeSurface::EXCESS_TO_ALL_INTERFACE
    );
    if (!(surfaceTension >= 0 && surfaceTension < GREAT))
    {
        FatalIOErrorInFunction(dict_)
            << "surfaceTension " << surfaceTension << " is not allowed: a"
            << " finite, non-negative surface tension [N/m] (water-air"
            << " 0.0728 at 20 C; 0: none)" << exit(FatalIOError);
    }
    if (!std::isfinite(gasPressure))
    {
        FatalIOErrorInFunction(dict_)
            << "gasPressure " << gasPressure << " is not allowed: a finite"
            << " pressure [Pa], relative as p" << exit(FatalIOError);
    }
    // (the lattice density of the gas must be positive and near 1: the
    // lattice's pressure range, as the water's)
    const scalar rhoGas = fluid_.units().rhoLattice(gasPressure);
    if (!(rhoGas > 0.5 && rhoGas < 1.5))
    {
        FatalIOErrorInFunction(dict_)
            << "gasPressure " << gasPressure << " Pa is a lattice density of "
            << rhoGas << ": it must give a density in (0.5, 1.5), a pressure"
            << " within +-" << fluid_.units().pressure(1.5) << " Pa of the"
            << " reference (p = 0). Give p relative to the gas, with"
            << " gasPressure 0" << exit(FatalIOError);
    }
    if (!(fillMargin >= 0 && fillMargin <= 0.1))
    {
        FatalIOErrorInFunction(dict_)
            << "fillMargin " << fillMargin << " is not allowed: it must lie"
            << " in [0, 0.1] (1e-3 as Thuerey 2007, 1e-2 as Pohl 2008)"
            << exit(FatalIOError);
    }

    if (!fluid_.restarted())
    {
        checkAlpha();
    }
    fluid_.enableFreeSurface
    (
        gasPressure, fillMargin, surfaceTension, alpha_, excessRule
    );
    updateFields();

    const labelVector n = fluid_.freeSurface()->counts();
    Info<< "Free surface (Koerner et al. 2005): gas pressure " << gasPressure
        << " Pa, fill margin " << fillMargin << ", surface tension "
        << surfaceTension << " N/m, excess mass to "
        << lbmFreeSurface::excessMassRuleNames[excessRule]
        << ", " << n.x() << " interface nodes" << nl
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::freeSurface::evolve(const sceneStage)
{
    fluid_.updateInterface();
}


void Foam::physicsEffects::freeSurface::updateFields()
{
    const lbmFreeSurface& fs = *fluid_.freeSurface();
    const labelList& cellNode = fluid_.lattice().cellNode();
    scalarField& a = alpha_.primitiveFieldRef();
    forAll(cellNode, celli)
    {
        a[celli] = fs.fill(cellNode[celli]);
    }
    alpha_.correctBoundaryConditions();
}


void Foam::physicsEffects::freeSurface::restartState
(
    restartManifest::stateTable& state
) const
{
    state.set("interfaceNodes", fluid_.freeSurface()->nInterface());
}


void Foam::physicsEffects::freeSurface::restartStateSources
(
    restartManifest::stateSources& sources
) const
{
    sources.set("interfaceNodes", wordList({"lbmFreeSurfaceType"}));
}


Foam::scalar Foam::physicsEffects::freeSurface::memoryBytes() const
{
    return returnReduce
    (
        fluid_.freeSurface()->memoryBytes(),
        sumOp<scalar>()
    );
}


Foam::string Foam::physicsEffects::freeSurface::plan() const
{
    return
        "mass exchange, gas populations and cell conversion at every"
        " lattice step (gas pressure "
      + Foam::name(optionalEntry<scalar>(dict_, "gasPressure", 0)) + " Pa)";
}


Foam::string Foam::physicsEffects::freeSurface::progress() const
{
    const labelVector n = fluid_.freeSurface()->counts();
    return
        "interface nodes " + Foam::name(n.x()) + ", filled "
      + Foam::name(n.y()) + ", emptied " + Foam::name(n.z());
}


// ************************************************************************* //
