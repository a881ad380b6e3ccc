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

Application
    setMaterialPoints

Group
    grpPreProcessingUtilities

Description
    Seeds the material points of the soil from regions given in
    system/setMaterialPointsDict, and writes them as the cloud
    <startTime>/lagrangian/materialPoints.

    Each region is a closed searchable surface of OpenFOAM (searchableBox,
    searchableCylinder, searchableSphere, triSurfaceMesh from an STL file in
    constant/triSurface, ...). Every cell of the lattice gets n points per
    direction at the centres of its n^D sub-cells; a point takes the first
    region (in the order given) that contains it. The cell of a point comes
    from the lattice directly (no search), so a million points take seconds.

    In parallel (-parallel, after decomposePar) each processor seeds its own
    cells and writes processorN/<startTime>/lagrangian/materialPoints: the
    serial seeding decomposed (as decomposePar makes it from a serial
    cloud), to round-off in the positions (the cell centres of the
    processor meshes). Each point's identity (the cloud's origId) comes
    from its cell's global lattice index and its sub-cell: the same
    whatever the decomposition.

    \verbatim
        pointsPerCell   2;                      // per direction
        regions
        (
            column
            {
                type        searchableBox;      // any closed searchable surface
                min         (0 0 -1);
                max         (20 10 1);
                material    sand;               // from constant/soilProperties
                                                // (none: a void, no points)
                // velocity, porosity, stress, geostaticCoeffs: see
                // materialPointRegion.H
            }
        );
    \endverbatim

    The geostatic stress takes gravity from constant/g (the gravity
    effect's); a gravity entry in constant/soilProperties is refused.

    A run on several processors shares the work by the cells: with
    weightField in system/decomposeParDict (serial runs only), the utility
    writes that field, the work of each cell per step (1 for its lattice
    node, pointWork for each of its points' sub-steps), which decomposePar
    weighs the cells by:
    \verbatim
        // system/decomposeParDict
        method          hierarchical;       // or scotch, simple
        coeffs          { n (2 1 1); }
        weightField     cellWork;           // written to 0/ here

        // system/setMaterialPointsDict (optional)
        pointWork       1;                  // a point sub-step's cost in
                                            // lattice node updates
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "caseChecks.H"
#include "optionalEntry.H"
#include "restartManifest.H"
#include "IFstream.H"
#include "fvCFD.H"
#include "latticeMesh.H"
#include "materialPoints.H"
#include "materialPointRegion.H"
#include "volumeType.H"
#include "uniformDimensionedFields.H"
#include "globalIndex.H"
#include "clockValue.H"
#include "constitutiveModel.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

//- Points per cell and direction, in [1, 8]
static label readPointsPerCell(const dictionary& dict)
{
    const label n = dict.get<label>("pointsPerCell");
    if (n < 1 || n > 8)
    {
        FatalIOErrorInFunction(dict)
            << "pointsPerCell " << n << " is not allowed: it must lie in"
            << " [1, 8] (points per cell and direction)" << exit(FatalIOError);
    }
    return n;
}


//- Gravity from constant/g (the gravity effect's), as the solver reads it;
//  the old gravity keyword of constant/soilProperties is refused naming the
//  new place
static vector readGravity
(
    const dictionary& soilDict,
    const fvMesh& mesh,
    const bool twoD
)
{
    if (soilDict.found("gravity"))
    {
        FatalIOErrorInFunction(soilDict)
            << "gravity is not read from constant/soilProperties: it is the"
            << " gravity effect's, from constant/g (value (...);): add"
            << " gravity to effects in constant/physicsProperties"
            << exit(FatalIOError);
    }
    vector gravity(Zero);
    IOobject gio
    (
        "g",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (gio.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        const uniformDimensionedVectorField g(gio);
        gravity = g.value();
        IFstream is(g.filePath());
        checkInPlane(twoD, gravity, "value", dictionary(is));
    }

    // The soil feels constant/g only with the gravity effect acting on it
    // (a geostatic stress without it is released at the first step: the
    // soil swells)
    IOobject pio
    (
        "physicsProperties",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (mag(gravity) > 0 && pio.typeHeaderOk<IOdictionary>(true))
    {
        const IOdictionary pd(pio);
        const wordList effects(optionalEntry<wordList>(pd, "effects", {}));
        bool onSoil = effects.found("gravity");
        if (onSoil && pd.isDict("gravityCoeffs"))
        {
            const dictionary& gc = pd.subDict("gravityCoeffs");
            onSoil =
                !foundEntry(gc, "phases")
             || gc.get<wordList>("phases").found("soil");
        }
        if (!onSoil)
        {
            Info<< "constant/g is not the soil's: constant/physicsProperties"
                << " has no gravity effect acting on the soil" << nl << endl;
            gravity = Zero;
        }
    }
    return gravity;
}


//- Candidate points: the centres of the n^D sub-cells of every cell, and
//  their identities from the cell's global lattice index and the sub-cell
//  (-1 when there are more sub-cells than labels: then false)
static bool seedCandidates
(
    const latticeMesh& lattice,
    const fvMesh& mesh,
    const label n,
    pointField& candidates,
    labelList& candidateId
)
{
    const label nDim = lattice.nDim();
    const label perCell = (nDim == 2 ? n*n : n*n*n);
    const scalar dx = lattice.dx();
    const vectorField& C = mesh.cellCentres();
    candidates.setSize(mesh.nCells()*perCell);
    candidateId.setSize(candidates.size());
    const labelVector& N = lattice.globalN();
    const bool globalIds =
        scalar(lattice.nGlobalBox())*perCell < scalar(labelMax);

    label i = 0;
    forAll(C, celli)
    {
        const labelVector g = lattice.globalIjk(lattice.cellNode()[celli]);
        const label cellId = g.x() + N.x()*(g.y() + N.y()*g.z());
        for (label c = 0; c < (nDim == 2 ? 1 : n); ++c)
        for (label b = 0; b < n; ++b)
        for (label a = 0; a < n; ++a)
        {
            candidateId[i] =
                globalIds ? cellId*perCell + a + n*(b + n*c) : -1;
            candidates[i++] = C[celli] + dx*vector
            (
                (a + 0.5)/n - 0.5,
                (b + 0.5)/n - 0.5,
                nDim == 2 ? 0 : (c + 0.5)/n - 0.5
            );
        }
    }
    return globalIds;
}


//- The first region containing each candidate (-1: none), and the number
//  of points of each region; a region without points is an error, or a
//  warning when it lies inside regions listed before it
static labelList assignRegions
(
    const PtrList<materialPointRegion>& regions,
    const pointField& candidates,
    const fvMesh& mesh,
    const scalar subCellSize,
    labelList& regionCount
)
{
    labelList region(candidates.size(), -1);
    regionCount.setSize(regions.size());
    regionCount = 0;
    labelList insideCount(regions.size(), 0);
    forAll(regions, r)
    {
        List<volumeType> vt;
        regions[r].surface().getVolumeType(candidates, vt);
        forAll(vt, i)
        {
            if (vt[i] == volumeType::INSIDE)
            {
                ++insideCount[r];
                if (region[i] < 0)
                {
                    region[i] = r;
                    ++regionCount[r];
                }
            }
        }
    }

    // A void keeps its sub-cells from the regions after it, and seeds none
    forAll(region, i)
    {
        if (region[i] >= 0 && regions[region[i]].isVoid())
        {
            region[i] = -1;
        }
    }

    forAll(regionCount, r)
    {
        if
        (
            returnReduce(regionCount[r], sumOp<label>()) == 0
         && returnReduce(insideCount[r], sumOp<label>()) > 0
        )
        {
            WarningInFunction
                << "Region " << regions[r].name() << " lies entirely"
                << " inside regions listed before it: it gets no points"
                << (
                       regions[r].isVoid()
                     ? " (a void, material none, carves only the regions"
                       " listed after it: list it first)"
                     : ""
                   )
                << endl;
        }
        else if (returnReduce(regionCount[r], sumOp<label>()) == 0)
        {
            FatalIOErrorInFunction(regions[r].dict())
                << "Region " << regions[r].name() << " contains no"
                << " point of the mesh: it lies outside the mesh (bounding box "
                << boundBox(mesh.points(), true) << ") or is smaller than a"
                << " sub-cell of size " << subCellSize << exit(FatalIOError);
        }
    }
    return region;
}


//- The material points of the candidates in a region, with their
//  region's material, velocity, porosity and initial stress
static void fillPoints
(
    const PtrList<materialPointRegion>& regions,
    const pointField& candidates,
    const labelList& candidateId,
    const labelList& region,
    const bool globalIds,
    const latticeMesh& lattice,
    const label n,
    const vector& gravity,
    materialPoints& points
)
{
    const label nDim = lattice.nDim();
    const label perCell = (nDim == 2 ? n*n : n*n*n);
    label nPoints = 0;
    forAll(region, i)
    {
        if (region[i] >= 0) ++nPoints;
    }
    points.setSize(nPoints);
    for (const materialPointRegion& reg : regions)
    {
        if (reg.finesContent() > 0)
        {
            points.enableFines();
        }
    }
    const scalar Vp = lattice.cellVolume()/perCell;
    const vector halfSize(0.5/n, 0.5/n, nDim == 2 ? 0.5 : 0.5/n);
    const vector up = mag(gravity) > SMALL ? -gravity/mag(gravity) : vector(0, 1, 0);
    label k = 0;
    forAll(region, i)
    {
        const label r = region[i];
        if (r < 0)
        {
            continue;
        }
        const materialPointRegion& reg = regions[r];
        points.x[k] = candidates[i];
        points.v[k] = reg.velocity();
        points.m[k] = reg.rho()*Vp;
        points.V[k] = Vp;
        points.V0[k] = Vp;
        points.F[k] = tensor::I;
        points.sigma[k] = reg.initialStress(candidates[i], up, mag(gravity));
        points.plasticStrain[k] = 0;
        points.C[k] = Zero;
        points.material[k] = reg.material();
        points.halfLength[k] = halfSize;
        points.porosity[k] = reg.porosity();
        if (points.carriesFines)
        {
            points.fines[k] = reg.finesContent();
        }
        points.id[k] = candidateId[i];
        ++k;
    }

    // A geostatic surface below points of its region would leave them
    // unstressed (the stress grows with the depth below the surface only)
    scalarList top(regions.size(), -GREAT);
    forAll(region, i)
    {
        if (region[i] >= 0)
        {
            top[region[i]] = max(top[region[i]], candidates[i] & up);
        }
    }
    Pstream::listCombineGather(top, maxEqOp<scalar>());
    Pstream::listCombineScatter(top);
    forAll(regions, r)
    {
        const materialPointRegion& reg = regions[r];
        if (reg.geostatic() && top[r] > reg.surfaceHeight() + 1e-9*lattice.dx())
        {
            FatalIOErrorInFunction(reg.dict())
                << "geostaticCoeffs/surface " << reg.surfaceHeight()
                << " is not allowed:"
                << " region " << reg.name() << " has points up to "
                << top[r] << " m above the origin along -g, which would"
                << " start without stress. Set surface at or above the"
                << " region's top (the ground surface the geostatic stress"
                << " grows from)." << exit(FatalIOError);
        }
    }
    if (!globalIds)
    {
        // (more sub-cells than labels: numbered in processor order)
        const globalIndex offsets(nPoints);
        forAll(points.id, i)
        {
            points.id[i] = offsets.toGlobal(i);
        }
    }
}


//- With system/decomposeParDict naming a weightField: that field, the work
//  of each cell per step (its lattice node's update, 1, and its points'
//  sub-steps at pointWork node updates each), for decomposePar to share
//  the soil as well as the water among the processors. Serial only (the
//  field is decomposePar's input)
static void writeWorkField
(
    const fvMesh& mesh,
    const latticeMesh& lattice,
    const dictionary& setDict,
    const dictionary& materialsDict,
    const labelList& region,
    const label perCell
)
{
    const Time& runTime = mesh.time();
    IOobject decompIO
    (
        "decomposeParDict",
        runTime.system(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (Pstream::parRun() || !decompIO.typeHeaderOk<IOdictionary>(false))
    {
        return;
    }
    const IOdictionary decompDict(decompIO);
    word fieldName;
    if (!readIfPresentEntry(decompDict, "weightField", fieldName))
    {
        return;
    }

    // One point sub-step costs about one node update of the coupled water:
    // the paper's 3D case on one core ran its soil at 5.5 M point updates/s
    // and its water at 5.7 M node updates/s (regularized D3Q19, drag)
    const scalar pointWork = optionalEntry<scalar>(setDict, "pointWork", 1);
    if (!(pointWork >= 0 && pointWork <= 1e6))
    {
        FatalIOErrorInFunction(setDict)
            << "pointWork " << pointWork << " is not allowed: it must lie in"
            << " [0, 1e6] (a point sub-step's cost in lattice node updates)"
            << exit(FatalIOError);
    }

    // The soil's sub-steps per step at its start, as the solver plans them
    // (soilCFL dx/c_p, the fastest material's p-wave speed)
    scalar cp = 0;
    for (const word& name : materialsDict.toc())
    {
        cp = max
        (
            cp,
            constitutiveModel::New(name, materialsDict.subDict(name))
           ->pWaveSpeed()
        );
    }
    const scalar CFL =
        optionalEntry<scalar>(runTime.controlDict(), "soilCFL", 0.5);
    const scalar deltaT = runTime.deltaTValue();
    const label subSteps =
        (cp > 0 && CFL > 0)
      ? max(label(std::ceil(deltaT/(CFL*lattice.dx()/cp) - 1e-9)), label(1))
      : 1;

    volScalarField work
    (
        IOobject
        (
            fieldName,
            runTime.timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1.0)
    );
    scalar soilWork = 0;
    forAll(work, celli)
    {
        label nPoints = 0;
        for (label i = celli*perCell; i < (celli + 1)*perCell; ++i)
        {
            nPoints += (region[i] >= 0);
        }
        work[celli] += nPoints*subSteps*pointWork;
        soilWork += nPoints*subSteps*pointWork;
    }
    work.write();
    Info<< "Work per cell for decomposePar (weightField " << fieldName
        << " of system/decomposeParDict)" << nl
        << "    water 1 per cell, soil " << pointWork << " per point"
        << " sub-step (pointWork), " << subSteps << " sub-steps per step:"
        << " the soil is " << 100*soilWork/(soilWork + work.size()) << "%"
        << " of the work" << nl
        << "    written to " << runTime.timeName()/fieldName << nl << endl;
}


//- Points per region and in total, and where they were written
static void report
(
    const PtrList<materialPointRegion>& regions,
    const labelList& regionCount,
    const wordList& materialNames,
    const materialPoints& points,
    const label n,
    const word& timeName,
    const scalar seconds
)
{
    Info<< "Material points" << nl;
    forAll(regions, r)
    {
        Info<< "    " << regions[r].name() << ": "
            << returnReduce(regionCount[r], sumOp<label>());
        if (regions[r].isVoid())
        {
            Info<< " sub-cells left empty (material none)" << nl;
        }
        else
        {
            Info<< " points of " << materialNames[regions[r].material()] << nl;
        }
    }
    Info<< "    total " << returnReduce(points.size(), sumOp<label>())
        << " points (" << n << " per cell and direction), "
        << materialPoints::memoryPerPoint() << " bytes per point" << nl
        << "    written to " << timeName << "/lagrangian/"
        << materialPoints::cloudName << " in " << seconds << " s" << nl
        << nl << "End" << nl << endl;
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Seed the material points of the soil from the regions of"
        " system/setMaterialPointsDict"
    );

    #include "setRootCase.H"
    // (an error in a global file names it in parallel too; nothing is
    // read after the set-up)
    readGlobalFilesOnEveryProcessor();
    // A number such as 1e400 in the input: the parser's error, not a trap
    // (caseChecks.H); the cloud's values are checked where it is read;
    // and OpenFOAM's fatal errors end it cleanly (caseChecks.H)
    suspendInputTraps();
    runSetup
    (
        [&]()
        {
            checkControlDict(args);
            #include "createTime.H"
            #include "createMesh.H"

            const clockValue start(clockValue::now());

            IOdictionary dict
            (
                IOobject
                (
                    "setMaterialPointsDict",
                    runTime.system(),
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE
                )
            );
            IOdictionary soilDict
            (
                IOobject
                (
                    "soilProperties",
                    runTime.constant(),
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE
                )
            );

            const latticeMesh lattice(mesh, 1);
            lattice.report(Info);

            const label n = readPointsPerCell(dict);
            const dictionary& materialsDict = soilDict.subDict("materials");
            const vector gravity = readGravity(soilDict, mesh, lattice.twoD());
            const PtrList<materialPointRegion> regions
            (
                materialPointRegion::readList
                (
                    dict, runTime, materialsDict, gravity
                )
            );
            for (const materialPointRegion& reg : regions)
            {
                checkInPlane
                (
                    lattice.twoD(), reg.velocity(), "velocity", reg.dict()
                );
            }

            pointField candidates;
            labelList candidateId;
            const bool globalIds =
                seedCandidates(lattice, mesh, n, candidates, candidateId);

            labelList regionCount;
            const labelList region
            (
                assignRegions
                (
                    regions, candidates, mesh, lattice.dx()/n, regionCount
                )
            );

            materialPoints points;
            fillPoints
            (
                regions, candidates, candidateId, region, globalIds, lattice, n,
                gravity, points
            );
            // The cloud and, after it, the counts and totals a run starting
            // here must find in it (a processor's cloud lost by decomposePar or
            // by hand) and its files' checksums (an edit is reported)
            // (the whole cloud is made here: a cloud written before goes
            // first, so that none of its fields outlives it, e.g. the fines
            // of a region that no longer has any)
            const fileName cloudDir
            (
                runTime.timePath()/"lagrangian"/materialPoints::cloudName
            );
            if (isDir(cloudDir))
            {
                rmDir(cloudDir);
            }
            restartManifest::beginWrite(runTime, false);
            points.write(mesh, lattice);
            restartManifest::stateTable state;
            state.set("soilPoints", points.size());
            state.set("soilMass", sum(points.m));
            {
                // The cloud's check sum as a run reads it back (written
                // in ASCII at the case's precision, the values change):
                // the solver compares it, also after decomposePar
                materialPoints readBack;
                readBack.read(mesh, runTime.timeName());
                const HashTable<scalar> h = readBack.hashSums();
                forAllConstIters(h, iter)
                {
                    state.set("cloudHash_" + iter.key(), iter.val());
                }
            }
            restartManifest::endWrite
            (
                runTime,
                "setMaterialPoints",
                state,
                wordList(),
                wordList
                ({
                    "lagrangian"/materialPoints::cloudName,
                    "uniform"/fileName("lagrangian")/materialPoints::cloudName
                })
            );

            writeWorkField
            (
                mesh, lattice, dict, materialsDict, region,
                lattice.nDim() == 2 ? n*n : n*n*n
            );

            const scalar seconds = start.elapsed();
            report
            (
                regions, regionCount, materialsDict.toc(), points, n,
                runTime.timeName(), seconds
            );
        }
    );

    return 0;
}


// ************************************************************************* //
