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
                velocity    (0 0 0);            // [m/s] (default 0)
                porosity    0.37;               // void fraction n (default 0)
                stress      geostatic;          // none (default) | geostatic
                geostaticCoeffs
                {
                    surface     10;             // [m] height of the free
                                                // surface along -gravity
                    K0          0.5;            // horizontal/vertical stress
                    waterDensity 1000;          // [kg/m3] submerged soil
                                                // (buoyancy): default 0
                }
            }
        );
    \endverbatim

    Geostatic stress (compression negative): vertical effective stress
    sigma_v = gamma (h - surface) at height h below the surface along
    -gravity (constant/g, the gravity effect's), horizontal
    K0 sigma_v, with the unit weight gamma = rho |g| of the dry soil, or
    for a soil under water (the buoyancy effect) the buoyant unit weight
    gamma' = (rho - (1 - n) rho_w) |g| = phi (rho_s - rho_w) |g| (rho the
    material's density per mixture volume phi rho_s, n the porosity).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "latticeMesh.H"
#include "materialPoints.H"
#include "searchableSurface.H"
#include "volumeType.H"
#include "Enum.H"
#include "uniformDimensionedFields.H"
#include "globalIndex.H"
#include <chrono>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Seed the material points of the soil from the regions of"
        " system/setMaterialPointsDict"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const auto start = std::chrono::steady_clock::now();

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

    const label n = dict.get<label>("pointsPerCell");
    if (n < 1 || n > 8)
    {
        FatalIOErrorInFunction(dict)
            << "pointsPerCell " << n << " is not allowed: it must lie in"
            << " [1, 8] (points per cell and direction)" << exit(FatalIOError);
    }

    const dictionary& materialsDict = soilDict.subDict("materials");
    const wordList materialNames(materialsDict.toc());
    // Gravity from constant/g (the gravity effect's), as the solver
    if (soilDict.found("gravity"))
    {
        FatalIOErrorInFunction(soilDict)
            << "gravity is not read from constant/soilProperties: it is the"
            << " gravity effect's, from constant/g (value (...);): add"
            << " gravity to effects in constant/physicsProperties"
            << exit(FatalIOError);
    }
    vector gravity(Zero);
    {
        IOobject gio
        (
            "g",
            runTime.constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        );
        if (gio.typeHeaderOk<uniformDimensionedVectorField>(true))
        {
            gravity = uniformDimensionedVectorField(gio).value();
        }
    }

    // The regions. Read from the list they are nameless blocks: each takes
    // the scoped name of the file and keyword (setMaterialPointsDict.regions.
    // <name>), so that an error names where to look
    PtrList<entry> regionEntries(dict.lookup("regions"));
    const label nRegions = regionEntries.size();
    forAll(regionEntries, r)
    {
        if (!regionEntries[r].isDict())
        {
            FatalIOErrorInFunction(dict)
                << "regions: entry " << regionEntries[r].keyword() << " is not"
                << " a dictionary: give each region as name { type ...;"
                << " material ...; }" << exit(FatalIOError);
        }
        regionEntries[r].dict().name() =
            dict.objectPath() + ".regions." + regionEntries[r].keyword();
    }
    if (!nRegions)
    {
        FatalIOErrorInFunction(dict)
            << "regions is empty: give at least one region" << exit(FatalIOError);
    }

    enum class stressType { none, geostatic };
    const Enum<stressType> stressTypeNames
    ({
        { stressType::none, "none" },
        { stressType::geostatic, "geostatic" },
    });

    PtrList<searchableSurface> surfaces(nRegions);
    labelList regionMaterial(nRegions);
    List<vector> regionVelocity(nRegions);
    scalarList regionPorosity(nRegions);
    scalarList regionRho(nRegions);
    List<stressType> regionStress(nRegions);
    scalarList regionSurface(nRegions, 0.0);
    scalarList regionK0(nRegions, 1.0);
    scalarList regionWaterRho(nRegions, 0.0);

    forAll(regionEntries, r)
    {
        const dictionary& rd = regionEntries[r].dict();
        const word& name = regionEntries[r].keyword();
        surfaces.set
        (
            r,
            searchableSurface::New
            (
                rd.get<word>("type"),
                IOobject
                (
                    name,
                    runTime.constant(),
                    "triSurface",
                    runTime,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE
                ),
                rd
            )
        );
        if (!surfaces[r].hasVolumeType())
        {
            FatalIOErrorInFunction(rd)
                << "Region " << name << ": surface type " << rd.get<word>("type")
                << " does not enclose a volume. Use a closed surface"
                << " (searchableBox, searchableCylinder, searchableSphere, a"
                << " closed triSurfaceMesh)" << exit(FatalIOError);
        }

        const word mat = rd.get<word>("material");
        regionMaterial[r] = materialNames.find(mat);
        if (regionMaterial[r] < 0)
        {
            FatalIOErrorInFunction(rd)
                << "Region " << name << ": material " << mat << " is not in"
                << " constant/soilProperties materials " << materialNames
                << exit(FatalIOError);
        }
        regionRho[r] = materialsDict.subDict(mat).get<scalar>("rho");
        regionVelocity[r] = rd.getOrDefault<vector>("velocity", Zero);
        regionPorosity[r] = rd.getOrDefault<scalar>("porosity", 0);
        if (!(regionPorosity[r] >= 0 && regionPorosity[r] < 1))
        {
            FatalIOErrorInFunction(rd)
                << "Region " << name << ": porosity " << regionPorosity[r]
                << " is not allowed: the void fraction must lie in [0, 1)"
                << exit(FatalIOError);
        }
        regionStress[r] =
            stressTypeNames.getOrDefault("stress", rd, stressType::none);
        if (regionStress[r] == stressType::geostatic)
        {
            const dictionary& gd = rd.subDict("geostaticCoeffs");
            regionSurface[r] = gd.get<scalar>("surface");
            regionK0[r] = gd.get<scalar>("K0");
            regionWaterRho[r] = gd.getOrDefault<scalar>("waterDensity", 0);
            if (!(regionWaterRho[r] >= 0))
            {
                FatalIOErrorInFunction(gd)
                    << "waterDensity " << regionWaterRho[r] << " is not"
                    << " allowed: it must be >= 0 [kg/m3]"
                    << exit(FatalIOError);
            }
            if (!(regionK0[r] >= 0))
            {
                FatalIOErrorInFunction(gd)
                    << "K0 " << regionK0[r] << " is not allowed: it must be"
                    << " >= 0" << exit(FatalIOError);
            }
            if (mag(gravity) < SMALL)
            {
                FatalIOErrorInFunction(rd)
                    << "Region " << name << ": geostatic stress needs gravity"
                    << " (constant/g, with gravity in the effects of"
                    << " constant/physicsProperties)" << exit(FatalIOError);
            }
        }
    }

    // Candidate points: the centres of the n^D sub-cells of every cell
    const label nDim = lattice.nDim();
    const label perCell = (nDim == 2 ? n*n : n*n*n);
    const scalar dx = lattice.dx();
    const vectorField& C = mesh.cellCentres();
    pointField candidates(mesh.nCells()*perCell);
    labelList candidateId(candidates.size());
    const labelVector& N = lattice.globalN();
    const bool globalIds =
        scalar(lattice.nGlobalBox())*perCell < scalar(labelMax);
    {
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
    }

    // First region containing each point
    labelList region(candidates.size(), -1);
    labelList regionCount(nRegions, 0);
    labelList insideCount(nRegions, 0);
    forAll(surfaces, r)
    {
        List<volumeType> vt;
        surfaces[r].getVolumeType(candidates, vt);
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

    forAll(regionCount, r)
    {
        if
        (
            returnReduce(regionCount[r], sumOp<label>()) == 0
         && returnReduce(insideCount[r], sumOp<label>()) > 0
        )
        {
            WarningInFunction
                << "Region " << regionEntries[r].keyword() << " lies entirely"
                << " inside regions listed before it: it gets no points" << endl;
        }
        else if (returnReduce(regionCount[r], sumOp<label>()) == 0)
        {
            FatalIOErrorInFunction(regionEntries[r].dict())
                << "Region " << regionEntries[r].keyword() << " contains no"
                << " point of the mesh: it lies outside the mesh (bounding box "
                << boundBox(mesh.points(), true) << ") or is smaller than a"
                << " sub-cell of size " << dx/n << exit(FatalIOError);
        }
    }

    // The points
    materialPoints points;
    label nPoints = 0;
    forAll(region, i)
    {
        if (region[i] >= 0) ++nPoints;
    }
    points.setSize(nPoints);
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
        symmTensor stress(Zero);
        if (regionStress[r] == stressType::geostatic)
        {
            const scalar h = candidates[i] & up;
            const scalar gamma =
                (
                    regionRho[r]
                  - (1 - regionPorosity[r])*regionWaterRho[r]
                )*mag(gravity);
            const scalar sv = gamma*min(h - regionSurface[r], 0.0);
            const symmTensor vv = sqr(up);
            stress = sv*vv + regionK0[r]*sv*(symmTensor::I - vv);
        }
        points.x[k] = candidates[i];
        points.v[k] = regionVelocity[r];
        points.m[k] = regionRho[r]*Vp;
        points.V[k] = Vp;
        points.V0[k] = Vp;
        points.F[k] = tensor::I;
        points.sigma[k] = stress;
        points.plasticStrain[k] = 0;
        points.C[k] = Zero;
        points.material[k] = regionMaterial[r];
        points.halfLength[k] = halfSize;
        points.porosity[k] = regionPorosity[r];
        points.id[k] = candidateId[i];
        ++k;
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

    points.write(mesh, lattice);

    const scalar seconds = std::chrono::duration<scalar>
    (
        std::chrono::steady_clock::now() - start
    ).count();

    Info<< "Material points" << nl;
    forAll(regionEntries, r)
    {
        Info<< "    " << regionEntries[r].keyword() << ": "
            << returnReduce(regionCount[r], sumOp<label>()) << " points of "
            << materialNames[regionMaterial[r]] << nl;
    }
    Info<< "    total " << returnReduce(nPoints, sumOp<label>()) << " points ("
        << n << " per cell and direction), "
        << materialPoints::memoryPerPoint() << " bytes per point" << nl
        << "    written to " << runTime.timeName() << "/lagrangian/"
        << materialPoints::cloudName << " in " << seconds << " s" << nl
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
