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

#include "surfaceLoadEffect.H"
#include "optionalEntry.H"
#include "physicsScene.H"
#include "soilEffect.H"
#include "caseChecks.H"
#include "selectEntry.H"
#include "OFstream.H"
#include "IFstream.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(surfaceLoad, 0);
    addToRunTimeSelectionTable(physicsEffect, surfaceLoad, scene);
    addToMemberFunctionSelectionTable
    (
        physicsEffect, surfaceLoad, haloWidth, mesh
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::surfaceLoad::surfaceLoad(physicsScene& scene)
:
    physicsEffect(scene),
    dict_
    (
        IOobject
        (
            "surfaceLoadProperties",
            scene.mesh().time().constant(),
            scene.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    soil_(scene.effect<physicsEffects::soil>("soil").mpm()),
    started_(false),
    startFile_(scene.mesh().time().timePath()/"uniform"/"surfaceLoad")
{
    const fvMesh& mesh = scene.mesh();
    const boundBox& bounds = mesh.bounds();
    const bool twoD = scene.lattice().twoD();

    if (!dict_.isDict("loads") || dict_.subDict("loads").empty())
    {
        FatalIOErrorInFunction(dict_)
            << "loads: a dictionary of the loads is needed, e.g." << nl
            << "    loads { footing { type searchableBox; min (9.5 4.9 -1);"
            << " max (10.5 5 1); direction (0 -1 0); pressure 1e5; } }"
            << exit(FatalIOError);
    }
    const dictionary& loads = dict_.subDict("loads");
    for (const entry& e : loads)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(loads)
                << "loads: " << e.keyword() << " is not a dictionary: each"
                << " load is { type searchableBox; min ...; max ...;"
                << " pressure ...; }" << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        autoPtr<region> r(new region);
        r->name = e.keyword();

        // (a load's points are those in a box at the start)
        enum class regionType { box };
        selectEntry
        (
            Enum<regionType>({{regionType::box, "searchableBox"}}),
            "type", d
        );
        r->box = boundBox(d.get<point>("min"), d.get<point>("max"));
        if (!r->box.valid() || !r->box.overlaps(bounds))
        {
            FatalIOErrorInFunction(d)
                << "min " << r->box.min() << ", max " << r->box.max()
                << ": the box must have min below max and meet the mesh "
                << bounds << exit(FatalIOError);
        }

        // Along an axis: the box's area across it is then exact
        r->direction = optionalEntry<vector>(d, "direction", vector(0, -1, 0));
        checkInPlane(twoD, r->direction, "direction", d);
        direction axis = 0;
        label nAxes = 0;
        for (direction j = 0; j < 3; ++j)
        {
            if (r->direction[j] != 0)
            {
                axis = j;
                ++nAxes;
            }
        }
        if (nAxes != 1)
        {
            FatalIOErrorInFunction(d)
                << "direction " << r->direction << " is not allowed: a load"
                << " acts along an axis of the mesh, e.g. (0 -1 0)"
                << exit(FatalIOError);
        }
        r->direction /= mag(r->direction);

        // The area across the direction, clipped to the mesh (2D: the
        // mesh's thickness)
        r->area = 1;
        for (direction j = 0; j < 3; ++j)
        {
            if (j == axis)
            {
                continue;
            }
            r->area *=
                max
                (
                    min(r->box.max()[j], bounds.max()[j])
                  - max(r->box.min()[j], bounds.min()[j]),
                    0.0
                );
        }
        if (!(r->area > 0))
        {
            FatalIOErrorInFunction(d)
                << "min " << r->box.min() << ", max " << r->box.max()
                << ": the box has no area across direction " << r->direction
                << " inside the mesh " << bounds << exit(FatalIOError);
        }

        r->pressure = Function1<scalar>::New("pressure", d);
        r->nPoints = 0;
        r->nFound = 0;
        r->lastPressure = 0;
        r->lastPosition = 0;
        loads_.append(r.ptr());
    }

    wordList columns;
    for (const region& r : loads_)
    {
        columns.append
        (
            wordList
            ({
                r.name + ":pressure", r.name + ":force",
                r.name + ":position"
            })
        );
    }
    stepFile_ = newStepFile
    (
        mesh, "surfaceLoad", "surfaceLoad",
        "Per load: its pressure [Pa], the total force on its points [N],"
        " their mean position along its direction [m]",
        columns
    );

    scene.effect<physicsEffects::soil>("soil").beforeAdvance
    (
        [this]() { apply(); }
    );

    Info<< "Surface loads (constant/surfaceLoadProperties):";
    for (const region& r : loads_)
    {
        Info<< nl << "    " << r.name << ": pressure "
            << r.pressure->type() << " along " << r.direction << " on "
            << r.area << " m2, the points in " << r.box;
    }
    Info<< nl << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::physicsEffects::surfaceLoad::start()
{
    // (the file of the time the run started from: a processor that
    // decomposePar left without uniform/ takes the others')
    const fileName& file = startFile_;
    const bool mine = isFile(file);
    const bool restart = returnReduce(mine, orOp<bool>());
    dictionary written;
    if (mine)
    {
        IFstream is(file);
        written = dictionary(is);
    }
    const materialPoints& points = soil_.points();

    for (region& r : loads_)
    {
        labelList local;
        if (restart && mine)
        {
            // A restart: the points its time was written with
            if (!written.isDict(r.name))
            {
                FatalIOErrorInFunction(written)
                    << "The load " << r.name << " of " << dict_.objectPath()
                    << " is not in " << file << " (loads " << written.toc()
                    << "): a restart loads the points its time was written"
                    << " with." << nl
                    << "    Restart with the loads of that run, or start"
                    << " from 0" << exit(FatalIOError);
            }
            local = written.subDict(r.name).get<labelList>("ids");
        }
        else if (!restart)
        {
            // The points in the box now
            DynamicList<label> inBox;
            forAll(points.x, p)
            {
                if (r.box.contains(points.x[p]))
                {
                    inBox.append(points.id[p]);
                }
            }
            local.transfer(inBox);
        }
        List<labelList> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = local;
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        r.ids.clear();
        for (const labelList& l : all)
        {
            r.ids.insert(l);
        }
        r.nPoints = r.ids.size();
        if (r.nPoints == 0)
        {
            FatalIOErrorInFunction(dict_.subDict("loads").subDict(r.name))
                << "The load " << r.name << " finds no material point in its"
                << " box " << r.box << ": put the box around the points it"
                << " loads (one layer at the soil's surface)"
                << exit(FatalIOError);
        }
        Info<< "Surface load " << r.name << ": " << r.nPoints << " points";
        if (restart)
        {
            Info<< " (as written in " << file << ")";
        }
        Info<< nl;
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::surfaceLoad::apply()
{
    if (!started_)
    {
        started_ = true;
        start();
    }
    // The step's start: the soil advances over [t - dt, t] with the force
    // it has at its start, constant over its sub-steps (as the couplings'
    // forces)
    const Time& runTime = scene_.mesh().time();
    const scalar t = runTime.value() - runTime.deltaTValue();
    const materialPoints& points = soil_.points();

    for (region& r : loads_)
    {
        selected_.clear();
        scalar position = 0;
        forAll(points.id, p)
        {
            if (r.ids.found(points.id[p]))
            {
                selected_.append(p);
                position += points.x[p] & r.direction;
            }
        }
        const scalar P = r.pressure->value(t);
        if (!std::isfinite(P))
        {
            FatalIOErrorInFunction(dict_.subDict("loads").subDict(r.name))
                << "pressure of load " << r.name << " is " << P << " at t = "
                << t << " s: a finite value is needed" << exit(FatalIOError);
        }
        // (the points still there share p A: eroded ones drop out)
        r.nFound = returnReduce(selected_.size(), sumOp<label>());
        reduce(position, sumOp<scalar>());
        if (r.nFound > 0)
        {
            // The pressure acts on the points' surface, half a point's
            // length l/2 = V/(2 A/N) from their centres against the
            // direction, not at the centres: its moment about them, the
            // traction's virtual work to first order (f N(x_p + d) =
            // f N(x_p) + (f (x) d).grad N), enters the internal force as
            // the stress -(f (x) d)/V = (f/2)/(A/N_0) n n added to the
            // point's own (V = l A/N_0, each of the N_0 points loaded at the
            // start covering A/N_0; p/2 while none has eroded away).
            // Without it the loaded row carried about half the pressure,
            // the row below the rest, and a biaxial sample failed 10% early
            const scalar f = P*r.area/r.nFound;
            soil_.addPointTractions
            (
                selected_,
                f*r.direction,
                (0.5*f*r.nPoints/r.area)*sqr(r.direction)
            );
            r.lastPosition = position/r.nFound;
        }
        r.lastPressure = P;
    }

    if (stepFile_.valid() && stepFile_->writeToFile())
    {
        OFstream& os = stepFile_->file();
        os  << t;
        for (const region& r : loads_)
        {
            os  << tab << r.lastPressure
                << tab << (r.nFound > 0 ? r.lastPressure*r.area : 0)
                << tab << r.lastPosition;
        }
        os  << endl;
    }
}


void Foam::physicsEffects::surfaceLoad::write()
{
    const fileName dir(scene_.mesh().time().timePath()/"uniform");
    mkDir(dir);
    OFstream os(dir/"surfaceLoad");
    for (const region& r : loads_)
    {
        labelList ids(r.ids.sortedToc());
        os  << r.name << nl << token::BEGIN_BLOCK << nl
            << "    ids " << ids << token::END_STATEMENT << nl
            << token::END_BLOCK << nl;
    }
    os.flush();
    if (!os.good())
    {
        FatalErrorInFunction
            << "Could not write " << os.name() << exit(FatalError);
    }
}


Foam::wordList Foam::physicsEffects::surfaceLoad::stateFiles() const
{
    return wordList(1, "uniform/surfaceLoad");
}


Foam::string Foam::physicsEffects::surfaceLoad::progress() const
{
    string s;
    for (const region& r : loads_)
    {
        s += (s.empty() ? "load " : ", ") + r.name + " "
          + Foam::name(r.lastPressure) + " Pa";
    }
    return s;
}


// ************************************************************************* //
