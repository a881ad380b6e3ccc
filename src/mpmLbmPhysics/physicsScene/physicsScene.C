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
#include "materialPointSoil.H"
#include "Time.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(physicsScene, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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
    const clock::time_point now = clock::now();
    const scalar wall = seconds(start_, now);
    const Time& runTime = mesh_.time();

    // Decided on wall clocks that differ between processors: agree, since
    // the report below is collective
    bool first = !projected_ && (wall > 2.0 || nSteps_ >= 50);
    bool due = seconds(lastProgress_, now) >= progressInterval_;
    const bool last = (nSteps_ == nStepsTotal_);
    reduce(first, orOp<bool>());
    reduce(due, orOp<bool>());

    if (!first && !due && !last)
    {
        return;
    }

    const scalar perStep = wall/max(nSteps_, label(1));
    const scalar eta = perStep*max(nStepsTotal_ - nSteps_, label(0));

    if (first)
    {
        projected_ = true;
        Info<< "Projected wall time " << perStep*nStepsTotal_ << " s for "
            << nStepsTotal_ << " steps (" << perStep << " s per step,"
            << " measured over " << nSteps_ << " steps)" << nl << endl;
    }

    if (due || last)
    {
        lastProgress_ = now;
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

Foam::physicsScene::physicsScene(fvMesh& mesh)
:
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
    progressInterval_(dict_.getOrDefault<scalar>("progressInterval", 10)),
    nSteps_(0),
    nStepsTotal_(0),
    projected_(false)
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

    // The soil's shape functions reach up to 2 nodes beyond a point's cell
    // (cubic B-splines), and the images of missing cells' nodes further:
    // the shared lattice is built wide enough for both
    lattice(has("soil") ? materialPointSoil::haloWidth(mesh_) : 1);

    // The water and the soil first: the couplings use them
    effects_.setSize(names_.size());
    for (const bool phases : {true, false})
    {
        forAll(names_, i)
        {
            const bool isPhase = (names_[i] == "fluid" || names_[i] == "soil");
            if (isPhase == phases)
            {
                effects_.set(i, physicsEffect::New(names_[i], *this, dict_));
            }
        }
    }
    checkRequirements();

    // Evolution order by stage (stable)
    {
        DynamicList<labelPair> order;
        DynamicList<label> stages;
        forAll(effects_, i)
        {
            order.append(labelPair(i, 0));
            stages.append(effects_[i].stage());
            if (effects_[i].lateStage() >= 0)
            {
                order.append(labelPair(i, 1));
                stages.append(effects_[i].lateStage());
            }
        }
        labelList idx(identity(order.size()));
        std::stable_sort
        (
            idx.begin(), idx.end(),
            [&stages](label a, label b) { return stages[a] < stages[b]; }
        );
        evolveOrder_.setSize(order.size());
        forAll(idx, k)
        {
            evolveOrder_[k] = order[idx[k]];
        }
    }
    effectTime_.setSize(effects_.size(), 0);

    // What the run will cost
    const Time& runTime = mesh_.time();
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

    start_ = clock::now();
    lastProgress_ = start_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::latticeMesh& Foam::physicsScene::lattice(const label haloWidth)
{
    if (!lattice_.valid())
    {
        lattice_.reset(new latticeMesh(mesh_, haloWidth));
        lattice_->report(Info);
    }
    else if (lattice_->haloWidth() < haloWidth)
    {
        FatalErrorInFunction
            << "The lattice was built with halo width "
            << lattice_->haloWidth() << " but an effect needs " << haloWidth
            << abort(FatalError);
    }
    return lattice_();
}


void Foam::physicsScene::evolve()
{
    for (const labelPair& ip : evolveOrder_)
    {
        const label i = ip.first();
        const clock::time_point t0 = clock::now();
        if (ip.second() == 0)
        {
            effects_[i].evolve();
        }
        else
        {
            effects_[i].evolveLate();
        }
        effectTime_[i] += seconds(t0, clock::now());
    }
    forAll(effects_, i)
    {
        const clock::time_point t0 = clock::now();
        effects_[i].endStep();
        effectTime_[i] += seconds(t0, clock::now());
    }
    ++nSteps_;
    progress();
}


void Foam::physicsScene::write()
{
    Time& runTime = const_cast<Time&>(mesh_.time());
    if (!runTime.writeTime())
    {
        return;
    }
    // The effects' outputs, then the registered fields (U, p, rho, ...):
    // all counted as writing in the run's cost
    const clock::time_point t0 = clock::now();
    forAll(effects_, i)
    {
        effects_[i].write();
    }
    runTime.write();
    writeTime_ += seconds(t0, clock::now());
}


void Foam::physicsScene::summary() const
{
    const scalar wall = seconds(start_, clock::now());
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
    Info<< "    writing: " << writeTime_ << " s" << nl << endl;
}


void Foam::physicsScene::estimate()
{
    Time& runTime = const_cast<Time&>(mesh_.time());
    const clock::time_point t0 = clock::now();
    label n = 0;
    while (runTime.run() && n < 50)
    {
        ++runTime;
        for (const labelPair& ip : evolveOrder_)
        {
            if (ip.second() == 0)
            {
                effects_[ip.first()].evolve();
            }
            else
            {
                effects_[ip.first()].evolveLate();
            }
        }
        ++n;
        bool enough = seconds(t0, clock::now()) > 3.0;
        reduce(enough, orOp<bool>());
        if (enough)
        {
            break;
        }
    }
    const scalar wall = seconds(t0, clock::now());
    const scalar perStep = wall/max(n, label(1));
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
    // water needs 4 times the steps instead of 2.
    const scalar total = perStep*nStepsTotal_;
    Info<< nl << "Estimate from " << n << " steps (" << perStep
        << " s per step)" << nl
        << "    case as set up:  wall time " << total << " s ("
        << total/3600 << " h), memory " << memory/1048576.0 << " MiB" << nl
        << "    dx halved:       wall time " << total*nodesFactor*2 << " s"
        << " at fixed lattice Mach (" << total*nodesFactor*4
        << " s at fixed tau), memory " << memory*nodesFactor/1048576.0
        << " MiB" << nl
        << "    dx doubled:      wall time " << total/(nodesFactor*2) << " s"
        << " at fixed lattice Mach (" << total/(nodesFactor*4)
        << " s at fixed tau), memory " << memory/nodesFactor/1048576.0
        << " MiB" << nl
        << "    Nothing was written." << nl << endl;
}


// ************************************************************************* //
