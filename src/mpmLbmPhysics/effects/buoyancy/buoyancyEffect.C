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
#include "optionalEntry.H"
#include "lbmFreeSurface.H"
#include "nodeFieldIO.H"
#include "caseChecks.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "soilEffect.H"
#include "porousFlowEffect.H"
#include "dragEffect.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"
#include "volFields.H"
#include "selectEntry.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(buoyancy, 0);
    addToRunTimeSelectionTable(physicsEffect, buoyancy, scene);
    addToMemberFunctionSelectionTable(physicsEffect, buoyancy, haloWidth, mesh);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::buoyancy::buoyancy(physicsScene& scene)
:
    physicsEffect(scene),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    soil_(scene.effect<physicsEffects::soil>("soil").mpm()),
    addedWaterForce_(nullptr),
    maxForce_(0),
    warm_(false),
    requested_("default"),
    analytic_(false),
    started_(false)
{
    if (!scene.effect<physicsEffects::drag>("drag").twoWay())
    {
        FatalErrorInFunction
            << "buoyancy needs drag twoWay (constant/dragProperties):"
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

    // Who carries the hydrostatic pressure: the lattice, or (the default
    // where it can: no free surface, g along no periodic direction) the
    // analytic rho_w g.(x - x_top); decided at the first step, when gravity
    // has been set
    if (foundEntry(scene.dict(), "buoyancyCoeffs"))
    {
        const dictionary& coeffs = scene.dict().subDict("buoyancyCoeffs");
        if (foundEntry(coeffs, "hydrostatic"))
        {
            enum class mode { analytic, lattice };
            const Enum<mode> modeNames
            ({
                {mode::analytic, "analytic"},
                {mode::lattice, "lattice"}
            });
            requested_ =
                modeNames[selectEntry(modeNames, "hydrostatic", coeffs)];
        }
    }

    fluid_.enableForceField();
    const latticeMesh& lattice = fluid_.lattice();
    const label nBox = lattice.nBox();
    pressure_.setSize(nBox, 0.0);
    target_.setSize(nBox, Zero);
    applied_.setSize(nBox, Zero);
    streamed_.setSize(nBox, Zero);
    weight_.setSize(nBox, Zero);

    // The lattice's gradient stencil at a node next to a wall or pressure
    // patch sees the node's own value beyond it (a pressure patch's
    // diagonal links: the value of the node beside it on their wall
    // node's row), so it gives half the
    // gradient normal to the boundary there (the water's balance is built
    // on that same stencil and needs it as it is). The soil's pore-pressure
    // force takes the full gradient: per node and direction, the stencil's
    // response to the coordinate field (1 inside, 1/2 at such nodes)
    // divides it. Measured without: the soil's first row on a wall or an
    // inlet felt half its buoyancy.
    gradScale_.setSize(nBox, vector::one);
    {
        const scalar dx = lattice.dx();
        const volVectorField& C = scene.mesh().C();
        for (direction j = 0; j < 3; ++j)
        {
            scalarList x(nBox, 0.0);
            forAll(lattice.cellNode(), celli)
            {
                x[lattice.cellNode()[celli]] = C[celli][j]/dx;
            }
            fluid_.streamedScalar(x, gradP_);
            // Inside: sum_q w_q c_q x(n - c_q) = -c_s^2 e_j = -e_j/3
            for (const label n : lattice.cellNode())
            {
                const scalar response = -3*gradP_[n][j];
                gradScale_[n][j] = response > 0.25 ? 1/response : 1;
            }
        }
    }

    // What the walls' reflection takes from the streamed image of a
    // uniform force: column j at node n is e_j - M(e_j) (zero away from
    // walls). Added back in balanced(), a locally uniform force is its own
    // image at walls too, as the lattice's own body force is (a water at
    // rest under a uniform weight balances it exactly, walls included)
    wallDeficit_.setSize(nBox, Zero);
    for (direction j = 0; j < 3; ++j)
    {
        List<vector> e(nBox, Zero);
        for (const label n : lattice.cellNode())
        {
            e[n][j] = 1;
        }
        fluid_.streamedForce(e, streamed_);
        for (const label n : lattice.cellNode())
        {
            const vector col(e[n] - streamed_[n]);
            for (direction i = 0; i < 3; ++i)
            {
                wallDeficit_[n](i, j) = col[i];
            }
        }
    }

    // The applied force of a written time, for a restart that continues
    // bit for bit (see evolve)
    IOobject io
    (
        "lbmStaticForce",
        scene.mesh().time().timeName(),
        scene.mesh(),
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    // (a run from U and p starts its balance afresh: a static force left
    // in the start time may be of the other hydrostatic mode)
    if (fluid_.restarted() && io.typeHeaderOk<volVectorField>(true))
    {
        const volVectorField Fw(io, scene.mesh());
        checkFinite(Fw.primitiveField(), Fw.objectPath(), "internalField");
        forAll(lattice.cellNode(), celli)
        {
            applied_[lattice.cellNode()[celli]] = Fw[celli];
        }
        warm_ = true;
        Info<< "    the water's static force read from " << io.name() << nl;
    }
    porosity_.setSize(nBox, 1.0);
    porosityP_.setSize(nBox, 0.0);
    gradP_.setSize(nBox, Zero);
    gradNP_.setSize(nBox, Zero);
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

void Foam::physicsEffects::buoyancy::start()
{
    // (g along a periodic direction: the default keeps the pressure on
    // the lattice; asked for, the analytic mode takes off the part of g
    // across the other directions, the lattice keeps the part that drives
    // the flow; with g along periodic directions only there is nothing to
    // take off)
    const bool can = fluid_.canUseAnalyticHydrostatic();
    if
    (
        requested_ == "analytic"
     && mag(fluid_.bodyAcceleration()) > 0
     && !(mag(fluid_.hydrostaticAcceleration()) > 0)
    )
    {
        FatalIOErrorInFunction(scene_.dict().subDict("buoyancyCoeffs"))
            << "hydrostatic analytic has nothing to take off here: constant/g "
            << fluid_.bodyAcceleration() << " lies along periodic directions"
            << " only (cyclic patches), across which the lattice cannot hold"
            << " a pressure that grows: there the weight drives the flow."
            << " Use hydrostatic lattice (the default here)"
            << exit(FatalIOError);
    }
    // (water without weight has no hydrostatic pressure to take off: the
    // lattice mode, which it equals, so that a time written before the
    // analytic mode existed restarts)
    // With a free surface the lattice mode stays the default: off the
    // lattice, the water at a surface off the reference level holds p_rgh
    // of that level's depth, and its porosity term at a soil's face
    // alternates between node rows as the whole pressure's did below a
    // single level (measured: a rectangular dam between reservoirs 0.3 m
    // apart, validation/dupuitSeepage: the discharge +4.7% of Dupuit-
    // Charny and its halves 1.1% apart, against +2.6% and steady in the
    // lattice mode, whose surfaces hold the gas pressure).
    analytic_ =
        (
            requested_ == "default"
          ? can && !fluid_.freeSurface()
          : requested_ == "analytic"
        )
     && mag(fluid_.hydrostaticAcceleration()) > 0;

    // A restart continues in the mode its populations were written with
    // (a time without lbmHydrostatic: the lattice carried the whole
    // pressure, as every run did before the analytic mode)
    const word mode(analytic_ ? "analytic" : "lattice");
    const word& written = fluid_.writtenHydrostatic();
    if (fluid_.restarted() && written != mode)
    {
        FatalIOErrorInFunction(scene_.dict())
            << "The water's populations in "
            << fluid_.writtenHydrostaticFile().path().path() << " were"
            << " written with buoyancy's hydrostatic " << written << " ("
            << fluid_.writtenHydrostaticFile()
            << (isFile(fluid_.writtenHydrostaticFile()) ? "" : ": none")
            << "); this run has hydrostatic " << mode << "."
            << nl << "    Continue that run with buoyancyCoeffs { hydrostatic "
            << written << "; } in constant/physicsProperties, or start from 0"
            << exit(FatalIOError);
    }
    if (analytic_)
    {
        fluid_.useAnalyticHydrostatic();
        // (the interface nodes' porosity term, applied through X, is no
        // pressure gradient: the gas pressure is carried without it)
        fluid_.setFreeSurfaceStaticForce(&applied_);
    }
    Info<< "Buoyancy: "
        << (
               analytic_
             ? "the hydrostatic pressure analytic (the lattice carries p_rgh"
               " = p - rho_w g_h.(x - x_top), g_h the part of g across the"
               " directions that are not periodic)"
             : mag(fluid_.bodyAcceleration()) > 0
             ? "the hydrostatic pressure on the lattice"
             : "no hydrostatic pressure (the water has no weight)"
           ) << nl << endl;
}


void Foam::physicsEffects::buoyancy::balanced
(
    const List<vector>& F,
    List<vector>& MF
)
{
    fluid_.streamedForce(F, MF);
    for (const label n : fluid_.lattice().cellNode())
    {
        MF[n] += wallDeficit_[n] & F[n];
    }
}


void Foam::physicsEffects::buoyancy::evolve(const sceneStage)
{
    if (!started_)
    {
        // (before the first step, after the porosity's first setting: the
        // populations of a run from U and p then hold p_rgh)
        started_ = true;
        start();
    }
    const latticeMesh& lattice = fluid_.lattice();
    const label Q = fluid_.velocities().Q();
    const scalarList& f = fluid_.populations();
    const lbmLayout& layout = fluid_.layout();
    const scalarList& eps = fluid_.porosity();
    const labelList& cellNode = lattice.cellNode();
    // (the weight the lattice applies: with the hydrostatic pressure off
    // the lattice only the part along periodic directions, if any)
    const vector g = fluid_.latticeAcceleration();

    // Pore pressure c_s^2 (rho - 1)/n (lattice units, relative to the
    // reference) and the porosity. With the porous flow's displacement,
    // rho is the step's time-centred density, the populations' sum less
    // half the source they took in this step (see
    // latticeBoltzmannFluid::displacementSource): the soil and the
    // porosity term feel the pressure the lattice's own momentum feels
    const scalarList& source = fluid_.displacementSource();
    const bool centred = source.size() > 0;
    for (const label n : cellNode)
    {
        scalar rho = centred ? -0.5*source[n] : 0;
        for (label q = 0; q < Q; ++q)
        {
            rho += f[layout.at(q, n)];
        }
        weight_[n] = eps[n]*g;
        pressure_[n] = (rho - 1)/(3*eps[n]);
        porosity_[n] = eps[n];
    }

    // With a free surface: the gas's pressure in the gas (its populations
    // are not the water's), no weight there; the share of water of each
    // node (the fill level) takes the soil's pore-pressure force: dry soil
    // feels none
    // (less the hydrostatic pressure where it is off the lattice: the gas
    // pressure then continues p_rgh across the surface)
    const lbmFreeSurface* fs = fluid_.freeSurface();
    if (fs)
    {
        const lbmUnits& units = fluid_.units();
        for (const label n : cellNode)
        {
            if (fs->gas(n))
            {
                weight_[n] = Zero;
                pressure_[n] =
                (
                    fs->rhoGas()
                  - units.rhoLattice(fluid_.hydrostaticPressure(n))
                )/3;
            }
        }
    }

    // The streaming of a water at rest of density X gives node n the
    // impulse S(X) = sum_q w_q c_q X(n - c_q) = -c_s^2 grad(X), walls and
    // pressure boundaries included: the lattice's own gradient stencil.
    // The lattice gives the water S(rho) = 3 S(n p) = -grad(n p) (n the
    // porosity); with
    //     D(p) = 3 S(p)                                       = -grad(p)
    //     F_w  = n D(p) - 3 S(n p)                            = p grad(n)
    // the water feels exactly n D(p) = -n grad(p) and the soil
    // phi D(p) = -phi grad(p). Summed over the nodes S telescopes:
    // momentum is conserved (walls aside, which act on the water).
    forAll(porosityP_, n)
    {
        porosityP_[n] = porosity_[n]*pressure_[n];
    }
    fluid_.streamedScalar(pressure_, gradP_);
    fluid_.streamedScalar(porosityP_, gradNP_);

    const scalar toNewton =
        lattice.cellVolume()/fluid_.units().forceDensityToLattice();
    // The hydrostatic pressure off the lattice: its force on a node's
    // solid, -phi grad(p_h) V = -phi rho_w g V (Archimedes) [N per phi]
    const vector archimedes
    (
        analytic_
      ? vector
        (
           -fluid_.units().rho0()*lattice.cellVolume()
           *fluid_.hydrostaticAcceleration()
        )
      : vector::zero
    );
    // While the soil's gravity grows over soilProperties' gravityRamp, its
    // uplift grows with it: the water is hydrostatic from the start, and
    // its full lift -phi rho_w g on a soil of a fraction of its weight
    // floated the soil early in the ramp (at half the ramp the effective
    // stress was 19.5% of the buoyant weight, not 50%, and the layer kept
    // a heave). Only the hydrostatic part is scaled: a seepage's pressure
    // gradient acts whole.
    const vector liftWithheld
    (
        (1 - soil_.gravityRampFactor())*fluid_.units().rho0()
       *lattice.cellVolume()*fluid_.hydrostaticAcceleration()
    );
    soilForce_ = Zero;
    maxForce_ = 0;
    for (const label n : cellNode)
    {
        const vector D = 3*gradP_[n];
        const vector Fw = porosity_[n]*D - 3*gradNP_[n];

        target_[n] = Fw;

        const scalar phi = 1 - porosity_[n];
        const scalar wet = (fs ? fs->fill(n) : 1);
        if (phi > 0 && wet > 0)
        {
            soilForce_[n] =
                (toNewton*phi*wet)*cmptMultiply(gradScale_[n], D)
              + (phi*wet)*(archimedes + liftWithheld);
            maxForce_ = max(maxForce_, mag(soilForce_[n]));
        }
    }

    if (fs && analytic_)
    {
        // (the interface nodes' porosity term from their water neighbours)
        interfacePorosityForce(fs);
    }

    // Guo's scheme carries half of each step's force into the next, and
    // the streaming of that momentum from the neighbours makes a water at
    // rest balance (F + M F)/2 against the pressure rather than F: where
    // the force jumps (the porosity term at the soil's surface, and the
    // Guo-Zhao weight n rho g with it) the pressure would take up the
    // difference. The static force the water must balance is
    //     target = p grad(n) + W - (W + M W)/2,   W = n rho g
    // (the weight the lattice applies itself, and what its balance misses
    // where W jumps), applied as the X with (X + M X)/2 = target (M with the
    // walls' deficit added back, see the constructor: with the bare
    // reflection the balance at a wall has a growing odd-even solution, an
    // odd-even pore pressure of amplitude rho_w g dx/2 through the whole
    // tank, measured 1.6% of rho_w g H on the submerged bed before).
    // Relaxation sweeps, one per step from the last step's X (the static
    // force changes slowly), ten at the start
    balanced(weight_, streamed_);
    for (const label n : cellNode)
    {
        target_[n] += weight_[n] - 0.5*(weight_[n] + streamed_[n]);
    }
    // (with a free surface, only the liquid nodes: the surface's nodes
    // balance the lattice's own weight against the gas pressure rebuilt
    // at their links, as in clear water, and the gas takes no force; with
    // the hydrostatic pressure off the lattice the interface nodes keep
    // their porosity term, interfacePorosityForce)
    if (fs)
    {
        for (const label n : cellNode)
        {
            if (!fs->liquid(n) && !(analytic_ && fs->interface(n)))
            {
                target_[n] = Zero;
            }
        }
    }
    List<vector>& X = applied_;
    label nSweeps = 1;
    if (!warm_)
    {
        X = target_;
        nSweeps = 10;
        warm_ = true;
    }
    for (label sweep = 0; sweep < nSweeps; ++sweep)
    {
        balanced(X, streamed_);
        for (const label n : cellNode)
        {
            X[n] += target_[n] - 0.5*(X[n] + streamed_[n]);
        }
        if (fs)
        {
            // (the interface nodes' porosity term, where there is one,
            // applied as it is: see interfacePorosityForce)
            for (const label n : cellNode)
            {
                if (!fs->liquid(n))
                {
                    X[n] = fs->interface(n) ? target_[n] : Zero;
                }
            }
        }
    }
    if (addedWaterForce_)
    {
        const List<vector>& added = *addedWaterForce_;
        for (const label n : cellNode)
        {
            fluid_.setForce(n, X[n] + added[n]);
        }
    }
    else
    {
        for (const label n : cellNode)
        {
            fluid_.setForce(n, X[n]);
        }
    }

    soil_.addNodeForces(soilForce_);
    maxForce_ /= lattice.cellVolume();
}


void Foam::physicsEffects::buoyancy::interfacePorosityForce
(
    const lbmFreeSurface* fs
)
{
    // With the hydrostatic pressure off the lattice the water at a free
    // surface holds p_rgh = p_gas - rho_w g.(x_s - x_top), not the gas
    // pressure: wherever the surface is off the reference level, the
    // porosity term p_rgh grad(n) at an interface node is of the depth's
    // size (a reservoir's surface 0.3 m below the other's against a dam's
    // face: p_rgh about -3 kPa; left out, the surface's nodes at the face
    // were driven at 0.2 m/s). The lattice gives interface node x
    //     -3 S(n' p),  n'(y) = n(y) from water, n(x) from the gas
    // (the gas's populations are rebuilt at x's own porosity), so its term
    //     n(x) D(p) - 3 S(n' p) = 3 sum_q w_q c_q (n(x) - n(y)) p(y)
    // runs over the water neighbours y = x - c_q only (walls and patches
    // reflect x's own: none). Applied as it is, without the half-step
    // balance of the liquid nodes, as the surface's own forces are.
    const latticeMesh& lattice = fluid_.lattice();
    const velocitySet& vs = fluid_.velocities();
    const List<labelVector>& c = vs.c();
    const scalarList& w = vs.w();
    const label nBox = lattice.nBox();
    lattice.halo().exchange(pressure_.data(), 1, nBox);
    lattice.halo().exchange(porosity_.data(), 1, nBox);
    for (const label x : lattice.cellNode())
    {
        if (!fs->interface(x))
        {
            continue;
        }
        vector F(Zero);
        for (label q = 1; q < vs.Q(); ++q)
        {
            const label y = x - lattice.offset(c[q].x(), c[q].y(), c[q].z());
            if (fs->liquid(y) || fs->interface(y))
            {
                F +=
                    (3*w[q]*(porosity_[x] - porosity_[y])*pressure_[y])
                   *vector(c[q]);
            }
        }
        target_[x] = F;
    }
}


Foam::wordList Foam::physicsEffects::buoyancy::stateFiles() const
{
    return wordList(1, "lbmStaticForce");
}


void Foam::physicsEffects::buoyancy::write()
{
    // Lattice units, binary whatever the case's writeFormat (as the
    // populations): a restart continues bit for bit
    writeNodeField(fluid_.lattice(), "lbmStaticForce", applied_, dimless, true);
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
