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

#include "physicsScene.H"
#include "optionalEntry.H"
#include "caseChecks.H"
#include "Time.H"
#include "functionObjectList.H"
#include "timeControlFunctionObject.H"
#include "HashSet.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(physicsScene, 0);
}

const Foam::word Foam::physicsScene::registryName("physicsScene");


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::physicsScene::build(const label i)
{
    if (effects_.set(i))
    {
        return;
    }
    if (building_[i])
    {
        FatalIOErrorInFunction(dict_)
            << "effect " << names_[i] << " needs, through the effects it"
            << " needs, itself: a cycle no order of construction can meet"
            << exit(FatalIOError);
    }
    building_[i] = true;
    buildStack_.append(i);
    effects_.set(i, physicsEffect::New(names_[i], *this, dict_));
    buildStack_.remove();
    building_[i] = false;
}


void Foam::physicsScene::missingEffect(const word& name) const
{
    const word by =
        buildStack_.size() ? names_[buildStack_.last()] : word("the scene");
    FatalIOErrorInFunction(dict_)
        << "effect " << by << " needs effect " << name
        << ", which the scene does not select." << nl
        << "    effects " << names_ << ";" << nl
        << "    Add " << name << " to the list or remove " << by << "."
        << exit(FatalIOError);
}


void Foam::physicsScene::planSteps()
{
    // Every stage in its order; within a stage, the effects as listed
    DynamicList<Tuple2<sceneStage, label>> steps;
    for (int s = 0; s <= int(sceneStage::endStep); ++s)
    {
        const sceneStage stage = sceneStage(s);
        forAll(effects_, i)
        {
            if (effects_[i].stages().found(stage))
            {
                steps.append(Tuple2<sceneStage, label>(stage, i));
            }
        }
    }
    steps_.transfer(steps);

    Info<< "Step:";
    for (const Tuple2<sceneStage, label>& step : steps_)
    {
        Info<< ' ' << sceneStageNames[step.first()] << " ("
            << names_[step.second()] << ")";
    }
    Info<< nl << endl;
}


void Foam::physicsScene::checkRequirements() const
{
    forAll(effects_, i)
    {
        for (const word& needed : effects_[i].requires())
        {
            if (!names_.found(needed))
            {
                FatalIOErrorInFunction(dict_)
                    << "effect " << names_[i] << " needs effect " << needed
                    << ", which the scene does not select." << nl
                    << "    effects " << names_ << ";" << nl
                    << "    Add " << needed << " to the list or remove "
                    << names_[i] << "." << exit(FatalIOError);
            }
        }
    }
}


void Foam::physicsScene::progress()
{
    const scalar wall = start_.elapsed();
    const Time& runTime = runTime_;

    if (nSteps_ == 1)
    {
        firstStepWall_ = wall;
    }
    const scalar stepsWall = wall - firstStepWall_;

    // Decided on wall clocks that differ between processors: agree, since
    // the report below is collective. Projected from the steps after the
    // first, over 50 of them or 2 s
    bool first =
        !projected_ && nSteps_ > 1 && (stepsWall > 2.0 || nSteps_ > 50);
    bool due = scalar(lastProgress_.elapsed()) >= progressInterval_;
    const bool last = (nSteps_ == nStepsTotal_);
    reduce(first, orOp<bool>());
    reduce(due, orOp<bool>());

    if (!first && !due && !last)
    {
        return;
    }

    // The remaining steps at the pace of those after the first
    const scalar perStep =
        nSteps_ > 1 ? stepsWall/(nSteps_ - 1) : wall/max(nSteps_, label(1));
    const scalar eta = perStep*max(nStepsTotal_ - nSteps_, label(0));

    if (first)
    {
        projected_ = true;
        Info<< "Projected wall time "
            << firstStepWall_ + perStep*(nStepsTotal_ - 1) << " s for "
            << nStepsTotal_ << " steps (" << perStep << " s per step,"
            << " measured over " << nSteps_ - 1 << " steps after the first,"
            << " which took " << firstStepWall_ << " s)" << nl << endl;
    }

    if (due || last)
    {
        lastProgress_.update();
        scalar updates = 0;
        forAll(effects_, i)
        {
            updates += effects_[i].updatesDone();
        }
        Info<< "Time = " << runTime.timeName() << " s  step " << nSteps_
            << "/" << nStepsTotal_ << " ("
            << label(100.0*nSteps_/max(nStepsTotal_, label(1))) << "%)"
            << "  wall " << label(wall) << " s  ETA " << label(eta + 0.5)
            << " s  " << updates/max(wall, VSMALL)/1e6
            << " M updates/s";
        forAll(effects_, i)
        {
            const string s = effects_[i].progress();
            if (!s.empty())
            {
                Info<< "  " << s.c_str();
            }
        }
        Info<< endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsScene::physicsScene(Time& runTime, fvMesh& mesh)
:
    regIOobject
    (
        IOobject
        (
            registryName,
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    runTime_(runTime),
    mesh_(mesh),
    dict_
    (
        IOobject
        (
            "physicsProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    names_(dict_.get<wordList>("effects")),
    writeTime_(0),
    fieldTime_(0),
    fieldRefreshes_(0),
    progressInterval_(optionalEntry<scalar>(dict_, "progressInterval", 10)),
    deltaT_(runTime.deltaTValue()),
    fixedTimeStep_(false),
    nSteps_(0),
    nStepsTotal_(0),
    projected_(false),
    firstStepWall_(0)
{
    if (names_.empty())
    {
        FatalIOErrorInFunction(dict_)
            << "effects () is empty: the scene must select at least one"
            << " effect, e.g. effects (fluid);" << exit(FatalIOError);
    }
    forAll(names_, i)
    {
        for (label j = 0; j < i; ++j)
        {
            if (names_[i] == names_[j])
            {
                FatalIOErrorInFunction(dict_)
                    << "effect " << names_[i] << " is listed twice in effects "
                    << names_ << exit(FatalIOError);
            }
        }
    }

    Info<< "Scene effects: " << names_ << nl << endl;

    // A restart's files as written, before anything reads them
    restartManifest::checkFiles(runTime);
    restartManifest::checkEffects(runTime, names_);

    // The lattice every effect shares, with the widest halo they declare
    label haloWidth = 1;
    for (const word& name : names_)
    {
        haloWidth =
            max(haloWidth, physicsEffect::haloWidthOf(name, mesh_, dict_));
    }
    lattice_.reset(new latticeMesh(mesh_, haloWidth));
    lattice_->report(Info);

    // In the order listed; an effect builds those it needs first
    effects_.setSize(names_.size());
    building_.setSize(names_.size(), false);
    forAll(names_, i)
    {
        build(i);
    }
    checkRequirements();
    planSteps();
    fixedTimeStep_ = false;
    forAll(effects_, i)
    {
        fixedTimeStep_ = fixedTimeStep_ || effects_[i].fixedTimeStep();
    }

    // The state read as written (a processor's missing cloud, say)
    {
        restartManifest::stateTable state;
        restartManifest::stateSources sources;
        forAll(effects_, i)
        {
            effects_[i].restartState(state);
            effects_[i].restartStateSources(sources);
        }
        restartManifest::checkState(runTime, state, sources);
    }
    effectTime_.setSize(effects_.size(), 0);

    // What the run will cost
    nStepsTotal_ = label
    (
        (runTime.endTime().value() - runTime.startTime().value())
       /runTime.deltaTValue() + 0.5
    );
    scalar memory = 0, updates = 0;
    forAll(effects_, i)
    {
        memory += effects_[i].memoryBytes();
        updates += effects_[i].updatesPerStep();
    }
    Info<< "Run plan" << nl
        << "    steps        " << nStepsTotal_ << " of " << runTime.deltaTValue()
        << " s from " << runTime.startTime().value() << " s to "
        << runTime.endTime().value() << " s" << nl
        << "    updates      " << updates << " per step" << nl
        << "    memory       " << memory/1048576.0 << " MiB for the"
        << " effects' data" << nl;
    forAll(effects_, i)
    {
        const string s = effects_[i].plan();
        if (!s.empty())
        {
            Info<< "    " << names_[i] << ": " << s.c_str() << nl;
        }
    }
    Info<< endl;

    start_.update();
    lastProgress_ = start_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::physicsScene::needsSoilWithWater() const
{
    forAll(effects_, i)
    {
        if (effects_[i].needsSoilWithWater())
        {
            return true;
        }
    }
    return false;
}


void Foam::physicsScene::keepDeltaT()
{
    const scalar dt = runTime_.deltaTValue();
    if (dt != deltaT_ && fixedTimeStep_)
    {
        // (the step taken at the new deltaT while the lattice steps the
        // old one ran the water at twice its labelled time, unsaid)
        WarningInFunction
            << "deltaT " << dt << " s read from "
            << runTime_.system()/"controlDict" << " while running is"
            << " not taken: this run keeps deltaT " << deltaT_ << " s, with"
            << " which its lattice units were made (the water's velocity in"
            << " dx/deltaT, its pressure in rho (dx/deltaT)^2/3, its tau)."
            << nl << "    To change the step, end the run (stopAt writeNow)"
            << " and start from 0 with the new deltaT; a restart with"
            << " another deltaT than the written water's is refused" << nl
            << endl;
        runTime_.setDeltaT(deltaT_, false);
    }
}


void Foam::physicsScene::evolve()
{
    for (const Tuple2<sceneStage, label>& step : steps_)
    {
        const clockValue t0(clockValue::now());
        run(step);
        effectTime_[step.second()] += t0.elapsed();
    }
    ++nSteps_;
    progress();
}


namespace
{

//- Whether a function object of this type reads the fields only when it
//  writes
bool sampleOnWriteOnly(const Foam::word& type, const Foam::dictionary& dict)
{
    using namespace Foam;
    // OpenFOAM's (v1912) objects whose execute() does nothing: they read
    // the fields in write() alone, so only their writeControl needs the
    // fields (probes at every step, written every 10 steps, refreshed
    // them at every step: 75% of a run's wall time). sampledSurfaces
    // samples in execute() too with sampleOnExecute.
    static const wordHashSet writeOnly
    ({
        "probes",
        "patchProbes",
        "sets",
        "fieldMinMax",
        "surfaceFieldValue",
        "volFieldValue",
        "writeObjects"
    });
    return
        writeOnly.found(type)
     || (type == "surfaces" && !dict.getOrDefault("sampleOnExecute", false));
}

} // End anonymous namespace


bool Foam::physicsScene::functionObjectsReadFields() const
{
    const functionObjectList& objects = runTime_.functionObjects();
    if (!objects.status())
    {
        return false;
    }
    // The project's own function objects read the lattice and the points
    static const wordHashSet ownTypes
    ({
        "latticeForces",
        "latticeWallShearStress",
        "materialPointProbes"
    });
    forAll(objects, i)
    {
        // (an object with time controls is wrapped in a timeControl; one
        // without executes and writes at every step)
        const functionObject& fo = objects[i];
        if (!isA<functionObjects::timeControl>(fo))
        {
            if (!ownTypes.found(fo.type()))
            {
                return true;
            }
            continue;
        }
        const functionObjects::timeControl& controlled =
            refCast<const functionObjects::timeControl>(fo);
        const word& type = controlled.filter().type();
        if
        (
            !ownTypes.found(type)
         && (
                (
                    !sampleOnWriteOnly(type, controlled.dict())
                 && controlFires(controlled.executeControl())
                )
             || controlFires(controlled.writeControl())
            )
         && withinTimeWindow(controlled.dict())
        )
        {
            return true;
        }
    }
    return false;
}


bool Foam::physicsScene::controlFires(const Foam::timeControl& control) const
{
    // As Foam::timeControl::execute() decides (v1912), without changing its
    // state: an object samples or writes the fields in its execute() or
    // its write(), each under its own control
    const scalar interval = control.interval();
    switch (control.control())
    {
        case Foam::timeControl::ocNone:
            return false;
        case Foam::timeControl::ocTimeStep:
        {
            const label every = label(interval);
            return every <= 1 || runTime_.timeIndex() % every == 0;
        }
        case Foam::timeControl::ocWriteTime:
            // (called off the write times only)
            return runTime_.writeTime();
        case Foam::timeControl::ocRunTime:
        case Foam::timeControl::ocAdjustableRunTime:
        {
            if (!(interval > 0))
            {
                return true;
            }
            // It fires when the index of its interval grows: from the
            // previous step to this one
            const scalar t0 = runTime_.startTime().value();
            const scalar dt = runTime_.deltaTValue();
            const scalar t = runTime_.value();
            return
                label((t - t0 + 0.5*dt)/interval)
              > label((t - dt - t0 + 0.5*dt)/interval);
        }
        default:
            // (always, cpuTime, clockTime, onEnd: as it may fire)
            return true;
    }
}


bool Foam::physicsScene::withinTimeWindow(const dictionary& dict) const
{
    // functionObjects::timeControl's timeStart and timeEnd (OpenFOAM's
    // keywords, read here every step: no spelling check, which OpenFOAM
    // does not make either)
    const scalar t = runTime_.value();
    return
        t >= dict.getOrDefault<scalar>("timeStart", -GREAT)
     && t <= dict.getOrDefault<scalar>("timeEnd", GREAT);
}


void Foam::physicsScene::updateFields()
{
    forAll(effects_, i)
    {
        effects_[i].updateFields();
    }
}


void Foam::physicsScene::write()
{
    if (!runTime_.writeTime())
    {
        // Function objects execute after this, in Time::run: they read the
        // fields of this step (the cost paid only when one reads them)
        if (functionObjectsReadFields())
        {
            const clockValue t0(clockValue::now());
            updateFields();
            fieldTime_ += t0.elapsed();
            ++fieldRefreshes_;
        }
        return;
    }
    // The effects' outputs, then the registered fields (U, p, rho, ...):
    // all counted as writing in the run's cost
    // A time is complete or set aside at a restart (restartManifest)
    const clockValue t0(clockValue::now());
    restartManifest::beginWrite(runTime_);
    // A failed write (a full disk) reported as what it is, with what to do
    bool fieldsWritten = true;
    string failure = catchFatal
    (
        [&]()
        {
            updateFields();
            forAll(effects_, i)
            {
                effects_[i].write();
            }
            fieldsWritten = runTime_.write();
        },
        false
    );
    if (failure.empty() && !fieldsWritten)
    {
        failure = "OpenFOAM could not write the registered fields";
    }
    if (!failure.empty())
    {
        FatalErrorInFunction
            << "Writing time " << runTime_.timeName() << " in "
            << runTime_.timePath() << " failed:" << nl << "    "
            << failure.c_str() << nl
            << "    Is the disk full, or the folder not writable? The time"
            << " keeps the marker " << restartManifest::incompleteMarker
            << ": a restart from the latest time sets it aside and starts"
            << " from the last complete time." << exit(FatalError);
    }
    restartManifest::stateTable state;
    DynamicList<word> exact;
    forAll(effects_, i)
    {
        effects_[i].restartState(state);
        exact.append(effects_[i].stateFiles());
    }
    restartManifest::endWrite
    (
        runTime_, "mpmLbmFoam", state, exact, wordList(), names_
    );
    writeTime_ += t0.elapsed();
}


void Foam::physicsScene::summary() const
{
    const scalar wall = start_.elapsed();
    scalar updates = 0;
    forAll(effects_, i)
    {
        updates += effects_[i].updatesDone();
    }

    Info<< nl << "Run cost" << nl
        << "    steps        " << nSteps_ << nl
        << "    wall time    " << wall << " s" << nl;
    if (nSteps_ && wall > 0)
    {
        Info<< "    throughput   " << updates/wall/1e6
            << " M updates/s over all effects" << nl;
    }
    forAll(effects_, i)
    {
        const scalar t = effectTime_[i];
        Info<< "    " << names_[i] << ": " << t << " s ("
            << label(100*t/max(wall, VSMALL) + 0.5) << "%)";
        if (t > 0 && effects_[i].updatesDone() > 0)
        {
            Info<< ", " << effects_[i].updatesDone()/t/1e6
                << " M " << effects_[i].updateUnit() << " updates/s";
        }
        Info<< nl;
    }
    Info<< "    writing: " << writeTime_ << " s" << nl;
    if (fieldTime_ > 0)
    {
        Info<< "    fields for function objects: " << fieldTime_ << " s ("
            << label(100*fieldTime_/max(wall, VSMALL) + 0.5) << "%, "
            << fieldRefreshes_ << " refreshes off the write times, at the"
            << " steps their execute or write control fires)" << nl;
    }
    // The rest of the wall time: the function objects' own work, the
    // start-up, the progress reports
    const scalar other = wall - sum(effectTime_) - writeTime_ - fieldTime_;
    if (runTime_.functionObjects().status() && runTime_.functionObjects().size())
    {
        Info<< "    function objects, start-up and the rest: " << other
            << " s (" << label(100*other/max(wall, VSMALL) + 0.5) << "%)"
            << nl;
    }
    Info<< endl;
}


void Foam::physicsScene::estimate()
{
    if (nStepsTotal_ <= 0)
    {
        Info<< nl << "Estimate: the case is at its endTime ("
            << runTime_.endTime().value() << " s): there are no steps to"
            << " run. Raise endTime in system/controlDict to estimate a"
            << " continuation." << nl << "    Nothing was written." << nl
            << endl;
        return;
    }

    // The first steps are slower (memory touched for the first time,
    // caches cold): timed from the third on, as a long run sees them
    const label nWarmUp = min(label(2), nStepsTotal_ - 1);
    clockValue t0(clockValue::now());
    label n = 0;
    // (not Time::run(): at a write time it executes the function objects,
    // which write their state into a time folder)
    while
    (
        runTime_.value() + 0.5*runTime_.deltaTValue()
      < runTime_.endTime().value()
     && n < 50 + nWarmUp
    )
    {
        ++runTime_;
        // (not endStep: its per-step outputs would write)
        for (const Tuple2<sceneStage, label>& step : steps_)
        {
            if (step.first() != sceneStage::endStep)
            {
                run(step);
            }
        }
        ++n;
        if (n == nWarmUp)
        {
            t0.update();
        }
        bool enough = n > nWarmUp && scalar(t0.elapsed()) > 3.0;
        reduce(enough, orOp<bool>());
        if (enough)
        {
            break;
        }
    }
    n = max(n - nWarmUp, label(1));
    const scalar wall = t0.elapsed();
    const scalar perStep = wall/n;
    scalar memory = 0;
    forAll(effects_, i)
    {
        memory += effects_[i].memoryBytes();
    }
    const label D = lattice_->nDim();
    const scalar nodesFactor = std::pow(2.0, D);

    // Halving dx at a fixed lattice Mach number (acoustic scaling) halves
    // the time step: nodes x 2^D, steps x 2. The soil's points and
    // sub-steps scale alike (CFL). At fixed tau (diffusive scaling) the
    // water needs 4 times the steps instead of 2. A scene without water
    // has only the soil's CFL scaling.
    const bool water = names_.found("fluid");
    const scalar total = perStep*nStepsTotal_;
    auto duration = [](const scalar t)
    {
        return
            Foam::name(t) + " s"
          + (t > 3600 ? " (" + Foam::name(t/3600) + " h)" : std::string());
    };
    // Wall time with the nodes (and points) times nodes and the steps
    // times steps at fixed lattice Mach (the soil's CFL alike), steps^2 at
    // fixed tau
    auto scaled = [&](const scalar nodes, const scalar steps)
    {
        return
            water
          ? duration(total*nodes*steps) + " at fixed lattice Mach ("
          + duration(total*nodes*steps*steps) + " at fixed tau)"
          : duration(total*nodes*steps) + " (the soil's CFL: steps x "
          + Foam::name(steps) + ")";
    };
    Info<< nl << "Estimate from " << n << " steps (" << perStep
        << " s per step, after " << nWarmUp << " warm-up steps)" << nl
        << "    case as set up:  wall time " << duration(total).c_str()
        << " for " << nStepsTotal_ << " steps, memory "
        << memory/1048576.0 << " MiB" << nl
        << "    dx halved:       wall time "
        << scaled(nodesFactor, 2).c_str() << ", memory "
        << memory*nodesFactor/1048576.0 << " MiB" << nl
        << "    dx doubled:      wall time "
        << scaled(1/nodesFactor, 0.5).c_str() << ", memory "
        << memory/nodesFactor/1048576.0 << " MiB" << nl
        << "    Writing is not included. Nothing was written." << nl << endl;
}


// ************************************************************************* //
