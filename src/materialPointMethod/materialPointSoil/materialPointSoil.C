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

#include "materialPointSoil.H"
#include "optionalEntry.H"
#include "restartManifest.H"
#include "unitConversion.H"
#include "selectEntry.H"
#include "volFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(materialPointSoil, 0);
}

const Foam::Enum<Foam::materialPointSoil::transferType>
Foam::materialPointSoil::transferTypeNames
({
    { transferType::PIC, "PIC" },
    { transferType::FLIP, "FLIP" },
    { transferType::APIC, "APIC" },
});

const Foam::Enum<Foam::materialPointSoil::updateType>
Foam::materialPointSoil::updateTypeNames
({
    { updateType::USL, "USL" },
    { updateType::USF, "USF" },
    { updateType::MUSL, "MUSL" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::materialPointSoil::readMaterials()
{
    const dictionary& mats = dict_.subDict("materials");
    materialNames_ = mats.toc();
    if (materialNames_.empty())
    {
        FatalIOErrorInFunction(mats)
            << "materials is empty: the soil needs at least one material"
            << exit(FatalIOError);
    }
    materials_.setSize(materialNames_.size());
    forAll(materialNames_, i)
    {
        materials_.set
        (
            i,
            constitutiveModel::New
            (
                materialNames_[i],
                mats.subDict(materialNames_[i])
            )
        );
    }
}


Foam::scalar Foam::materialPointSoil::pWaveSpeed() const
{
    // (with an added modulus, e.g. the pore water's when the soil is
    // undrained: Biot's undrained modulus M + K_f/n)
    scalar cp = 0;
    forAll(materials_, i)
    {
        cp = max
        (
            cp,
            std::sqrt
            (
                sqr(materials_[i].pWaveSpeed())
              + addedModulus_/materials_[i].rho()
            )
        );
    }
    return cp;
}


Foam::scalar Foam::materialPointSoil::stableDt() const
{
    const scalar cp = pWaveSpeed();
    scalar vmax = 0;
    label fastest = -1;
    forAll(points_.v, p)
    {
        const scalar v2 = magSqr(points_.v[p]);
        if (!(v2 <= vmax))
        {
            vmax = v2;
            fastest = p;
        }
    }
    // A point ten times faster than the fastest p-wave has left the range
    // an explicit MPM step resolves (or is not finite): stop before
    // anything non-finite is written
    if (fastest >= 0 && !(std::sqrt(vmax) < maxSpeed_))
    {
        FatalErrorInFunction
            << "The soil went unstable at time " << mesh_.time().timeName()
            << " s: material point " << points_.id[fastest]
            << " (origId) at "
            << points_.x[fastest] << " moves at " << std::sqrt(vmax)
            << " m/s, above " << maxSpeed_ << " m/s (ten times the largest"
            << " p-wave speed of the materials)." << nl
            << "    Lower soilCFL in system/controlDict (now " << CFL_
            << "), or check the loads the couplings put on the soil."
            << " Nothing of this step was written." << nl;
        // (a cloud edited or damaged since it was written is the likelier
        // cause: named with the files, as the start found them)
        if (restartManifest::suspects.size())
        {
            FatalError
                << "    The start read files changed since they were"
                << " written, the likelier cause:";
            for (const fileName& f : restartManifest::suspects)
            {
                FatalError<< " " << f.c_str();
            }
            FatalError<< nl;
        }
        FatalError<< exit(FatalError);
    }
    // (every processor takes the same sub-steps)
    reduce(vmax, maxOp<scalar>());
    return CFL_*lattice_.dx()/(cp + std::sqrt(vmax));
}


void Foam::materialPointSoil::checkPeriodicReach() const
{
    // The soil's grid does not wrap around cyclic patches: a point whose
    // shape function would reach across one is refused (the water may be
    // periodic around a soil body that stays clear of the seam)
    const labelVector& N = lattice_.globalN();
    const vector& o = lattice_.origin();
    const scalar dx = lattice_.dx();
    const scalar clear = (shape_->reach() + 1)*dx;
    for (direction d = 0; d < 3; ++d)
    {
        if (!lattice_.periodic()[d])
        {
            continue;
        }
        forAll(points_.x, p)
        {
            const scalar x = points_.x[p][d];
            if (x < o[d] + clear || x > o[d] + N[d]*dx - clear)
            {
                FatalErrorInFunction
                    << "Material point " << p << " at " << points_.x[p]
                    << " is within " << clear << " m of the cyclic patches"
                    << " normal to " << vector::componentNames[d]
                    << " at time " << mesh_.time().timeName() << " s" << nl
                    << "    The soil's grid does not wrap around cyclic"
                    << " patches: keep the soil " << shape_->reach() + 1
                    << " cells clear of them, or use walls"
                    << exit(FatalError);
            }
        }
    }
}


Foam::string Foam::materialPointSoil::dilationAdvice
(
    const label p,
    const scalar J
) const
{
    // A constant dilation angle dilates a shearing soil for as long as it
    // shears (no critical state where it stops): the free toe of a layer
    // sliding down a slope (c = 0, psi 15 or 30 deg) swelled a
    // thousandfold within about a second; with psi = 0 it slid on. A
    // point turned inside out (det F < 0) is advised too: a swelling toe
    // also ends so (a new user's probe, 2026-12-07: det F -10928 at
    // 108 m/s, the advice left out)
    const constitutiveModel& model = materials_[points_.material[p]];
    const scalar psi = model.dilationAngle();
    if ((J > 0 && J <= 1) || psi <= 0 || points_.plasticStrain[p] < 0.1)
    {
        return string();
    }
    return
        "\n    The point has sheared plastically (equivalent plastic strain "
      + Foam::name(points_.plasticStrain[p]) + ") in material "
      + model.name() + " of dilation angle "
      + Foam::name(radToDeg(psi)) + " deg: a constant dilation angle"
        " swells the soil for as long as it shears (no critical state"
        " where real soil stops dilating), and a cohesionless soil that"
        " swells at its free surface loses its confinement. For flows of"
        " large deformation try dilationAngle 0 (or a few degrees).";
}


void Foam::materialPointSoil::volumeRunaway
(
    const label p,
    const scalar J
) const
{
    FatalErrorInFunction
        << "The soil went unstable at time " << mesh_.time().timeName()
        << " s: material point " << points_.id[p] << " (origId) at "
        << points_.x[p] << " has " << J << " times its initial volume"
        << " (det F; allowed: " << minVolumeRatio << " to " << maxVolumeRatio
        << "), moving at " << mag(points_.v[p]) << " m/s." << nl
        << "    Its deformation gradient runs away: lower soilCFL in"
        << " system/controlDict (now " << CFL_ << "), "
        << (
               shape_->type() == "linear"
             ? "use a smoother shapeFunction than linear (quadraticBSpline"
               " or GIMP: with linear shape functions a point crossing a"
               " cell face at speed makes its velocity gradient jump), "
             : ""
           )
        << "or check the loads the couplings put on the soil (an impact"
        << " this fast splashes the points apart). Nothing of this step was"
        << " written."
        << dilationAdvice(p, J).c_str()
        << exit(FatalError);
}


void Foam::materialPointSoil::updateConstitutive
(
    const label start,
    const label end
)
{
    const label* material = points_.material.cdata();
    label first = start;
    while (first < end)
    {
        const label m = material[first];
        label last = first + 1;
        while (last < end && material[last] == m)
        {
            ++last;
        }
        materials_[m].updateStresses
        (
            last - first,
            strainIncrement_.cdata() + (first - start),
            points_.sigma.data() + first,
            points_.plasticStrain.data() + first
        );
        first = last;
    }
}


Foam::scalar Foam::materialPointSoil::gravityRampFactor() const
{
    return
        (gravityRamp_ > 0 && time_ < gravityRamp_) ? time_/gravityRamp_ : 1;
}


Foam::vector Foam::materialPointSoil::rampedGravity() const
{
    return gravityRampFactor()*gravity_;
}


void Foam::materialPointSoil::removePoints(const labelUList& gone)
{
    points_.remove(gone, travellingForces(), travellingStresses());
}


void Foam::materialPointSoil::nodeWeights
(
    const label p,
    shapeWeights& sw
) const
{
    pointWeights(p, sw);
}


void Foam::materialPointSoil::migrate()
{
    points_.migrate
    (
        leavingPoint_,
        leavingProc_,
        hasPointForces_ ? &pointForce_ : nullptr,
        hasPointStresses_ ? &pointStress_ : nullptr
    );
    leavingPoint_.clear();
    leavingProc_.clear();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialPointSoil::materialPointSoil(const latticeMesh& lattice)
:
    lattice_(lattice),
    mesh_(lattice.mesh()),
    dict_
    (
        IOobject
        (
            "soilProperties",
            mesh_.time().constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    shape_(shapeFunction::New(dict_)),
    kernels_(shape_->newTransfer()),
    transfer_(selectEntry(transferTypeNames, "transfer", dict_)),
    flipRatio_
    (
        optionalEntry<scalar>(optionalDict(dict_, "FLIPCoeffs"), "ratio", 0.99)
    ),
    flipDamping_
    (
        optionalEntry<scalar>(optionalDict(dict_, "FLIPCoeffs"), "damping", -1)
    ),
    update_
    (
        selectEntry
        (
            updateTypeNames, "updateScheme", dict_, true, updateType::USL
        )
    ),
    CFL_(readCFL()),
    gravity_(Zero),
    gravityRamp_(optionalEntry<scalar>(dict_, "gravityRamp", 0)),
    localDamping_(optionalEntry<scalar>(dict_, "localDamping", 0)),
    time_(mesh_.time().value()),
    haloRoutesSet_(false),
    addedModulus_(0),
    maxSpeed_(GREAT),
    periodic_
    (
        lattice.periodic()[0] || lattice.periodic()[1] || lattice.periodic()[2]
    ),
    hasPointForces_(false),
    hasPointStresses_(false),
    gridExchange_(nullptr),
    nClamped_(0),
    firstClamped_(-1),
    firstClampedAt_(Zero),
    firstClampedSpeed_(0),
    nSubSteps_(0),
    subDt_(0),
    nTotalSubSteps_(0),
    pointUpdates_(0)
{
    if (lattice_.haloWidth() < shape_->reach())
    {
        FatalErrorInFunction
            << "Lattice halo width " << lattice_.haloWidth() << " is below"
            << " the reach " << shape_->reach() << " of shape function "
            << shape_->type() << abort(FatalError);
    }
    if (dict_.found("CFL"))
    {
        // The time step is controlDict's business, with deltaT and maxCo:
        // a CFL left here would be silently ignored
        FatalIOErrorInFunction(dict_)
            << "CFL is not read from constant/soilProperties: the soil's"
            << " Courant number is soilCFL in system/controlDict (a value"
            << " in (0, 1], default 0.5)" << exit(FatalIOError);
    }
    if (dict_.found("gravity"))
    {
        // Gravity comes from constant/g, one way for every phase: the old
        // keyword would be silently ignored
        FatalIOErrorInFunction(dict_)
            << "gravity is not read from constant/soilProperties: it is the"
            << " gravity effect's, from constant/g (value (...);): add"
            << " gravity to effects in constant/physicsProperties (the"
            << " optional gravityRamp stays here)" << exit(FatalIOError);
    }
    if (!(gravityRamp_ >= 0))
    {
        FatalIOErrorInFunction(dict_)
            << "gravityRamp " << gravityRamp_ << " is not allowed: it must be"
            << " >= 0 [s]" << exit(FatalIOError);
    }
    if (!(localDamping_ >= 0 && localDamping_ < 1))
    {
        FatalIOErrorInFunction(dict_)
            << "localDamping " << localDamping_ << " is not allowed: it must"
            << " lie in [0, 1)" << exit(FatalIOError);
    }
    const dictionary& flipDict = optionalDict(dict_, "FLIPCoeffs");
    if (flipDict.found("ratio") && flipDict.found("damping"))
    {
        FatalIOErrorInFunction(flipDict)
            << "FLIPCoeffs gives both ratio and damping: give one (ratio, the"
            << " FLIP share per sub-step in [0, 1]; or damping, the PIC share"
            << " as a rate in [0, 1e6] 1/s, independent of the soil's time"
            << " step)" << exit(FatalIOError);
    }
    if (flipDict.found("damping") && !(flipDamping_ >= 0 && flipDamping_ <= 1e6))
    {
        FatalIOErrorInFunction(flipDict)
            << "FLIPCoeffs: damping " << flipDamping_ << " is not allowed: it"
            << " must lie in [0, 1e6] 1/s (0: pure FLIP; the FLIP share of a"
            << " sub-step dt is exp(-damping dt))" << exit(FatalIOError);
    }
    if (!(flipRatio_ >= 0 && flipRatio_ <= 1))
    {
        FatalIOErrorInFunction(dict_)
            << "FLIPCoeffs: ratio " << flipRatio_ << " is not allowed: it must"
            << " lie in [0, 1] (0: PIC, 1: pure FLIP)" << exit(FatalIOError);
    }

    readMaterials();
    maxSpeed_ = 0;
    forAll(materials_, i)
    {
        maxSpeed_ = max(maxSpeed_, 10*materials_[i].pWaveSpeed());
    }
    walls_.reset
    (
        new soilWalls
        (
            lattice_,
            dict_.subDict("walls"),
            shape_->reach(),
            shape_->type()
        )
    );
    // Known issue (a new user's probe, 2026-12-07, diagnosed the same day):
    // an elastic block sliding on a Coulomb friction wall starts to rock
    // and bounce from about 0.1 s (its lift and rocking growing with an
    // e-folding time of about 30-50 ms, to 1-3 cm/s), and near its sticking
    // angle it then creeps further than a rigid block's Coulomb law gives
    // (16.9 degrees, mu 0.3, nu 0.2, gravity ramped over 0.5 s: 0.26-0.36 m
    // in 3 s against 0.136 m at 4 and 8 cells across its height, with APIC,
    // FLIP and every shape function; PIC's damping held it at the coarser
    // grid, not at 16 cells). It needs friction (coefficient 0 slides as
    // g sin(theta) to 0.02%), grows with Poisson's ratio (nu 0 and 0.1:
    // Coulomb's slide to 0.5% at 4 and 8 cells; 0.3, 0.45 unstable) and
    // with the grid's fineness, and away from sticking the slide is
    // Coulomb's (mu 0.2, 0.25: 0.05%) though the block still rocks: the
    // signature of the frictional slip-wave instability of elastic bodies
    // under a constant Coulomb coefficient (Adams 1995, J. Appl. Mech. 62,
    // 867; Adams 1998, J. Appl. Mech. 65, 470: an apparent friction below
    // the interface's; Brener et al. 2016, JMPS 89, 149). Ruled out as
    // causes: the transfer, the update scheme (USL, USF, MUSL), the affine
    // velocity's form (C = B D^-1 instead of the velocity gradient) and the
    // contact's place half a cell inside the face (the contact at the face,
    // commit 595fc3e, crept as well: APIC 0.276 and 0.302 m, FLIP 0.135 and
    // 0.182 m at 4 and 8 cells).
    if (walls_->maxFrictionCoefficient() > 0)
    {
        wordList elastic;
        forAll(materials_, i)
        {
            if (materials_[i].type() == "linearElastic")
            {
                elastic.append(materialNames_[i]);
            }
        }
        if (elastic.size())
        {
            WarningInFunction
                << "the elastic material(s) " << elastic
                << " on a friction wall: an elastic body sliding under a"
                << " constant Coulomb coefficient can rock and bounce"
                << " (frictional slip waves, Adams 1995), and near its"
                << " sticking angle then creeps further than Coulomb's law"
                << " gives, more on finer grids (16.9 degrees, mu 0.3, nu"
                << " 0.2: 0.26-0.36 m in 3 s against 0.136 m; nu 0 and 0.1"
                << " held Coulomb's slide to 0.5%)." << nl
                << "    A known issue: see the README's soilProperties row"
                << endl;
        }
    }

    // Grid
    const label nBox = lattice_.nBox();
    gridMass_.setSize(nBox, 0.0);
    gridMomentum_.setSize(nBox, Zero);
    gridForce_.setSize(nBox, Zero);
    gridVelocity_.setSize(nBox, Zero);
    gridVelocityOld_.setSize(nBox, Zero);
    strainIncrement_.setSize(soilTransfer::pointBlock);

    // The owner of every node a point can move into
    nodeOwner_.setSize(nBox, -1);
    for (const label n : lattice_.cellNode())
    {
        nodeOwner_[n] = Pstream::myProcNo();
    }
    forAll(lattice_.halo().recvNodes(), proci)
    {
        for (const label n : lattice_.halo().recvNodes()[proci])
        {
            nodeOwner_[n] = proci;
        }
    }

    // Points
    if (!points_.read(mesh_, mesh_.time().timeName()))
    {
        FatalErrorInFunction
            << "No material points in " << mesh_.time().timePath()
            << "/lagrangian/" << materialPoints::cloudName << nl
            << "    Make them with setMaterialPoints (system/"
            << "setMaterialPointsDict)" << exit(FatalError);
    }
    checkAgainstWriter();
    // (the files these come from, named: a damaged cloud)
    const fileName cloudDir
    (
        mesh_.time().timePath()/"lagrangian"/materialPoints::cloudName
    );
    forAll(points_.material, p)
    {
        if (points_.material[p] < 0 || points_.material[p] >= materials_.size())
        {
            FatalErrorInFunction
                << "Material point " << p << " has material index "
                << points_.material[p] << " (" << cloudDir/"material"
                << ") but soilProperties defines "
                << materials_.size() << " materials " << materialNames_
                << exit(FatalError);
        }
        shape_->checkHalfLength
        (
            points_.halfLength[p].x(),
            cloudDir/"halfLength" + ", point " + Foam::name(p)
        );
    }

    Info<< "Material point soil" << nl
        << "    points       " << nPoints() << " ("
        << materialPoints::memoryPerPoint() << " bytes per point)" << nl
        << "    shape function " << shape_->type() << ", transfer "
        << transferTypeNames[transfer_];
    if (transfer_ == transferType::FLIP)
    {
        if (flipDamping_ >= 0)
        {
            Info<< " (damping " << flipDamping_ << " 1/s)";
        }
        else
        {
            Info<< " (ratio " << flipRatio_ << ")";
        }
    }
    Info<< ", update " << updateTypeNames[update_] << nl;
    if (gravityRamp_ > 0)
    {
        Info<< "    gravity (constant/g) ramped over " << gravityRamp_ << " s"
            << nl;
        scalar sigmaMax = 0;
        for (const symmTensor& sigma : points_.sigma)
        {
            sigmaMax = max(sigmaMax, mag(sigma));
        }
        reduce(sigmaMax, maxOp<scalar>());
        if (time_ <= 0 && sigmaMax > 0)
        {
            // A stress that carries the soil's whole weight (a geostatic
            // start) under a gravity that starts from 0: the soil heaves
            // while the ramp lasts (a 10 m column 5.9 mm, its stress 80%
            // low at half the ramp)
            WarningInFunction
                << "The points start stressed (up to " << sigmaMax
                << " Pa, e.g. setMaterialPoints' geostatic stress) and"
                << " soilProperties' gravityRamp " << gravityRamp_
                << " s grows gravity from 0: the stress lifts the soil"
                << " until the ramp ends. A geostatic start needs"
                << " gravityRamp 0; a ramp starts from zero stress."
                << endl;
        }
    }
    if (localDamping_ > 0)
    {
        Info<< "    local damping " << localDamping_ << nl;
    }
    forAll(materials_, i)
    {
        Info<< "  ";
        materials_[i].report(Info);
    }
    Info<< "    stable time step " << stableDt() << " s (CFL " << CFL_
        << "); controlDict deltaT " << mesh_.time().deltaTValue() << " s"
        << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::materialPointSoil::haloWidth(const fvMesh& mesh)
{
    const IOdictionary dict
    (
        IOobject
        (
            "soilProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const label reach = shapeFunction::New(dict)->reach();

    // Missing cells: fewer cells than the bounding box holds (the mesh is
    // uniform; latticeMesh checks that)
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    const scalar cellVolume =
        returnReduce(mesh.nCells() ? mesh.V()[0] : scalar(0), maxOp<scalar>());
    const boundBox bb(mesh.points(), true);
    const bool missing =
        cellVolume > 0 && nCells + 0.5 < bb.volume()/cellVolume;

    return max(label(2), missing ? 3*reach - 1 : reach);
}


Foam::scalar Foam::materialPointSoil::readCFL() const
{
    // Read at every outer step, so an edit of a running case's controlDict
    // (runTimeModifiable) takes effect, as maxCo does for OpenFOAM's solvers
    const dictionary& control = mesh_.time().controlDict();
    const scalar CFL = optionalEntry<scalar>(control, "soilCFL", 0.5);
    if (!(CFL > 0 && CFL <= 1))
    {
        FatalIOErrorInFunction(control)
            << "soilCFL " << CFL << " is not allowed: it must lie in (0, 1]"
            << " (the soil's sub-step over dx/(c_p + |v|))"
            << exit(FatalIOError);
    }
    return CFL;
}


void Foam::materialPointSoil::advance(const scalar deltaT)
{
    if (nTotalSubSteps_ == 0 && gravityRamp_ > 0 && mag(gravity_) == 0)
    {
        // (the effects are all set at the first step: the gravity effect
        // gives the soil its gravity)
        FatalIOErrorInFunction(dict_)
            << "gravityRamp " << gravityRamp_ << " s: the soil feels no"
            << " gravity to ramp (constant/physicsProperties has no gravity"
            << " effect acting on the soil)." << nl
            << "    Add gravity to effects in constant/physicsProperties, or"
            << " remove gravityRamp" << exit(FatalIOError);
    }
    CFL_ = readCFL();
    const scalar dtStable = stableDt();
    if (!(deltaT/dtStable <= 1e7))
    {
        FatalErrorInFunction
            << "At time " << time_ << " s the soil's stable step is "
            << dtStable << " s (soilCFL " << CFL_ << " dx/(c_p + |v|), the"
            << " p-wave speed " << pWaveSpeed() << " m/s): "
            << deltaT/dtStable << " sub-steps per step of deltaT " << deltaT
            << " s, more than 1e7." << nl
            << "    Check E and rho of the materials in constant/soilProperties"
            << " (c_p = sqrt(M/rho)), or the soil has gone unstable (a point"
            << " far faster than c_p)" << exit(FatalError);
    }
    nSubSteps_ = max(label(std::ceil(deltaT/dtStable - 1e-9)), label(1));
    subDt_ = deltaT/nSubSteps_;
    sortPoints();
    if (gridExchange_)
    {
        gridExchange_->begin(deltaT);
    }
    // The sub-steps' times from the step's start, which a restart reads
    // back exactly (accumulated, they drifted from it: the gravity ramp
    // then differed in the last bits after a restart)
    const scalar start = time_;
    for (label s = 0; s < nSubSteps_; ++s)
    {
        time_ = start + (s + 1)*subDt_;
        subStep(subDt_);
    }
    time_ = start + deltaT;
    if (gridExchange_)
    {
        gridExchange_->end();
    }
    nTotalSubSteps_ += nSubSteps_;
    pointUpdates_ += scalar(nSubSteps_)*nPoints();

    const label nClamped = returnReduce(nClamped_, sumOp<label>());
    if (nClamped)
    {
        // The first point held, of the lowest processor that held any
        const label proc = returnReduce
        (
            nClamped_ ? Pstream::myProcNo() : Pstream::nProcs(),
            minOp<label>()
        );
        const bool mine = (proc == Pstream::myProcNo());
        const label id =
            returnReduce(mine ? firstClamped_ : label(0), sumOp<label>());
        const vector at =
            returnReduce(mine ? firstClampedAt_ : vector::zero, sumOp<vector>());
        const scalar speed =
            returnReduce(mine ? firstClampedSpeed_ : scalar(0), sumOp<scalar>());
        WarningInFunction
            << nClamped << " material point moves out of the domain were"
            << " stopped at its boundary (a wall or the face of a missing"
            << " cell) at time " << mesh_.time().timeName() << " s, the"
            << " first by point " << id << " (origId) at " << at
            << ", moving at " << speed << " m/s" << nl
            << "    The points hit the boundary faster than the grid stops"
            << " them: lower soilCFL in system/controlDict (now " << CFL_
            << ") or check the loads on the soil" << endl;
    }
    nClamped_ = 0;
}


Foam::label Foam::materialPointSoil::nPoints() const
{
    return returnReduce(points_.size(), sumOp<label>());
}


Foam::scalar Foam::materialPointSoil::memoryBytes() const
{
    // Per point the stored arrays only: the weights are evaluated where
    // they are used, the strain increments kept for one block of points.
    // Per box node: mass, momentum, force, velocity and old velocity, the
    // particle-to-grid records (8 doubles) and the padded velocities: 4
    // doubles where a stress update reads them apart from G2P (USF, MUSL,
    // or any transfer but FLIP), 8 for FLIP's velocity and change
    const bool flip = (transfer_ == transferType::FLIP);
    const label nPadded =
        (flip ? 8 : 0) + (!flip || update_ != updateType::USL ? 4 : 0);
    return returnReduce
    (
        scalar(points_.size())*materialPoints::memoryPerPoint()
      + scalar(soilTransfer::pointBlock)*sizeof(symmTensor)
      + scalar(lattice_.nBox())
       *(sizeof(scalar) + 4*sizeof(vector) + (8 + nPadded)*sizeof(scalar)),
        sumOp<scalar>()
    );
}


Foam::scalar Foam::materialPointSoil::minPorosity() const
{
    scalar n = 1;
    for (const scalar np : points_.porosity)
    {
        n = min(n, np);
    }
    return returnReduce(n, minOp<scalar>());
}


Foam::vector Foam::materialPointSoil::momentum() const
{
    vector sum(Zero);
    forAll(points_.v, p)
    {
        sum += points_.m[p]*points_.v[p];
    }
    if (Pstream::parRun())
    {
        reduce(sum, sumOp<vector>());
    }
    return sum;
}


Foam::scalar Foam::materialPointSoil::kineticEnergy() const
{
    scalar e = 0;
    forAll(points_.v, p)
    {
        e += 0.5*points_.m[p]*magSqr(points_.v[p]);
    }
    // (reduced only in parallel: the serial sum stays as it was, to the
    // bit, whatever the compiler makes of the loop)
    if (Pstream::parRun())
    {
        reduce(e, sumOp<scalar>());
    }
    return e;
}


// ************************************************************************* //
