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

#include "latticeBoltzmannFluid.H"
#include "optionalEntry.H"
#include "IFstream.H"
#include "OFstream.H"
#include "nodeFieldIO.H"
#include "selectEntry.H"
#include "caseChecks.H"
#include "lbmKernel.H"
#include "vector2D.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(latticeBoltzmannFluid, 0);
}

const Foam::word Foam::latticeBoltzmannFluid::outletStateFile("lbmOutletState");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// A positive physical property from the dictionary, no larger than max,
// or a FatalIOError
Foam::scalar positiveEntry
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::scalar max = Foam::VGREAT
)
{
    const Foam::scalar value = dict.get<Foam::scalar>(key);
    if (!(value > 0 && value <= max))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " = " << value << " is not allowed:"
            << " it must be a positive number (SI units)"
            << (max < Foam::VGREAT ? " no larger than " : "")
            << (max < Foam::VGREAT ? Foam::name(max) : Foam::word())
            << Foam::exit(Foam::FatalIOError);
    }
    return value;
}

// Whether the populations stream in place (streaming inPlace | twoLattice)
bool streamsInPlace(const Foam::dictionary& dict)
{
    const Foam::word streaming
    (
        Foam::optionalEntry<Foam::word>(dict, "streaming", "inPlace")
    );
    if (streaming != "inPlace" && streaming != "twoLattice")
    {
        FatalIOErrorInFunction(dict)
            << "streaming " << streaming << " is not allowed: it must be"
            << " inPlace (one lattice, the AA pattern: half the memory;"
            << " the default) or twoLattice (the reference)"
            << Foam::exit(Foam::FatalIOError);
    }
    return streaming == "inPlace";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::latticeBoltzmannFluid::latticeBoltzmannFluid(const latticeMesh& lattice)
:
    lattice_(lattice),
    mesh_(lattice.mesh()),
    dict_
    (
        IOobject
        (
            "fluidProperties",
            mesh_.time().constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    velocitySet_(velocitySet::New(dict_.get<word>("velocitySet"), dict_)),
    units_
    (
        lattice.dx(),
        mesh_.time().deltaTValue(),
        positiveEntry(dict_, "nu"),
        positiveEntry(dict_, "rho", 1e5)
    ),
    collision_(collisionModel::New(dict_, velocitySet_())),
    bodyAcceleration_(Zero),
    latticeAcceleration_(Zero),
    machLimit_(optionalEntry<scalar>(dict_, "machLimit", 0.5)),
    smagorinsky_(optionalEntry<scalar>(dict_, "smagorinskyConstant", 0)),
    writeStress_(optionalEntry<bool>(dict_, "writeViscousStress", false)),
    U_
    (
        IOobject
        (
            "U",
            mesh_.time().timeName(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_
    ),
    p_
    (
        IOobject
        (
            "p",
            mesh_.time().timeName(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_
    ),
    rho_
    (
        IOobject
        (
            "rho",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh_,
        dimensionedScalar("rho", dimDensity, units_.rho0())
    ),
    AisCurrent_(true),
    inPlace_(streamsInPlace(dict_)),
    momentumStale_(true),
    halo_(lattice.halo()),
    restarted_(false),
    hydrostaticGradient_(Zero),
    hydrostaticRef_(Zero),
    writtenHydrostaticGradient_(Zero),
    writtenHydrostaticRef_(Zero),
    porosityInitialised_(false),
    storageFollowsPorosity_(true),
    displacedMass_(0),
    displacement_(false),
    mass0_(0),
    nSteps_(0),
    givenDrag_(false),
    prepared_(false)
{
    checkVelocitySet();

    // Gravity and any body force come from constant/g, one way for every
    // phase: the old keyword would be silently ignored
    if (foundEntry(dict_, "bodyAcceleration"))
    {
        FatalIOErrorInFunction(dict_)
            << "bodyAcceleration is not read from constant/fluidProperties:"
            << " gravity and body forces are the gravity effect's, from"
            << " constant/g (value (...);): add gravity to effects in"
            << " constant/physicsProperties, with gravityCoeffs { phases"
            << " (fluid); } for a body force on the water alone"
            << exit(FatalIOError);
    }
    if (!(machLimit_ > 0 && machLimit_ <= 1))
    {
        FatalIOErrorInFunction(dict_)
            << "machLimit " << machLimit_ << " is not allowed: it must lie"
            << " in (0, 1]; the lattice Boltzmann method is accurate for"
            << " Mach numbers well below 0.3" << exit(FatalIOError);
    }
    // (Smagorinsky's constant is of order 0.1: beyond 1 the eddy
    // viscosity would swamp the flow it models; written so NaN fails)
    if (!(smagorinsky_ >= 0 && smagorinsky_ <= 1))
    {
        FatalIOErrorInFunction(dict_)
            << "smagorinskyConstant " << smagorinsky_ << " is not allowed:"
            << " it must lie in [0, 1] (0: no sub-grid model; 0.1 to 0.17"
            << " usual)" << exit(FatalIOError);
    }

    // Damaged initial fields stop here (binary NaN or Inf, 1e400)
    checkFinite(U_.primitiveField(), U_.objectPath(), "internalField");
    checkFinite(p_.primitiveField(), p_.objectPath(), "internalField");
    forAll(U_.boundaryField(), patchi)
    {
        const word entry
        (
            "boundaryField." + U_.boundaryField()[patchi].patch().name()
        );
        checkFinite(U_.boundaryField()[patchi], U_.objectPath(), entry);
        checkFinite(p_.boundaryField()[patchi], p_.objectPath(), entry);
    }
    // ... and values the lattice cannot hold: a pressure whose lattice
    // density 1 + p/(rho c_s^2) is not in (0, 2) (1e300 overflowed the
    // kernel before the stability guard saw it), a speed at or above the
    // Mach limit
    {
        const scalar pMax = units_.rho0()*sqr(units_.soundSpeed());
        // (the values of the patches that impose p too, fixed values and
        // advective outlets: -1e300 there trapped in the first step)
        auto checkP = [&](const scalarField& p, const word& entry)
        {
            forAll(p, i)
            {
                if (!(mag(p[i]) < pMax))
                {
                    FatalErrorInFunction
                        << "file: " << p_.objectPath() << ", " << entry
                        << ": p " << p[i] << " Pa at index " << i << " is"
                        << " not allowed: the lattice holds |p| < rho c_s^2"
                        << " = " << pMax << " Pa at this deltaT and cell"
                        << " size (its density 1 + p/(rho c_s^2) must lie in"
                        << " (0, 2); c_s = dx/(sqrt(3) deltaT) = "
                        << units_.soundSpeed() << " m/s)." << nl
                        << "    Check p's units (Pa, relative to the"
                        << " reference; not p/rho), or use a smaller deltaT"
                        << " in system/controlDict" << exit(FatalError);
                }
            }
        };
        checkP(p_.primitiveField(), "internalField");
        forAll(p_.boundaryField(), patchi)
        {
            const fvPatchScalarField& pp = p_.boundaryField()[patchi];
            if (!pp.fixesValue() && pp.type() != "advective")
            {
                continue;
            }
            checkP
            (
                p_.boundaryField()[patchi],
                "boundaryField." + p_.boundaryField()[patchi].patch().name()
            );
        }
        const scalar uMax = machLimit_*units_.soundSpeed();
        auto checkU = [&](const vectorField& U, const word& entry)
        {
            forAll(U, i)
            {
                const vector& v = U[i];
                if
                (
                    !(mag(v.x()) < uMax && mag(v.y()) < uMax
                   && mag(v.z()) < uMax && mag(v) < uMax)
                )
                {
                    FatalErrorInFunction
                        << "file: " << U_.objectPath() << ", " << entry
                        << ": U " << v << " at index " << i << " is at or"
                        << " above machLimit " << machLimit_ << " times the"
                        << " lattice's speed of sound, " << uMax << " m/s at"
                        << " this deltaT and cell size (c_s = dx/(sqrt(3)"
                        << " deltaT) = " << units_.soundSpeed() << " m/s)."
                        << nl << "    Check U, or use a smaller deltaT in"
                        << " system/controlDict" << exit(FatalError);
                }
            }
        };
        checkU(U_.primitiveField(), "internalField");
        forAll(U_.boundaryField(), patchi)
        {
            checkU
            (
                U_.boundaryField()[patchi],
                "boundaryField." + U_.boundaryField()[patchi].patch().name()
            );
        }
    }

    if (U_.dimensions() != dimVelocity)
    {
        FatalErrorInFunction
            << "Field U in " << U_.objectPath() << " has dimensions "
            << U_.dimensions() << "; the lattice Boltzmann water expects the"
            << " velocity in m/s, dimensions " << dimVelocity
            << exit(FatalError);
    }
    if (lattice_.twoD())
    {
        // (a 2D scene moves in its plane: refused where the field gives
        // anything else, on any processor)
        scalar Uz = 0;
        for (const vector& u : U_.primitiveField())
        {
            Uz = max(Uz, mag(u.z()));
        }
        if (returnReduce(Uz, maxOp<scalar>()) > 0)
        {
            FatalErrorInFunction
                << "Field U in " << U_.objectPath() << " has a z component"
                << " (up to " << returnReduce(Uz, maxOp<scalar>())
                << " m/s) in a 2D case (one cell thick in z): the water"
                << " moves in its plane" << exit(FatalError);
        }
    }
    if (p_.dimensions() != dimPressure)
    {
        FatalErrorInFunction
            << "Field p in " << p_.objectPath() << " has dimensions "
            << p_.dimensions() << "; the lattice Boltzmann water expects the"
            << " pressure in Pa, dimensions [1 -1 -2 0 0 0 0]"
            << exit(FatalError);
    }

    // Offsets of the lattice vectors
    const label Q = velocitySet_->Q();
    offset_.setSize(Q);
    for (label q = 0; q < Q; ++q)
    {
        const labelVector& c = velocitySet_->c()[q];
        offset_[q] = lattice_.offset(c.x(), c.y(), c.z());
    }

    // Reference speed for the Mach check: given, or the largest initial or
    // wall speed
    scalar Umax = max(mag(U_.primitiveField()));
    forAll(U_.boundaryField(), patchi)
    {
        Umax = max(Umax, max(mag(U_.boundaryField()[patchi])));
    }
    reduce(Umax, maxOp<scalar>());
    const scalar Uref = optionalEntry<scalar>(dict_, "Uref", Umax);
    if (dict_.found("Uref") && (!(Uref > 0) || !std::isfinite(Uref)))
    {
        entryNotAllowed
        (
            dict_, "Uref", Uref,
            "the speed scale of the Mach check must be positive [m/s]"
        );
    }

    Info<< "Lattice Boltzmann water" << nl
        << "    velocity set " << velocitySet_->type() << nl;
    collision_->report(Info);
    if (smagorinsky_ > 0)
    {
        Info<< "    Smagorinsky sub-grid model, constant " << smagorinsky_
            << nl;
    }
    Info<< endl;
    units_.report(Info, Uref);
    checkUnits();

    const scalar Ma = units_.Mach(Uref);
    if (Ma >= machLimit_)
    {
        FatalIOErrorInFunction(dict_)
            << "The lattice Mach number " << Ma << " of the reference speed "
            << Uref << " m/s is at or above machLimit " << machLimit_ << nl
            << "    Reduce deltaT in system/controlDict below "
            << 0.3*lattice_.dx()/(Uref*std::sqrt(3.0)) << " s (Mach 0.3)"
            << exit(FatalIOError);
    }
    if (Ma > 0.2)
    {
        WarningInFunction
            << "The lattice Mach number " << Ma << " of the reference speed "
            << Uref << " m/s is above 0.2: compressibility errors of order"
            << " Ma^2 = " << sqr(Ma) << " and a risk of instability." << nl
            << "    Reduce deltaT in system/controlDict below "
            << 0.1*lattice_.dx()/(Uref*std::sqrt(3.0)) << " s (Mach 0.1)"
            << endl;
    }

    // The halo exchange sends, from each neighbour, only the directions
    // that the pull from some owned node reads: q such that h + c_q is
    // owned, for the halo nodes h of that neighbour (5 of 19 across a face)
    {
        const labelListList& recvNodes = halo_.recvNodes();
        const List<unsigned char>& kind = lattice_.kind();
        const label nBox = lattice_.nBox();
        labelListList needed(recvNodes.size());
        forAll(recvNodes, proci)
        {
            boolList use(max(Q, label(1)), false);
            for (const label h : recvNodes[proci])
            {
                for (label q = 0; q < Q; ++q)
                {
                    const label x = h + offset_[q];
                    if (x >= 0 && x < nBox && kind[x] == latticeMesh::OWNED)
                    {
                        use[q] = true;
                    }
                }
            }
            DynamicList<label> comps;
            forAll(use, q)
            {
                if (use[q])
                {
                    comps.append(q);
                }
            }
            needed[proci].transfer(comps);
        }
        halo_.setComponents(needed);
    }

    obstacles_.reset(new lbmObstacles(lattice_, dict_));
    obstacles_->report(Info);
    boundaries_.reset
    (
        new lbmBoundaries
        (
            lattice_, velocitySet_(), units_, U_, p_, obstacles_()
        )
    );
    boundaries_->report(Info);

    // A pressure link whose wall node's row lies across a processor
    // boundary takes all the populations of that halo node: its
    // neighbour sends them all
    {
        const labelList& from = boundaries_->pressureLinkSources();
        const List<unsigned char>& kind = lattice_.kind();
        boolList haloSource(lattice_.nBox(), false);
        bool any = false;
        for (const label y : from)
        {
            if (kind[y] == latticeMesh::HALO)
            {
                haloSource[y] = true;
                any = true;
            }
        }
        if (returnReduce(any, orOp<bool>()))
        {
            const labelListList& recvNodes = halo_.recvNodes();
            labelListList needed(halo_.recvComponents());
            forAll(recvNodes, proci)
            {
                for (const label h : recvNodes[proci])
                {
                    if (haloSource[h])
                    {
                        needed[proci] = identity(Q);
                        break;
                    }
                }
            }
            halo_.setComponents(needed);
        }
    }
    if
    (
        units_.tau() - 0.5 < pressurePatchTauMinusHalf_
     && returnReduce(boundaries_->pressureLinkNodes().size(), sumOp<label>())
     && !collision_->splitRelaxation()
    )
    {
        WarningInFunction
            << "tau - 1/2 = " << units_.tau() - 0.5 << " with pressure"
            << " patches and collisionModel " << collision_->type() << ":"
            << " a pressure patch's links take the non-equilibrium part of"
            << " the node beside them (Guo, Zheng & Shi 2002), which a"
            << " collision that relaxes it at one rate turns over nearly"
            << " whole each step near tau = 1/2, and a flow through the"
            << " patch can grow from it (a tank filling through a patch"
            << " with BGK: unstable at tau - 1/2 = 0.0077, stable at 0.015;"
            << " regularized stable at 0.0077)." << nl
            << "    To stay stable with a flow through the patch: collisionModel"
            << " TRT or MRT (they hold), or tau - 1/2 above "
            << pressurePatchTauMinusHalf_ << " (tau - 1/2 = 3 nu deltaT/dx^2)."
            << endl;
    }

    initialise();
    updateFields();

    // What the populations cost (all processors)
    const scalar populationBytes = returnReduce
    (
        scalar(sizeof(scalar))*(fA_.size() + fB_.size()),
        sumOp<scalar>()
    );
    Info<< "Lattice Boltzmann streaming" << nl
        << "    " << (inPlace_ ? "inPlace" : "twoLattice") << ": "
        << (inPlace_ ? "one lattice (AA pattern)" : "two lattices (pull)")
        << ", " << (inPlace_ ? 1 : 2)*Q*label(sizeof(scalar))
        << " bytes per node, populations " << populationBytes/1048576.0
        << " MiB" << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeBoltzmannFluid::enableForceField()
{
    if (Fx_.empty())
    {
        const label nBox = lattice_.nBox();
        Fx_.setSize(nBox, 0.0);
        Fy_.setSize(nBox, 0.0);
        Fz_.setSize(nBox, 0.0);
        relaxK_.setSize(nBox, 0.0);
        relaxS_.setSize(nBox, 1.0);
        relaxUx_.setSize(nBox, 0.0);
        relaxUy_.setSize(nBox, 0.0);
        relaxUz_.setSize(nBox, 0.0);
        dragX_.setSize(nBox, 0.0);
        dragY_.setSize(nBox, 0.0);
        dragZ_.setSize(nBox, 0.0);
    }
}


void Foam::latticeBoltzmannFluid::enableGivenDrag()
{
    enableForceField();
    givenDrag_ = true;
    dragX_ = 0;
    dragY_ = 0;
    dragZ_ = 0;
}


void Foam::latticeBoltzmannFluid::prepareStream()
{
    if (prepared_)
    {
        return;
    }
    if (inPlace_ && layout_.natural())
    {
        startInPlace();
    }
    scalarList& f = current();
    if (nSteps_ == 0 && !restarted_)
    {
        warnUniformPressure();
        startAtForceBalance();
    }
    if (nSteps_ == 0 && restarted_)
    {
        checkWrittenHydrostatic();
    }
    exchangeHalo(f.data());
    if (boundaries_->timeVarying())
    {
        boundaries_->update(units_, U_, p_, f.cdata(), layout_);
    }
    if (writtenDrag_.size() && nSteps_ == 0 && dragX_.size())
    {
        // The last step's drag as the run wrote it (see writePopulations)
        const label nBox = lattice_.nBox();
        SubList<scalar>(dragX_, nBox) = SubList<scalar>(writtenDrag_, nBox);
        SubList<scalar>(dragY_, nBox) =
            SubList<scalar>(writtenDrag_, nBox, nBox);
        SubList<scalar>(dragZ_, nBox) =
            SubList<scalar>(writtenDrag_, nBox, 2*nBox);
        writtenDrag_.clear();
    }
    if (freeSurface_)
    {
        // After the halo: the gas slots next to this processor's interface
        // nodes are its own to rebuild. Before the boundaries: a curved
        // body's interpolated bounce-back reads the slot of the node
        // beyond, which may be a rebuilt gas slot (the rebuild reads no
        // slot the boundaries write)
        setFreeSurfaceForces();
        freeSurface_->reconstruct
        (
            f.data(),
            latticeAcceleration()
        );
    }
    boundaries_->fill
    (
        f.data(),
        layout_,
        porosity_.size() ? porosity_.cdata() : nullptr,
        freeSurface_.get(),
        latticeAcceleration()
    );
    if (freeSurface_)
    {
        // (what the walls, inlets and pressure patches send the surface's
        // nodes)
        freeSurface_->exchangeBoundaryMass(f.cdata());
        freeSurface_->bodyLinkMass(boundaries_());
        freeSurface_->pressureLinkMass(f.cdata(), boundaries_());
        freeSurface_->slipLinks
        (
            f.data(),
            boundaries_(),
            latticeAcceleration()
        );
    }
    prepared_ = true;
}


void Foam::latticeBoltzmannFluid::streamedState
(
    const label n,
    scalar& rho,
    vector& j,
    vector& p,
    vector& Fo
) const
{
    // As the kernel forms them (lbmKernel.H)
    const label Q = velocitySet_->Q();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& f = current();
    rho = 0;
    j = Zero;
    p = Zero;
    for (label q = 0; q < Q; ++q)
    {
        const vector cq(c[q]);
        const scalar fq = f[layout_.at(q, n - offset_[q])];
        rho += fq;
        j += fq*cq;
        p += f[layout_.at(q, n)]*cq;
    }
    const scalar eps = porosity_.size() ? porosity_[n] : 1.0;
    Fo = eps*latticeAcceleration();
    if (Fx_.size())
    {
        Fo += vector(Fx_[n], Fy_[n], Fz_[n]);
    }
}


void Foam::latticeBoltzmannFluid::step()
{
    prepareStream();
    scalarList& f = current();

    const label Q = velocitySet_->Q();
    labelList srcBase(Q), dstBase(Q), oldBase(Q);
    const lbmLayout& after = inPlace_ ? nextLayout_ : layout_;
    for (label q = 0; q < Q; ++q)
    {
        srcBase[q] = layout_.at(q, -offset_[q]);
        dstBase[q] = after.base(q);
        oldBase[q] = layout_.base(q);
    }

    lbmKernelArgs a;
    a.fOld = f.cdata();
    a.fNew = inPlace_ ? f.data() : next().data();
    a.srcBase = srcBase.cdata();
    a.dstBase = dstBase.cdata();
    a.oldBase = oldBase.cdata();
    // (the water's runs: without the nodes inside bodies)
    // (with a free surface: without the gas nodes)
    const List<latticeMesh::nodeRun>& runs =
        freeSurface_ ? freeSurface_->runs() : obstacles_->runs();
    a.runs = reinterpret_cast<const label (*)[2]>(runs.cdata());
    a.nRuns = runs.size();
    const vector g = latticeAcceleration();
    a.g[0] = g.x();
    a.g[1] = g.y();
    a.g[2] = g.z();
    if (Fx_.size())
    {
        a.Fx = Fx_.cdata();
        a.Fy = Fy_.cdata();
        a.Fz = Fz_.cdata();
        a.relaxK = relaxK_.cdata();
        a.relaxS = relaxS_.cdata();
        a.dragX = dragX_.data();
        a.dragY = dragY_.data();
        a.dragZ = dragZ_.data();
        a.relaxUx = relaxUx_.cdata();
        if (porosity_.size())
        {
            a.porosity = porosity_.cdata();
        }
        a.relaxUy = relaxUy_.cdata();
        a.relaxUz = relaxUz_.cdata();
        a.givenDrag = givenDrag_;
        if (inPlace_ && !givenDrag_)
        {
            if (momentumStale_)
            {
                sumMomentum();
            }
            a.momX = momX_.data();
            a.momY = momY_.data();
            a.momZ = momZ_.data();
        }
    }
    a.omega = 1.0/units_.tau();
    a.smagorinsky = smagorinsky_;

    stats_ = lbmKernelStats();
    collision_->streamCollide(a, stats_);
    ++nSteps_;
    prepared_ = false;

    const scalar maxU2 = sqr(machLimit_)*lattice::cs2;
    if (inPlace_)
    {
        Foam::Swap(layout_, nextLayout_);
    }
    else
    {
        AisCurrent_ = !AisCurrent_;
    }
    if
    (
        !std::isfinite(stats_.mass)
     || !(stats_.rhoMin > 0)
     || !(stats_.u2Max <= maxU2)
    )
    {
        instability(current());
    }
}


void Foam::latticeBoltzmannFluid::startInPlace()
{
    // Natural to swapped: exchange the slots of q and opp(q) at every node
    // (the next step then pulls from the neighbours and pushes, lbmLayout.H)
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const labelList& opp = velocitySet_->opp();
    const label block = layout_.block();
    const label pad = layout_.pad();
    scalarList& f = current();
    for (label q = 0; q < Q; ++q)
    {
        if (q < opp[q])
        {
            std::swap_ranges
            (
                f.begin() + q*block,
                f.begin() + (q + 1)*block,
                f.begin() + opp[q]*block
            );
        }
    }
    layout_ = lbmLayout(lbmLayout::SWAPPED, nBox, opp, offset_, pad);
    nextLayout_ = lbmLayout(lbmLayout::PUSHED, nBox, opp, offset_, pad);
    momentumStale_ = true;
}


void Foam::latticeBoltzmannFluid::sumMomentum()
{
    // As the two-lattice loop sums the node's old populations (lbmKernel.H)
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& f = current();
    momX_.setSize(nBox, 0.0);
    momY_.setSize(nBox, 0.0);
    momZ_.setSize(nBox, 0.0);
    for (const label n : lattice_.cellNode())
    {
        scalar px = 0, py = 0, pz = 0;
        for (label q = 0; q < Q; ++q)
        {
            const scalar fq = f[layout_.at(q, n)];
            px += c[q].x()*fq;
            py += c[q].y()*fq;
            pz += c[q].z()*fq;
        }
        momX_[n] = px;
        momY_[n] = py;
        momZ_[n] = pz;
    }
    momentumStale_ = false;
}


void Foam::latticeBoltzmannFluid::exchangeHalo(scalar* f) const
{
    labelList start(velocitySet_->Q());
    forAll(start, q)
    {
        start[q] = layout_.base(q);
    }
    halo_.exchangeSelected(f, start);
}


void Foam::latticeBoltzmannFluid::startAtForceBalance()
{
    // Guo's scheme carries the momentum rho u + F/2 between steps: a water
    // set at rest in a balance of pressure and forces (hydrostatic, or the
    // pore pressure at the soil's surface) carries F/2. Populations set at
    // equilibrium from U carry rho U only, and would start with a jolt of
    // F/2 (large where the porosity jumps): add it, as the first-order
    // Hermite term w_q 3 c_q.F/2 (no mass)
    if (Fx_.empty() && mag(latticeAcceleration()) == 0)
    {
        return;
    }
    const label Q = velocitySet_->Q();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& w = velocitySet_->w();
    const vector g = latticeAcceleration();
    scalarList& f = current();
    momentumStale_ = true;
    for (const label n : lattice_.cellNode())
    {
        scalar rho = 0;
        for (label q = 0; q < Q; ++q)
        {
            rho += f[layout_.at(q, n)];
        }
        vector F = (porosity_.size() ? porosity_[n] : 1.0)*g;
        if (Fx_.size())
        {
            F += vector(Fx_[n], Fy_[n], Fz_[n]);
        }
        for (label q = 0; q < Q; ++q)
        {
            f[layout_.at(q, n)] += 1.5*w[q]*(vector(c[q]) & F);
        }
    }
}


void Foam::latticeBoltzmannFluid::warnUniformPressure() const
{
    // The weight a hydrostatic pressure can balance (along a periodic
    // direction the weight drives the flow)
    const vector g(hydrostaticAcceleration());
    if (mag(g) == 0)
    {
        return;
    }
    const vector up(-g/mag(g));
    const vectorField& C = mesh_.C();
    const labelList& nodeCell = lattice_.nodeCell();
    scalar pMin = GREAT, pMax = -GREAT, hMin = GREAT, hMax = -GREAT;
    for (const label n : lattice_.cellNode())
    {
        if (obstacles_->solid(n) || (freeSurface_ && freeSurface_->gas(n)))
        {
            continue;
        }
        const label celli = nodeCell[n];
        pMin = min(pMin, p_[celli]);
        pMax = max(pMax, p_[celli]);
        hMin = min(hMin, up & C[celli]);
        hMax = max(hMax, up & C[celli]);
    }
    reduce(pMin, minOp<scalar>());
    reduce(pMax, maxOp<scalar>());
    reduce(hMin, minOp<scalar>());
    reduce(hMax, maxOp<scalar>());
    // (water at least two cells deep: its weight over its depth)
    const scalar depth = hMax - hMin + lattice_.dx();
    const scalar weight = units_.rho0()*mag(g)*depth;
    if (depth < 2.5*lattice_.dx() || pMax - pMin > 1e-6*weight)
    {
        return;
    }
    WarningInFunction
        << "The water's initial pressure ("
        << p_.time().timeName(p_.time().startTime().value())
        << "/p) is uniform, " << pMax << " Pa, but"
        << " the water has weight: g = " << g << " m/s2 over its depth of "
        << depth << " m, rho g H = " << weight << " Pa. It starts out of"
        << " hydrostatic balance by that much: it falls under its weight"
        << " and a pressure wave of that size runs through it (a closed"
        << " tank rings; an open one drains through its patches)." << nl
        << "    Set p to the hydrostatic pressure, e.g. with setExprFields"
        << " (p = rho g (h - y) below the level h, as the tutorials do), or"
        << " ignore this if the start is meant" << nl << endl;
}


void Foam::latticeBoltzmannFluid::streamScratch(List<vector>& G)
{
    // The halo, the boundaries' linear part, and the pull: the first
    // moment each owned node receives
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = velocitySet_->c();
    halo_.exchangeSelected(scratch_.data(), nBox);
    boundaries_->fillHomogeneous(scratch_.data(), freeSurface_.get());
    G.setSize(nBox);
    G = Zero;
    for (const label n : lattice_.cellNode())
    {
        vector m(Zero);
        for (label q = 0; q < Q; ++q)
        {
            m += scratch_[q*nBox + n - offset_[q]]*vector(c[q]);
        }
        G[n] = m;
    }
}


void Foam::latticeBoltzmannFluid::streamedForce
(
    const List<vector>& F,
    List<vector>& MF
)
{
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = velocitySet_->c();
    const scalarList& w = velocitySet_->w();
    scratch_.setSize(Q*nBox);
    scratch_ = 0;
    for (const label n : lattice_.cellNode())
    {
        for (label q = 0; q < Q; ++q)
        {
            scratch_[q*nBox + n] = 3*w[q]*(vector(c[q]) & F[n]);
        }
    }
    streamScratch(MF);
}


void Foam::latticeBoltzmannFluid::streamedScalar
(
    const scalarList& X,
    List<vector>& G
)
{
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const scalarList& w = velocitySet_->w();
    scratch_.setSize(Q*nBox);
    scratch_ = 0;
    for (const label n : lattice_.cellNode())
    {
        for (label q = 0; q < Q; ++q)
        {
            scratch_[q*nBox + n] = w[q]*X[n];
        }
    }
    streamScratch(G);
}


// ************************************************************************* //
