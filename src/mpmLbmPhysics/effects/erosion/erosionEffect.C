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

#include "erosionEffect.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "soilEffect.H"
#include "dragEffect.H"
#include "dragModel.H"
#include "buoyancyEffect.H"
#include "uniformDimensionedFields.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(erosion, 0);
    addToRunTimeSelectionTable(physicsEffect, erosion, scene);
    addToMemberFunctionSelectionTable(physicsEffect, erosion, haloWidth, mesh);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The drag's law, after refusing a one-way drag (the soil would not feel
// the water that erodes it)
const dragModel& twoWayDrag(physicsScene& scene, const dictionary& dict)
{
    const physicsEffects::drag& d =
        scene.effect<physicsEffects::drag>("drag");
    if (!d.twoWay())
    {
        FatalIOErrorInFunction(d.dict())
            << "erosion needs drag twoWay (constant/dragProperties has drag"
            << " oneWay): the soil must feel the water that erodes it"
            << exit(FatalIOError);
    }
    return d.model();
}


// |g| from constant/g (the hydraulic gradient and the Shields threshold
// use it, whether or not the scene applies gravity)
scalar gravityMagnitude(const fvMesh& mesh, const dictionary& dict)
{
    IOobject io
    (
        "g",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        FatalIOErrorInFunction(dict)
            << "erosion needs constant/g: the hydraulic gradient"
            << " i = q mu/(k rho_w |g|) and the Shields threshold use |g|"
            << exit(FatalIOError);
    }
    const scalar g = mag(uniformDimensionedVectorField(io).value());
    if (!(g > 0) || !std::isfinite(g))
    {
        FatalIOErrorInFunction(dict)
            << "constant/g: |g| " << g << " is not allowed: erosion's"
            << " hydraulic gradient and Shields threshold need a gravity"
            << " (it acts on the phases only with the gravity effect)"
            << exit(FatalIOError);
    }
    return g;
}


// The erosion dictionary with what the law takes from the scene
dictionary lawDict
(
    const dictionary& dict,
    const latticeBoltzmannFluid& fluid,
    const dragModel& drag,
    const scalar g
)
{
    dictionary d(dict);
    d.set("rhoFluid", fluid.units().rho0());
    d.set("nuFluid", drag.muFluid()/drag.rhoFluid());
    d.set("g", g);
    return d;
}


// finesLimit of every material of constant/soilProperties, in the soil's
// order
scalarList finesLimits(const fvMesh& mesh, const materialPointSoil& soil)
{
    const IOdictionary soilDict
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
    const dictionary& materials = soilDict.subDict("materials");
    scalarList limits(soil.materials().size(), Zero);
    forAll(limits, mati)
    {
        const dictionary& matDict =
            materials.subDict(soil.materials()[mati].name());
        limits[mati] = matDict.getOrDefault<scalar>("finesLimit", 0);
        if (!(limits[mati] >= 0 && limits[mati] < 1))
        {
            FatalIOErrorInFunction(matDict)
                << "finesLimit " << limits[mati] << " is not allowed: the"
                << " fines content erosion stops at, a mass fraction of the"
                << " solid in [0, 1)" << exit(FatalIOError);
        }
    }
    return limits;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::erosion::erosion(physicsScene& scene)
:
    physicsEffect(scene),
    dict_
    (
        IOobject
        (
            "erosionProperties",
            scene.mesh().time().constant(),
            scene.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    soil_(scene.effect<physicsEffects::soil>("soil")),
    drag_(twoWayDrag(scene, dict_)),
    g_(gravityMagnitude(scene.mesh(), dict_)),
    law_(erosionLaw::New(lawDict(dict_, fluid_, drag_, g_))),
    finesLimit_(finesLimits(scene.mesh(), soil_.mpm())),
    suspension_
    (
        fluid_.lattice(),
        fluid_.units(),
        dict_.getOrDefault<word>("field", "fines"),
        dict_,
        fluid_.boundaries(),
        fluid_.U()
    ),
    uPhysical_(fluid_.lattice().nBox(), Zero),
    u_(fluid_.lattice().nBox(), Zero),
    source_(fluid_.lattice().nBox(), Zero),
    eroded_(0),
    filtered_(0),
    mixtureFactor_(0),
    surfaceSolidFraction_(0),
    minVolumeFraction_(0),
    removeVolume_(0),
    densest_(0),
    largest_(0),
    anyOpen_(false),
    removed_(0)
{
    if (law_->surface())
    {
        // The densest soil's solid fraction and the largest point at the
        // run's start; a restart takes them from the written time (the
        // points' porosity follows their deformation since)
        const fileName statePath
        (
            scene.mesh().time().timePath()/"uniform"/"erosionState"
        );
        scalar densest = 0;
        scalar largest = 0;
        if (isFile(statePath))
        {
            IFstream is(statePath);
            const dictionary state(is);
            densest = state.get<scalar>("densestSolidFraction");
            largest = state.get<scalar>("largestPointVolume");
        }
        else
        {
            const materialPoints& pts = soil_.mpm().points();
            forAll(pts.porosity, p)
            {
                densest = max(densest, 1 - pts.porosity[p]);
                largest = max(largest, pts.V0[p]);
            }
            reduce(densest, maxOp<scalar>());
            reduce(largest, maxOp<scalar>());
        }
        densest_ = densest;
        largest_ = largest;
        surfaceSolidFraction_ =
            dict_.getOrDefault<scalar>("surfaceSolidFraction", 0.5*densest);
        if (!(surfaceSolidFraction_ > 0) || !(surfaceSolidFraction_ < 1))
        {
            FatalIOErrorInFunction(dict_)
                << "surfaceSolidFraction " << surfaceSolidFraction_ << " is"
                << " not allowed: the nodal solid fraction that marks the"
                << " soil's surface, in (0, 1)" << exit(FatalIOError);
        }
        minVolumeFraction_ =
            dict_.getOrDefault<scalar>("minVolumeFraction", 1e-3);
        if (!(minVolumeFraction_ >= 0 && minVolumeFraction_ < 1))
        {
            FatalIOErrorInFunction(dict_)
                << "minVolumeFraction " << minVolumeFraction_ << " is not"
                << " allowed: a point left with less than this fraction of"
                << " the largest point's initial volume is removed (its"
                << " mass given to the water), in [0, 1)"
                << exit(FatalIOError);
        }
        removeVolume_ = minVolumeFraction_*largest;
        findOpenNodes();
        const label nBox = fluid_.lattice().nBox();
        phi_.setSize(nBox, Zero);
        wallShear_.setSize(nBox, Zero);
        demand_.setSize(nBox, Zero);
        weightSum_.setSize(nBox, Zero);
        emptiedMass_.setSize(nBox, Zero);
        emptiedWeight_.setSize(nBox, Zero);
    }
    if (suspension_.field().dimensions() != dimDensity)
    {
        FatalIOErrorInFunction(dict_)
            << suspension_.field().objectPath() << ": the suspended fines"
            << " are a mass per volume of water " << dimDensity << ", not "
            << suspension_.field().dimensions() << exit(FatalIOError);
    }
    // Filtration fills clean pores: points without fines start at none
    if
    (
        filtrationLaw::selected(dict_)
     && !soil_.mpm().points().carriesFines
    )
    {
        soil_.mpm().points().enableFines();
    }
    if (!law_->surface() && !soil_.mpm().points().carriesFines)
    {
        FatalIOErrorInFunction(dict_)
            << "The material points carry no fines: give a region of"
            << " system/setMaterialPointsDict a finesContent and run"
            << " setMaterialPoints" << exit(FatalIOError);
    }

    if (suspensionSettling::selected(dict_))
    {
        settling_.reset
        (
            new suspensionSettling
            (
                dict_,
                fluid_.units().rho0(),
                drag_.muFluid()/drag_.rhoFluid(),
                suspension_
            )
        );
    }

    if (filtrationLaw::selected(dict_))
    {
        filtration_ = filtrationLaw::New(dict_);
        catchDemand_.setSize(fluid_.lattice().nBox(), Zero);
    }

    if (dict_.getOrDefault<bool>("mixtureDensity", false))
    {
        if (!scene.has("buoyancy"))
        {
            FatalIOErrorInFunction(dict_)
                << "mixtureDensity true needs effect buoyancy (the"
                << " suspension's weight on the water raises the pore"
                << " pressure, which acts on the soil through buoyancy);"
                << " add buoyancy to the effects of"
                << " constant/physicsProperties or set mixtureDensity false"
                << exit(FatalIOError);
        }
        mixtureFactor_ = 1 - fluid_.units().rho0()/law_->rhoSolid();
        mixtureForce_.setSize(fluid_.lattice().nBox(), Zero);
        scene.effect<physicsEffects::buoyancy>("buoyancy")
            .addWaterForce(mixtureForce_);
    }

    if (dict_.getOrDefault<bool>("writeBalance", true))
    {
        wordList columns({"eroded"});
        if (filtration_.valid())
        {
            columns.append("filtered");
        }
        columns.append(wordList({"suspended", "out"}));
        if (settling_.valid())
        {
            columns.append("deposited");
        }
        columns.append("defect");
        balanceFile_ = newStepFile
        (
            scene.mesh(), "erosion", "erosion",
            "Fines [kg]: eroded from the points since the start, filtered"
            " (caught back in the points' pores since the start, with a"
            " filtrationLaw), suspended in the water, out through the"
            " patches since the start (net), deposited at walls by settling"
            " (with a settlingModel), and the balance's defect over the"
            " largest of these",
            columns
        );
    }

    Info<< "Erosion of the soil's fines" << nl;
    law_->report(Info);
    if (law_->surface())
    {
        Info<< "    The soil's surface: nodal solid fraction "
            << surfaceSolidFraction_ << nl
            << "    Points left with less than " << minVolumeFraction_
            << " of the largest point's initial volume ("
            << removeVolume_ << " m3) are removed" << nl;
    }
    else
    {
        forAll(finesLimit_, mati)
        {
            Info<< "    " << soil_.mpm().materials()[mati].name()
                << ": finesLimit " << finesLimit_[mati] << nl;
        }
    }

    if (filtration_.valid())
    {
        filtration_->report(Info);
    }
    if (mixtureForce_.size())
    {
        Info<< "    The suspension weighs on the water: Phi (1 - rho_w/rho_s)"
            << " = " << mixtureFactor_ << " Phi times the water's body"
            << " acceleration" << nl;
    }
    suspension_.report(Info);
    if (settling_.valid())
    {
        settling_->model().report(Info);
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::sceneStageList Foam::physicsEffects::erosion::stages() const
{
    sceneStageList joined;
    if (mixtureForce_.size())
    {
        // Before buoyancy sets the water's forces (forcing)
        joined.append(sceneStage::exchange);
    }
    joined.append(sceneStage::transport);
    if (balanceFile_.valid())
    {
        joined.append(sceneStage::endStep);
    }
    return joined;
}


Foam::label Foam::physicsEffects::erosion::nodeOf(const point& x) const
{
    const latticeMesh& lattice = fluid_.lattice();
    const scalar dx = lattice.dx();
    const vector& origin = lattice.origin();
    const labelVector& bs = lattice.boxStart();
    labelVector b;
    for (direction d = 0; d < 3; ++d)
    {
        b[d] = (d == 2 && lattice.twoD())
             ? 0
             : label(std::floor((x[d] - origin[d])/dx)) - bs[d];
    }
    return lattice.node(b.x(), b.y(), b.z());
}


void Foam::physicsEffects::erosion::erodePoints()
{
    const latticeMesh& lattice = fluid_.lattice();
    const scalarList& phi = soil_.solidFraction();
    const List<vector>& soilVelocity = soil_.nodeVelocity();
    materialPoints& pts = soil_.mpm().points();

    const scalar dt = scene_.mesh().time().deltaTValue();
    const scalar Vcell = lattice.cellVolume();
    const scalar rhoS = law_->rhoSolid();

    source_ = 0;
    bool changed = false;
    forAll(pts.x, p)
    {
        const scalar fLim = finesLimit_[pts.material[p]];
        const scalar f = pts.fines[p];
        if (!(f > fLim))
        {
            continue;
        }

        const label n = nodeOf(pts.x[p]);

        const scalar nNode = max(1 - phi[n], 0.01);
        const scalar q = mag(uPhysical_[n] - nNode*soilVelocity[n]);
        const scalar K = drag_.hydraulicConductivity(phi[n], g_);
        const scalar i = K < VGREAT ? q/K : 0;
        const scalar c = suspension_.Phi(n)/nNode/rhoS;

        const scalar m = pts.m[p];
        const scalar rate =
            law_->internalRate(pts.porosity[p], f - fLim, c, q, i);
        const scalar dm = min(rate*pts.V[p]*dt, m*(f - fLim)/(1 - fLim));
        if (!(dm > 0))
        {
            continue;
        }

        // The point keeps its volume and loses the grains' volume dm/rhoS
        // (the eroded mass is what the point lost, exactly: m - m' is
        // exact in floating point for m' in [m/2, m])
        const scalar mNew = m - dm;
        const scalar lost = m - mNew;
        pts.fines[p] = (f*m - lost)/mNew;
        pts.porosity[p] = min(pts.porosity[p] + lost/(rhoS*pts.V[p]), 1.0);
        pts.m[p] = mNew;
        source_[n] += lost/Vcell;
        eroded_ += lost;
        changed = true;
    }
    if (returnReduce(changed, orOp<bool>()))
    {
        soil_.pointsChanged();
    }
}


void Foam::physicsEffects::erosion::filterPoints()
{
    const scalarList& phi = soil_.solidFraction();
    const List<vector>& soilVelocity = soil_.nodeVelocity();
    materialPoints& pts = soil_.mpm().points();

    const scalar dt = scene_.mesh().time().deltaTValue();
    const scalar Vcell = fluid_.lattice().cellVolume();
    const scalar rhoS = law_->rhoSolid();
    const scalar fMax = filtration_->maxFinesContent();

    // The points' porosity never falls below this: a pore space the drag
    // laws still hold (Kozeny-Carman's permeability ~ n^3)
    const scalar nMin = 0.01;

    // What each point would catch, and its node's total
    catchPoint_.setSize(pts.x.size());
    catchDemand_ = 0;
    forAll(pts.x, p)
    {
        catchPoint_[p] = 0;
        const scalar f = pts.fines[p];
        if (!(f < fMax) || !(pts.porosity[p] > nMin))
        {
            continue;
        }
        const label n = nodeOf(pts.x[p]);
        const scalar nNode = max(1 - phi[n], 0.01);
        const scalar q = mag(uPhysical_[n] - nNode*soilVelocity[n]);
        const scalar C = max(suspension_.Phi(n), scalar(0))/nNode;
        const scalar m = pts.m[p];
        const scalar dm = min
        (
            filtration_->rate(C, q, f)*pts.V[p]*dt,
            min
            (
                m*(fMax - f)/(1 - fMax),
                rhoS*pts.V[p]*(pts.porosity[p] - nMin)
            )
        );
        if (dm > 0)
        {
            catchPoint_[p] = dm;
            catchDemand_[n] += dm;
        }
    }

    // Each node gives what its points ask, at most what it holds (the
    // points then share it in proportion to what they asked)
    forAll(catchDemand_, n)
    {
        if (catchDemand_[n] > 0)
        {
            const scalar held = max(suspension_.Phi(n), scalar(0))*Vcell;
            catchDemand_[n] =
                catchDemand_[n] > held
              ? held/catchDemand_[n]*(1 - 1e-12)
              : 1;
        }
    }

    // The points gain what their mass can hold exactly ((m + dm) - m:
    // a tiny dm added to m rounds, the same way step after step), and
    // each node gives exactly the sum its points gained, so the
    // suspension's loss and the points' gain are one number
    bool changed = false;
    forAll(pts.x, p)
    {
        if (!(catchPoint_[p] > 0))
        {
            continue;
        }
        const label n = nodeOf(pts.x[p]);
        const scalar m = pts.m[p];
        const scalar mNew = m + catchPoint_[p]*catchDemand_[n];
        const scalar gained = mNew - m;
        catchPoint_[p] = 0;
        if (!(gained > 0))
        {
            continue;
        }
        pts.fines[p] = min((pts.fines[p]*m + gained)/mNew, fMax);
        pts.porosity[p] = max(pts.porosity[p] - gained/(rhoS*pts.V[p]), nMin);
        pts.m[p] = mNew;
        catchPoint_[p] = gained;
        changed = true;
    }
    catchDemand_ = 0;
    forAll(pts.x, p)
    {
        if (catchPoint_[p] > 0)
        {
            catchDemand_[nodeOf(pts.x[p])] += catchPoint_[p];
        }
    }
    forAll(catchDemand_, n)
    {
        if (catchDemand_[n] > 0)
        {
            filtered_ += suspension_.take(n, catchDemand_[n]/Vcell)*Vcell;
        }
    }
    if (returnReduce(changed, orOp<bool>()))
    {
        soil_.pointsChanged();
    }
}


void Foam::physicsEffects::erosion::mixtureWeight()
{
    // Before the suspension's populations are set: on a restart read
    // them now (the weight is then the written state's to the last bit);
    // at a fresh start they are set from the field at the transport stage
    // of the first step, with the porosity the water has then (this stage
    // comes before porousFlow gives it), so that step has no weight yet
    if (!suspension_.initialised())
    {
        if (!suspension_.writtenPopulations())
        {
            return;
        }
        suspension_.prepare(u_, nullptr);
    }
    const lbmUnits& units = fluid_.units();

    // Phi [kg/m3 of mixture] x (1 - rho_w/rho_s) x a [m/s2] = N/m3
    const vector a =
        mixtureFactor_*units.forceDensityToLattice()
       *fluid_.bodyAcceleration();
    for (const label n : fluid_.lattice().cellNode())
    {
        mixtureForce_[n] = max(suspension_.Phi(n), scalar(0))*a;
    }
}


void Foam::physicsEffects::erosion::evolve(const sceneStage stage)
{
    if (stage == sceneStage::exchange)
    {
        mixtureWeight();
    }
    else if (stage == sceneStage::transport)
    {
        fluid_.nodalVelocity(uPhysical_);
        const lbmUnits& units = fluid_.units();
        forAll(u_, n)
        {
            u_[n] = units.toLattice(uPhysical_[n]);
        }
        suspension_.prepare(u_, porosity());
        if (settling_.valid())
        {
            settling_->update(suspension_, porosity());
        }
        if (law_->surface())
        {
            erodeSurface();
        }
        else
        {
            erodePoints();
        }
        if (filtration_.valid())
        {
            filterPoints();
        }
        suspension_.step(u_, porosity(), &source_);
    }
    else if (stage == sceneStage::endStep)
    {
        writeBalance();
    }
}


Foam::scalar Foam::physicsEffects::erosion::eroded() const
{
    return returnReduce(eroded_, sumOp<scalar>());
}


Foam::scalar Foam::physicsEffects::erosion::filtered() const
{
    return returnReduce(filtered_, sumOp<scalar>());
}


void Foam::physicsEffects::erosion::writeBalance()
{
    const scalar e = eroded();
    const scalar filtered = this->filtered();
    const scalar suspended = suspension_.content();
    const scalar out = sum(suspension_.patchOutflow());
    const scalar deposited = suspension_.deposited();
    const scalar content0 = suspension_.content0();

    // Over the largest mass the balance moves (the eroded mass where the
    // soil only erodes; the inflow where it only filters)
    const scalar scale = max
    (
        max(max(e, filtered), max(mag(out), deposited)),
        max(suspended, content0)
    );
    const scalar defect =
        scale > 0
      ? (suspended + out + deposited + filtered - content0 - e)/scale
      : 0;
    if (balanceFile_->writeToFile())
    {
        OFstream& os = balanceFile_->file();
        balanceFile_->writeCurrentTime(os);
        os  << tab << e;
        if (filtration_.valid())
        {
            os  << tab << filtered;
        }
        os  << tab << suspended << tab << out;
        if (settling_.valid())
        {
            os  << tab << deposited;
        }
        os  << tab << defect << endl;
    }
}


Foam::string Foam::physicsEffects::erosion::plan() const
{
    return
        "points eroded each step, the suspension on a D"
      + Foam::name(fluid_.lattice().nDim()) + "Q"
      + Foam::name(suspension_.Q()) + " lattice (tau "
      + Foam::name(suspension_.tau()) + ")"
      + (filtration_.valid() ? ", the pores filtering it back" : "");
}


void Foam::physicsEffects::erosion::write()
{
    if (law_->surface())
    {
        writeWallShearStress();

        // What a restart from this time must start from, to the last bit
        const fileName dir(scene_.mesh().time().timePath()/"uniform");
        mkDir(dir);
        OFstream os(dir/"erosionState");
        os.precision(17);
        os  << "densestSolidFraction " << densest_ << ";" << nl
            << "largestPointVolume " << largest_ << ";" << nl;
        if (!os.good())
        {
            FatalErrorInFunction
                << "Could not write " << os.name() << exit(FatalError);
        }
    }
    suspension_.writePopulations();
}


void Foam::physicsEffects::erosion::updateFields()
{
    suspension_.updateField(porosity());
}


Foam::wordList Foam::physicsEffects::erosion::stateFiles() const
{
    return suspension_.populationFiles();
}


Foam::scalar Foam::physicsEffects::erosion::memoryBytes() const
{
    return
        suspension_.memoryBytes()
      + returnReduce
        (
            scalar
            (
                uPhysical_.byteSize() + u_.byteSize() + source_.byteSize()
              + catchDemand_.byteSize() + catchPoint_.byteSize()
              + mixtureForce_.byteSize()
            )
          + (settling_.valid() ? settling_->memoryBytes() : 0),
            sumOp<scalar>()
        );
}


Foam::string Foam::physicsEffects::erosion::progress() const
{
    string s = "eroded " + Foam::name(eroded()) + " kg, ";
    if (filtration_.valid())
    {
        s += "filtered " + Foam::name(filtered()) + " kg, ";
    }
    s += "suspended " + Foam::name(suspension_.content()) + " kg";
    const label nRemoved = returnReduce(removed_, sumOp<label>());
    if (nRemoved)
    {
        s += ", " + Foam::name(nRemoved) + " points removed";
    }
    return s;
}


// ************************************************************************* //
