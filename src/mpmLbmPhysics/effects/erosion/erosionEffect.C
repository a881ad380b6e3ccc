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
#include "optionalEntry.H"
#include "freeSurfaceEffect.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "soilEffect.H"
#include "dragEffect.H"
#include "dragModel.H"
#include "buoyancyEffect.H"
#include "selectEntry.H"
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
        limits[mati] = optionalEntry<scalar>(matDict, "finesLimit", 0);
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
    surface_(freeSurface::of(scene)),
    drag_(twoWayDrag(scene, dict_)),
    g_(gravityMagnitude(scene.mesh(), dict_)),
    law_(erosionLaw::New(lawDict(dict_, fluid_, drag_, g_))),
    finesLimit_(finesLimits(scene.mesh(), soil_.mpm())),
    maxConcentration_
    (
        optionalEntry<scalar>(dict_, "maxConcentration", 0.6*law_->rhoSolid())
    ),
    materialSuspension_(soil_.mpm().materials().size(), 0),
    uPhysical_(fluid_.lattice().nBox(), Zero),
    u_(fluid_.lattice().nBox(), Zero),
    mixtureFactor_(0),
    surfaceSolidFraction_(0),
    minVolumeFraction_(0),
    removeVolume_(0),
    densest_(0),
    largest_(0),
    anyOpen_(false),
    removed_(0)
{
    if
    (
        !(maxConcentration_ > 0)
     || !(maxConcentration_ <= law_->rhoSolid())
    )
    {
        entryNotAllowed
        (
            dict_, "maxConcentration", maxConcentration_,
            "the most fines the pore water carries [kg/m3 of pore water],"
            " in (0, rhoSolid " + Foam::name(law_->rhoSolid()) + "]"
        );
    }

    // The suspensions: one, or one per material (its field
    // <field>.<material>)
    const word field(optionalEntry<word>(dict_, "field", "fines"));
    if (optionalEntry<bool>(dict_, "suspensionPerMaterial", false))
    {
        const auto& materials = soil_.mpm().materials();
        suspensions_.setSize(materials.size());
        suspensionMaterial_.setSize(materials.size());
        forAll(materials, mati)
        {
            materialSuspension_[mati] = mati;
            suspensionMaterial_[mati] = materials[mati].name();
        }
    }
    else
    {
        suspensions_.setSize(1);
    }
    forAll(suspensions_, s)
    {
        suspensions_.set
        (
            s,
            new latticeAdvectionDiffusion
            (
                fluid_.lattice(),
                fluid_.units(),
                suspensionMaterial_.empty()
              ? field
              : word(field + "." + suspensionMaterial_[s]),
                dict_,
                fluid_.boundaries(),
                fluid_.U(),
                surface_,
                &fluid_.obstacles()
            )
        );
    }
    const label nBox = fluid_.lattice().nBox();
    sources_.setSize(suspensions_.size(), scalarList(nBox, Zero));
    eroded_.setSize(suspensions_.size(), Zero);
    filtered_.setSize(suspensions_.size(), Zero);

    densest_ = 0;
    largest_ = 0;
    readState();
    if (law_->surface())
    {
        // The densest soil's solid fraction and the largest point at the
        // run's start; a restart takes them from the written time (the
        // points' porosity follows their deformation since)
        if (!(densest_ > 0))
        {
            const materialPoints& pts = soil_.mpm().points();
            forAll(pts.porosity, p)
            {
                densest_ = max(densest_, 1 - pts.porosity[p]);
                largest_ = max(largest_, pts.V0[p]);
            }
            reduce(densest_, maxOp<scalar>());
            reduce(largest_, maxOp<scalar>());
        }
        surfaceSolidFraction_ =
            optionalEntry<scalar>(dict_, "surfaceSolidFraction", 0.5*densest_);
        if (!(surfaceSolidFraction_ > 0) || !(surfaceSolidFraction_ < 1))
        {
            FatalIOErrorInFunction(dict_)
                << "surfaceSolidFraction " << surfaceSolidFraction_ << " is"
                << " not allowed: the nodal solid fraction that marks the"
                << " soil's surface, in (0, 1)" << exit(FatalIOError);
        }
        if (surfaceSolidFraction_ >= densest_)
        {
            // (no node of the soil reaches it: no surface, nothing erodes)
            FatalIOErrorInFunction(dict_)
                << "surfaceSolidFraction " << surfaceSolidFraction_ << " is"
                << " not allowed: the nodal solid fraction that marks the"
                << " soil's surface must lie below that of the densest"
                << " soil, " << densest_ << " (1 - its porosity): no node"
                << " would reach it and nothing would erode. The default is"
                << " half of it, " << 0.5*densest_ << exit(FatalIOError);
        }
        minVolumeFraction_ =
            optionalEntry<scalar>(dict_, "minVolumeFraction", 1e-3);
        if (!(minVolumeFraction_ >= 0 && minVolumeFraction_ < 1))
        {
            FatalIOErrorInFunction(dict_)
                << "minVolumeFraction " << minVolumeFraction_ << " is not"
                << " allowed: a point left with less than this fraction of"
                << " the largest point's initial volume is removed (its"
                << " mass given to the water), in [0, 1)"
                << exit(FatalIOError);
        }
        removeVolume_ = minVolumeFraction_*largest_;
        findOpenNodes();
        const label nBox = fluid_.lattice().nBox();
        phi_.setSize(nBox, Zero);
        wallShear_.setSize(nBox, Zero);
        demand_.setSize(nBox, Zero);
        handOff_.setSize(nBox, Zero);
        weightSum_.setSize(nBox, Zero);
        emptiedMass_.setSize(nBox, Zero);
        emptiedWeight_.setSize(nBox, Zero);
    }
    checkSuspensions();
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
        settling_.setSize(suspensions_.size());
        forAll(suspensions_, s)
        {
            settling_.set
            (
                s,
                new suspensionSettling
                (
                    dict_,
                    fluid_.units().rho0(),
                    drag_.muFluid()/drag_.rhoFluid(),
                    suspensions_[s]
                )
            );
        }
    }

    if (filtrationLaw::selected(dict_))
    {
        filtration_ = filtrationLaw::New(dict_);
        catchDemand_.setSize(fluid_.lattice().nBox(), Zero);
    }

    if (optionalEntry<bool>(dict_, "mixtureDensity", false))
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

    if (optionalEntry<bool>(dict_, "writeBalance", true))
    {
        // Per material (one suspension each), then the totals
        wordList columns;
        for (const word& mat : suspensionMaterial_)
        {
            columns.append("eroded." + mat);
            if (filtration_.valid())
            {
                columns.append("filtered." + mat);
            }
            columns.append(wordList({"suspended." + mat, "out." + mat}));
            if (settling_.size())
            {
                columns.append("deposited." + mat);
            }
        }
        columns.append("eroded");
        if (filtration_.valid())
        {
            columns.append("filtered");
        }
        columns.append(wordList({"suspended", "out"}));
        if (settling_.size())
        {
            columns.append("deposited");
        }
        columns.append("defect");
        balanceFile_ = newStepFile
        (
            scene.mesh(), "erosion", "erosion",
            "Fines [kg]: eroded from the points since erosion started in"
            " this case (a restart carries the totals on from the written"
            " time's uniform/erosionState and uniform/<field>Balance), filtered"
            " (caught back in the points' pores since then, with a"
            " filtrationLaw), suspended in the water (all of it), out"
            " through the patches since then (net), deposited at walls by"
            " settling since then (with a settlingModel), and the"
            " balance's defect over the largest of these",
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
    if (suspensionMaterial_.size())
    {
        Info<< "    A suspension per material: "
            << flatOutput(suspensionMaterial_) << nl;
    }
    suspensions_[0].report(Info);
    if (settling_.size())
    {
        settling_[0].model().report(Info);
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
    if (balanceFile_.valid() || surface_)
    {
        // (with a free surface: the suspensions follow its conversions)
        joined.append(sceneStage::endStep);
    }
    return joined;
}


Foam::label Foam::physicsEffects::erosion::suspensionOf(const label p) const
{
    return materialSuspension_[soil_.mpm().points().material[p]];
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

    for (scalarList& source : sources_)
    {
        source = 0;
    }
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
        if (surface_ && !surface_->water(n))
        {
            // Dry: above the water's surface nothing flows
            continue;
        }

        const scalar nNode = max(1 - phi[n], 0.01);
        const scalar q = mag(uPhysical_[n] - nNode*soilVelocity[n]);
        const scalar K = drag_.hydraulicConductivity(phi[n], g_);
        const scalar i = K < VGREAT ? q/K : 0;
        // (per volume of pore water: an interface node's water fills the
        // fraction of its pores its fill level gives)
        const scalar wet = wetFraction(n);
        const scalar c = Phi(n)/(nNode*wet)/rhoS;

        const scalar m = pts.m[p];
        const scalar rate =
            law_->internalRate(pts.porosity[p], f - fLim, c, q, i);

        // At most what the node's pore water can still carry
        scalar sourced = 0;
        for (const scalarList& source : sources_)
        {
            sourced += source[n];
        }
        const scalar room =
            (maxConcentration_*nNode*wet - Phi(n) - sourced)*Vcell;
        const scalar dm = min
        (
            min(rate*pts.V[p]*dt, m*(f - fLim)/(1 - fLim)),
            room
        );
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
        const label s = suspensionOf(p);
        sources_[s][n] += lost/Vcell;
        eroded_[s] += lost;
        changed = true;
    }
    if (returnReduce(changed, orOp<bool>()))
    {
        soil_.pointsChanged();
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
        for (latticeAdvectionDiffusion& susp : suspensions_)
        {
            susp.prepare(u_, porosity());
        }
        if (settling_.size())
        {
            // Several kinds of grains: each hindered by all of them
            const bool mixed =
                suspensions_.size() > 1 && settling_[0].model().hindered();
            if (mixed)
            {
                mixturePhi_.setSize(fluid_.lattice().nBox());
                for (const label n : fluid_.lattice().cellNode())
                {
                    mixturePhi_[n] = Phi(n);
                }
            }
            forAll(suspensions_, s)
            {
                settling_[s].update
                (
                    suspensions_[s],
                    porosity(),
                    mixed ? &mixturePhi_ : nullptr
                );
            }
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
        forAll(suspensions_, s)
        {
            suspensions_[s].step(u_, porosity(), &sources_[s]);
        }
    }
    else if (stage == sceneStage::endStep)
    {
        for (latticeAdvectionDiffusion& susp : suspensions_)
        {
            susp.followSurface();
        }
        if (balanceFile_.valid())
        {
            writeBalance();
        }
    }
}


Foam::scalar Foam::physicsEffects::erosion::eroded() const
{
    return returnReduce(sum(eroded_), sumOp<scalar>());
}


Foam::scalar Foam::physicsEffects::erosion::filtered() const
{
    return returnReduce(sum(filtered_), sumOp<scalar>());
}


Foam::scalar Foam::physicsEffects::erosion::suspended() const
{
    scalar sum = 0;
    for (const latticeAdvectionDiffusion& susp : suspensions_)
    {
        sum += susp.content();
    }
    return sum;
}


void Foam::physicsEffects::erosion::writeBalance()
{
    // Per suspension (global), then the totals
    const label nS = suspensions_.size();
    scalarList e(nS), filtered(nS), suspended(nS), out(nS), deposited(nS);
    scalarList content0(nS);
    forAll(suspensions_, s)
    {
        const latticeAdvectionDiffusion& susp = suspensions_[s];
        e[s] = returnReduce(eroded_[s], sumOp<scalar>());
        filtered[s] = returnReduce(filtered_[s], sumOp<scalar>());
        suspended[s] = susp.content();
        out[s] = sum(susp.patchOutflow());
        deposited[s] = susp.deposited();
        content0[s] = susp.content0();
    }

    // Each suspension's defect over the largest mass the balance moves
    // (the eroded mass where the soil only erodes; the inflow where it
    // only filters), the largest of them
    const scalar scale = max
    (
        max(max(sum(e), sum(filtered)), max(sum(mag(out)), sum(deposited))),
        max(sum(suspended), sum(content0))
    );
    scalar defect = 0;
    forAll(suspensions_, s)
    {
        const scalar d =
            scale > 0
          ? (
                suspended[s] + out[s] + deposited[s] + filtered[s]
              - content0[s] - e[s]
            )/scale
          : 0;
        if (mag(d) > mag(defect))
        {
            defect = d;
        }
    }

    if (balanceFile_->writeToFile())
    {
        OFstream& os = balanceFile_->file();
        balanceFile_->writeCurrentTime(os);
        auto columns = [&](const scalar es, const scalar fs, const scalar ss,
            const scalar os_, const scalar ds)
        {
            os  << tab << es;
            if (filtration_.valid())
            {
                os  << tab << fs;
            }
            os  << tab << ss << tab << os_;
            if (settling_.size())
            {
                os  << tab << ds;
            }
        };
        if (suspensionMaterial_.size())
        {
            forAll(suspensions_, s)
            {
                columns(e[s], filtered[s], suspended[s], out[s], deposited[s]);
            }
        }
        columns
        (
            sum(e), sum(filtered), sum(suspended), sum(out), sum(deposited)
        );
        os  << tab << defect << endl;
    }
}


Foam::string Foam::physicsEffects::erosion::plan() const
{
    const latticeAdvectionDiffusion& susp = suspensions_[0];
    return
        "points eroded each step, "
      + (
            suspensions_.size() > 1
          ? Foam::name(suspensions_.size()) + " suspensions (one per"
            " material)"
          : string("the suspension")
        )
      + " on a D" + Foam::name(fluid_.lattice().nDim()) + "Q"
      + Foam::name(susp.Q()) + " lattice (tau " + Foam::name(susp.tau()) + ")"
      + (filtration_.valid() ? ", the pores filtering it back" : "")
      + (mixtureForce_.size() ? ", its weight on the water" : "");
}


void Foam::physicsEffects::erosion::updateFields()
{
    for (latticeAdvectionDiffusion& susp : suspensions_)
    {
        susp.updateField(porosity());
    }
}


Foam::scalar Foam::physicsEffects::erosion::memoryBytes() const
{
    scalar bytes = 0;
    for (const latticeAdvectionDiffusion& susp : suspensions_)
    {
        bytes += susp.memoryBytes();
    }
    scalar local = scalar
    (
        uPhysical_.byteSize() + u_.byteSize()
      + catchDemand_.byteSize() + catchPoint_.byteSize()
      + mixtureForce_.byteSize()
    );
    for (const scalarList& source : sources_)
    {
        local += source.byteSize();
    }
    for (const suspensionSettling& settle : settling_)
    {
        local += settle.memoryBytes();
    }
    return bytes + returnReduce(local, sumOp<scalar>());
}


Foam::string Foam::physicsEffects::erosion::progress() const
{
    string s = "eroded " + Foam::name(eroded()) + " kg, ";
    if (filtration_.valid())
    {
        s += "filtered " + Foam::name(filtered()) + " kg, ";
    }
    s += "suspended " + Foam::name(suspended()) + " kg";
    const label nRemoved = returnReduce(removed_, sumOp<label>());
    if (nRemoved)
    {
        s += ", " + Foam::name(nRemoved) + " points removed this run";
    }
    return s;
}


// ************************************************************************* //
