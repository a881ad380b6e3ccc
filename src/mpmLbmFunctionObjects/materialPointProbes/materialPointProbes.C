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

#include "materialPointProbes.H"
#include "optionalEntry.H"
#include "mpmLbmFunctionObjectScene.H"
#include "soilEffect.H"
#include "fluidEffect.H"
#include "addToRunTimeSelectionTable.H"
#include "StringStream.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(materialPointProbes, 0);
    addToRunTimeSelectionTable
    (
        functionObject,
        materialPointProbes,
        dictionary
    );
}
}

const Foam::wordList Foam::functionObjects::materialPointProbes::fieldNames
({
    "displacement",
    "velocity",
    "stress",
    "porosity",
    "plasticStrain",
    "porePressure"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::materialPointProbes::select
(
    const physicsScene& scene
)
{
    const materialPoints& pts =
        scene.findEffect<physicsEffects::soil>("soil")->mpmConst().points();
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const scalar dx = scene.lattice().dx();

    ids_.setSize(locations_.size());
    weights_.setSize(locations_.size());
    start_.setSize(locations_.size());

    labelList order(pts.size());
    scalarList d2(pts.size());
    forAll(locations_, pi)
    {
        const point& loc = locations_[pi];

        // This processor's nearest points (in the plane of a 2D mesh: the
        // probe's z need not be the slab's)
        const Vector<label>& solD = mesh_.solutionD();
        forAll(order, p)
        {
            order[p] = p;
            d2[p] = 0;
            for (direction a = 0; a < 3; ++a)
            {
                if (solD[a] > 0)
                {
                    d2[p] += sqr(pts.x[p][a] - loc[a]);
                }
            }
        }
        const label k = min(nNearest_, pts.size());
        auto closer = [&](const label a, const label b)
        {
            return d2[a] < d2[b] || (d2[a] == d2[b] && pts.id[a] < pts.id[b]);
        };
        std::partial_sort(order.begin(), order.begin() + k, order.end(), closer);

        List<scalarList> allD(nProcs);
        List<labelList> allId(nProcs);
        List<List<point>> allX(nProcs);
        allD[me].setSize(k);
        allId[me].setSize(k);
        allX[me].setSize(k);
        for (label i = 0; i < k; ++i)
        {
            allD[me][i] = d2[order[i]];
            allId[me][i] = pts.id[order[i]];
            allX[me][i] = pts.x[order[i]];
        }
        Pstream::gatherList(allD);
        Pstream::scatterList(allD);
        Pstream::gatherList(allId);
        Pstream::scatterList(allId);
        Pstream::gatherList(allX);
        Pstream::scatterList(allX);

        // The nearest of all, ties by identity: the same on any number of
        // processors
        DynamicList<Tuple2<scalar, label>> cand;
        DynamicList<point> candX;
        forAll(allD, proci)
        {
            forAll(allD[proci], i)
            {
                cand.append(Tuple2<scalar, label>(allD[proci][i], allId[proci][i]));
                candX.append(allX[proci][i]);
            }
        }
        labelList rank(identity(cand.size()));
        std::sort
        (
            rank.begin(), rank.end(),
            [&](const label a, const label b)
            {
                return
                    cand[a].first() < cand[b].first()
                 || (
                        cand[a].first() == cand[b].first()
                     && cand[a].second() < cand[b].second()
                    );
            }
        );
        const label n = min(nNearest_, rank.size());
        if (n == 0 || std::sqrt(cand[rank[0]].first()) > 2*dx)
        {
            FatalIOErrorInFunction(mesh_.time().controlDict())
                << "materialPointProbes " << name() << ": probe " << pi
                << " at " << loc << " is not in the soil: "
                << (
                       n
                     ? "its nearest material point is "
                       + Foam::name(std::sqrt(cand[rank[0]].first()))
                       + " m away (more than two cells)"
                     : string("there are no material points")
                   )
                << nl << "    Place the probeLocations inside the soil"
                << exit(FatalIOError);
        }

        // Inverse-distance weights (Shepard); a point at the location
        // takes it all
        ids_[pi].setSize(n);
        weights_[pi].setSize(n);
        start_[pi] = Zero;
        scalar sumW = 0;
        const scalar hit = sqr(1e-9*dx);
        for (label i = 0; i < n; ++i)
        {
            const scalar dd = cand[rank[i]].first();
            ids_[pi][i] = cand[rank[i]].second();
            weights_[pi][i] =
                cand[rank[0]].first() <= hit
              ? (i == 0 ? 1.0 : 0.0)
              : 1.0/std::sqrt(dd);
            sumW += weights_[pi][i];
        }
        for (label i = 0; i < n; ++i)
        {
            weights_[pi][i] /= sumW;
            start_[pi] += weights_[pi][i]*candX[rank[i]];
        }
    }

    // Kept in the time's uniform/functionObjects for a restart
    setProperty("ids", ids_);
    setProperty("weights", weights_);
    setProperty("start", start_);
}


void Foam::functionObjects::materialPointProbes::buildSlots()
{
    slotsOf_.clear();
    forAll(ids_, pi)
    {
        forAll(ids_[pi], i)
        {
            slotsOf_(ids_[pi][i]).append(pi*nNearest_ + i);
        }
    }
}


void Foam::functionObjects::materialPointProbes::createFiles()
{
    if (!Pstream::master() || files_.size())
    {
        return;
    }
    files_.setSize(fields_.size());
    forAll(fields_, fi)
    {
        autoPtr<OFstream> os = createFile(fields_[fi]);
        forAll(start_, pi)
        {
            OStringStream line;
            line<< "Probe " << pi << ' ' << locations_[pi]
                << " (material from " << start_[pi] << ')';
            writeHeader(os(), line.str());
        }
        writeCommented(os(), "Time");
        forAll(start_, pi)
        {
            writeTabbed(os(), Foam::name(pi));
        }
        os() << endl;
        files_.set(fi, os.ptr());
    }
}


void Foam::functionObjects::materialPointProbes::initialise
(
    const physicsScene& scene
)
{
    if (ids_.size())
    {
        return;
    }
    // A restart continues the probes of the run it continues. A state that
    // cannot be read (a list of size -4: OpenFOAM's reading error, which
    // would drop the function object with a warning that names no file)
    // is no state
    bool found = false;
    {
        const bool throwing = FatalError.throwExceptions(true);
        const bool ioThrowing = FatalIOError.throwExceptions(true);
        try
        {
            found =
                getProperty("ids", ids_)
             && getProperty("weights", weights_)
             && getProperty("start", start_);
        }
        catch (const Foam::error&)
        {
            found = false;
        }
        FatalError.throwExceptions(throwing);
        FatalIOError.throwExceptions(ioThrowing);
    }
    found =
        found
     && ids_.size() == locations_.size()
     && weights_.size() == ids_.size()
     && start_.size() == ids_.size();
    forAll(ids_, pi)
    {
        if (!found)
        {
            break;
        }
        scalar sumW = 0;
        forAll(weights_[pi], i)
        {
            sumW += weights_[pi][i];
            found = found && std::isfinite(weights_[pi][i]) && weights_[pi][i] >= 0;
        }
        // (each point once; the start, the points' weighted position
        // when the probe took them, within the two cells of the location
        // a probe takes its points from: compared per component, as 1e300
        // overflowed the magnitude)
        const labelHashSet distinct(ids_[pi]);
        const vector d(start_[pi] - locations_[pi]);
        const scalar reach = 2*scene.lattice().dx()*(1 + 1e-9);
        found =
            found && weights_[pi].size() == ids_[pi].size()
         && ids_[pi].size() && ids_[pi].size() <= nNearest_
         && distinct.size() == ids_[pi].size()
         && mag(sumW - 1) < 1e-9 && min(ids_[pi]) >= 0
         && std::isfinite(d.x()) && std::isfinite(d.y())
         && std::isfinite(d.z()) && mag(d.x()) <= reach
         && mag(d.y()) <= reach && mag(d.z()) <= reach;
    }
    if (!found)
    {
        const Time& runTime = mesh_.time();
        if (runTime.value() > runTime.startTime().value() || runTime.timeIndex() > 0
         || runTime.value() > 0)
        {
            // A restart without (valid) state: said, never silent
            WarningInFunction
                << "materialPointProbes " << name() << ": no valid state of"
                << " its probes (ids, weights, start) in "
                << runTime.timePath()/"uniform"/"functionObjects"
                << "/functionObjectProperties" << nl
                << "    The probes take the material nearest their"
                << " locations at time " << runTime.timeName()
                << ": their displacement counts from there" << endl;
        }
        ids_.clear();
        weights_.clear();
        start_.clear();
        select(scene);
    }
    buildSlots();
    lost_.setSize(locations_.size(), false);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::materialPointProbes::materialPointProbes
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, typeName, dict, false),
    nNearest_(4)
{
    read(dict);
    // The solver builds its function objects before the first step: the
    // probes take the material where it is at the start
    if (mesh_.foundObject<physicsScene>(physicsScene::registryName))
    {
        initialise(mpmLbmScene(mesh_, type(), this->name(), "soil"));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::materialPointProbes::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    // (constructed without writeFile's own file: one file per field)
    writeToFile_ =
        Pstream::master() && optionalEntry<bool>(dict, "writeToFile", true);

    locations_ = dict.get<List<point>>("probeLocations");
    if (locations_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "probeLocations is empty: give at least one point"
            << exit(FatalIOError);
    }
    // (per component: 1e300 overflowed the magnitude; in a 2D case the
    // out-of-plane coordinate is any, as for OpenFOAM's probes)
    const boundBox& bb = mesh_.bounds();
    const Vector<label>& solved = mesh_.solutionD();
    forAll(locations_, pi)
    {
        const point& l = locations_[pi];
        bool inside = true;
        for (direction d = 0; d < 3; ++d)
        {
            inside =
                inside && std::isfinite(l[d])
             && (
                    solved[d] == -1
                 || (l[d] >= bb.min()[d] && l[d] <= bb.max()[d])
                );
        }
        if (!inside)
        {
            FatalIOErrorInFunction(dict)
                << "probeLocations: probe " << pi << " at " << l
                << " is not a point of the mesh, " << bb.min() << " to "
                << bb.max() << exit(FatalIOError);
        }
    }

    fields_ = optionalEntry<wordList>(dict, "fields", fieldNames);
    for (const word& field : fields_)
    {
        if (!fieldNames.found(field))
        {
            FatalIOErrorInFunction(dict)
                << "fields: " << field << " is not a quantity of the"
                << " material points" << nl << "    Allowed: " << fieldNames
                << exit(FatalIOError);
        }
    }

    nNearest_ = optionalEntry<label>
    (
        dict,
        "nearestPoints",
        mesh_.nSolutionD() == 3 ? 8 : 4
    );
    if (nNearest_ < 1 || nNearest_ > 64)
    {
        FatalIOErrorInFunction(dict)
            << "nearestPoints " << nNearest_ << ": must lie in [1, 64]"
            << exit(FatalIOError);
    }
    return true;
}


bool Foam::functionObjects::materialPointProbes::execute()
{
    physicsScene& scene = mpmLbmScene(mesh_, type(), name(), "soil");
    initialise(scene);

    const materialPoints& pts =
        scene.effect<physicsEffects::soil>("soil").mpm().points();
    const label n = locations_.size();
    scalarList sumW(n, Zero);
    List<vector> sumX(n, Zero);
    List<vector> sumV(n, Zero);
    List<symmTensor> sumS(n, Zero);
    scalarList sumN(n, Zero);
    scalarList sumE(n, Zero);
    forAll(pts.id, p)
    {
        const auto iter = slotsOf_.cfind(pts.id[p]);
        if (!iter.found())
        {
            continue;
        }
        for (const label slot : *iter)
        {
            const label pi = slot/nNearest_;
            const scalar w = weights_[pi][slot % nNearest_];
            sumW[pi] += w;
            sumX[pi] += w*pts.x[p];
            sumV[pi] += w*pts.v[p];
            sumS[pi] += w*pts.sigma[p];
            sumN[pi] += w*pts.porosity[p];
            sumE[pi] += w*pts.plasticStrain[p];
        }
    }
    Pstream::listCombineGather(sumW, plusEqOp<scalar>());
    Pstream::listCombineGather(sumX, plusEqOp<vector>());
    Pstream::listCombineGather(sumV, plusEqOp<vector>());
    Pstream::listCombineGather(sumS, plusEqOp<symmTensor>());
    Pstream::listCombineGather(sumN, plusEqOp<scalar>());
    Pstream::listCombineGather(sumE, plusEqOp<scalar>());
    Pstream::listCombineScatter(sumW);
    Pstream::listCombineScatter(sumX);
    Pstream::listCombineScatter(sumV);
    Pstream::listCombineScatter(sumS);
    Pstream::listCombineScatter(sumN);
    Pstream::listCombineScatter(sumE);

    displacement_.setSize(n);
    velocity_.setSize(n);
    stress_.setSize(n);
    porosity_.setSize(n);
    plasticStrain_.setSize(n);
    porePressure_.setSize(n);
    List<point> here(n);
    forAll(sumW, pi)
    {
        if (sumW[pi] <= 0)
        {
            // Every point of the probe has left the soil (eroded)
            if (!lost_[pi])
            {
                WarningInFunction
                    << "materialPointProbes " << name() << ": the material"
                    << " of probe " << pi << " (" << locations_[pi]
                    << ") has left the soil; it reports zeros from time "
                    << mesh_.time().timeName() << endl;
                lost_[pi] = true;
            }
            displacement_[pi] = Zero;
            velocity_[pi] = Zero;
            stress_[pi] = Zero;
            porosity_[pi] = 0;
            plasticStrain_[pi] = 0;
            here[pi] = start_[pi];
            continue;
        }
        // (a point that left is not counted: the others' weights share
        // its part)
        const scalar r = 1/sumW[pi];
        here[pi] = r*sumX[pi];
        displacement_[pi] = here[pi] - start_[pi];
        velocity_[pi] = r*sumV[pi];
        stress_[pi] = r*sumS[pi];
        porosity_[pi] = r*sumN[pi];
        plasticStrain_[pi] = r*sumE[pi];
    }

    // The water's pore pressure at the node of each probe's cell
    porePressure_ = 0;
    if (fields_.found("porePressure") && scene.has("fluid"))
    {
        const latticeBoltzmannFluid& lbm =
            scene.effect<physicsEffects::fluid>("fluid").lbm();
        const labelList& cellNode = lbm.lattice().cellNode();
        // (a point on a processor face may be found by both)
        scalarList count(n, Zero);
        forAll(here, pi)
        {
            const label celli = mesh_.findCell(here[pi]);
            if (celli >= 0)
            {
                porePressure_[pi] = lbm.nodePressure(cellNode[celli]);
                count[pi] = 1;
            }
        }
        Pstream::listCombineGather(porePressure_, plusEqOp<scalar>());
        Pstream::listCombineGather(count, plusEqOp<scalar>());
        Pstream::listCombineScatter(porePressure_);
        Pstream::listCombineScatter(count);
        forAll(count, pi)
        {
            if (count[pi] > 1)
            {
                porePressure_[pi] /= count[pi];
            }
        }
    }
    return true;
}


bool Foam::functionObjects::materialPointProbes::write()
{
    if (!Pstream::master() || !writeToFile() || start_.empty())
    {
        return true;
    }
    createFiles();
    forAll(files_, fi)
    {
        OFstream& os = files_[fi];
        const word& field = fields_[fi];
        writeCurrentTime(os);
        forAll(start_, pi)
        {
            os  << tab;
            if (field == "displacement") os << displacement_[pi];
            else if (field == "velocity") os << velocity_[pi];
            else if (field == "stress") os << stress_[pi];
            else if (field == "porosity") os << porosity_[pi];
            else if (field == "plasticStrain") os << plasticStrain_[pi];
            else os << porePressure_[pi];
        }
        os  << endl;
    }
    return true;
}


// ************************************************************************* //
