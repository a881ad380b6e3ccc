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

#include "porousFlowEffect.H"
#include "optionalEntry.H"
#include "physicsScene.H"
#include "fluidEffect.H"
#include "soilEffect.H"
#include "dragEffect.H"
#include "materialPointSoil.H"
#include "dragRelaxation.H"
#include "selectEntry.H"
#include "addToRunTimeSelectionTable.H"
#include "addToMemberFunctionSelectionTable.H"
#include <cstdio>

namespace Foam
{
namespace physicsEffects
{
    defineTypeNameAndDebug(porousFlow, 0);
    addToRunTimeSelectionTable(physicsEffect, porousFlow, scene);
    addToMemberFunctionSelectionTable
    (
        physicsEffect, porousFlow, haloWidth, mesh
    );
}
}

const Foam::Enum<Foam::physicsEffects::porousFlow::mediumType>
Foam::physicsEffects::porousFlow::mediumTypeNames
({
    { mediumType::soil, "soil" },
    { mediumType::fixed, "fixed" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffects::porousFlow::porousFlow(physicsScene& scene)
:
    physicsEffect(scene),
    dict_
    (
        IOobject
        (
            "porousFlowProperties",
            scene.mesh().time().constant(),
            scene.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    medium_(selectEntry(mediumTypeNames, "medium", dict_)),
    fluid_(scene.effect<physicsEffects::fluid>("fluid").lbm()),
    soil_(nullptr),
    porosity_(1),
    permeability_(GREAT),
    forchheimer_(0),
    zoned_(false)
{

    Info<< "Porous flow (Guo & Zhao 2002): medium " << mediumTypeNames[medium_];
    if (medium_ == mediumType::fixed)
    {
        if (scene.has("soil"))
        {
            FatalIOErrorInFunction(dict_)
                << "medium fixed is a rigid matrix for a scene without soil:"
                << " with the soil in the scene use medium soil (its"
                << " porosity and drag)" << exit(FatalIOError);
        }
        const dictionary& coeffs = dict_.subDict("fixedCoeffs");
        porosity_ = coeffs.get<scalar>("porosity");
        permeability_ = coeffs.get<scalar>("permeability");
        forchheimer_ = optionalEntry<scalar>(coeffs, "Forchheimer", 0);
        if (!(porosity_ > 0 && porosity_ <= 1))
        {
            FatalIOErrorInFunction(coeffs)
                << "porosity " << porosity_ << " is not allowed: the fluid"
                << " fraction must lie in (0, 1]" << exit(FatalIOError);
        }
        if (!(permeability_ > 0))
        {
            FatalIOErrorInFunction(coeffs)
                << "permeability " << permeability_ << " is not allowed: it"
                << " must be > 0 [m2]" << exit(FatalIOError);
        }
        if (!(forchheimer_ >= 0))
        {
            FatalIOErrorInFunction(coeffs)
                << "Forchheimer " << forchheimer_ << " is not allowed: it"
                << " must be >= 0" << exit(FatalIOError);
        }
        const latticeMesh& lattice = fluid_.lattice();
        zoned_ = foundEntry(coeffs, "cellZone");
        if (zoned_)
        {
            const word zoneName(coeffs.get<word>("cellZone"));
            const cellZoneMesh& zones = scene.mesh().cellZones();
            const label zonei = zones.findZoneID(zoneName);
            if (zonei < 0)
            {
                FatalIOErrorInFunction(coeffs)
                    << "cellZone " << zoneName << " is not a cell zone of"
                    << " the mesh; its cell zones: " << zones.names() << nl
                    << "    Make it with topoSet (a cellSet, then setToCellZone"
                    << " or a cellZoneSet action)" << exit(FatalIOError);
            }
            const labelList& cells = zones[zonei];
            if (returnReduce(cells.size(), sumOp<label>()) == 0)
            {
                FatalIOErrorInFunction(coeffs)
                    << "cellZone " << zoneName << " holds no cell: the"
                    << " medium would be nowhere" << exit(FatalIOError);
            }
            zoneNodes_.setSize(cells.size());
            scalarList storage(lattice.nBox(), 1.0);
            forAll(cells, i)
            {
                zoneNodes_[i] = lattice.cellNode()[cells[i]];
                storage[zoneNodes_[i]] = porosity_;
            }
            // (the resistance as a relaxation of the force field)
            fluid_.enableForceField();
            fluid_.setStorage(storage);
            Info<< " in cell zone " << zoneName << " ("
                << returnReduce(cells.size(), sumOp<label>()) << " cells;"
                << " the lattice carries its resistance, the porosity is"
                << " its storage)";
        }
        const scalar H = lattice.dx();
        Info<< ", porosity " << porosity_ << ", permeability "
            << permeability_ << " m2 (Darcy number K/dx^2 "
            << permeability_/sqr(H) << "), Forchheimer " << forchheimer_
            << nl;
        if (!zoned_)
        {
            // (after the line above: setPorosity logs its own)
            fluid_.setPorosity(scalarList(lattice.nBox(), porosity_));
        }
        setResistance();
    }
    else
    {
        // The soil's porosity is mapped onto the lattice each step
        soil_ = &scene.effect<physicsEffects::soil>("soil");
        fluid_.enablePorosity();
        Info<< ": porosity 1 - phi of the soil, resistance of the drag";
        const scalarList nMin(porosityBounds(soil_->mpm()));
        checkPorous(soil_->mpm(), nMin);
        const bool displacement =
            optionalEntry<Switch>(dict_, "displacement", false);
        if (displacement)
        {
            fluid_.enableDisplacement();
            // What it costs in accuracy: the pore water is the lattice's,
            // with the bulk modulus K_f = rho c_s^2 of its artificial sound
            // speed, and a soil's consolidation coefficient
            // c_v = k/(mu (n/K_f + 1/M)) (Biot, incompressible grains)
            // takes it: slower than with water by
            // (n/K_f + 1/M)/(n/K_w + 1/M) for each material's M
            const lbmUnits& units = fluid_.units();
            const scalar Kf = units.rho0()*sqr(units.soundSpeed());
            const scalar Kwater = 2.2e9;
            Info<< "; displacement on (moving soil pushes its volume of"
                << " water aside)" << nl;
            char figures[160];
            std::snprintf
            (
                figures, sizeof(figures),
                "    the pore water's bulk modulus is the lattice's,"
                " rho c_s^2 = %.3g Pa, %.3g times below water's (2.2e9 Pa)",
                Kf, Kwater/Kf
            );
            Info<< figures << nl;
            if (scene.has("soil"))
            {
                const materialPointSoil& mpm =
                    scene.effect<physicsEffects::soil>("soil").mpm();
                const scalar n = max(mpm.minPorosity(), SMALL);
                std::snprintf(figures, sizeof(figures), "%.3g", n);
                Info<< "    a soil's consolidation (c_v = k/(mu (n/K_f"
                    << " + 1/M))) runs slower than with water by, at n = "
                    << figures << ":";
                for (const constitutiveModel& mat : mpm.materials())
                {
                    const scalar M = mat.M();
                    std::snprintf
                    (
                        figures, sizeof(figures), " %.3g",
                        (n/Kf + 1/M)/(n/Kwater + 1/M)
                    );
                    Info<< " " << mat.name() << figures;
                }
                Info<< " (a shorter time step raises K_f as 1/dt^2)";
                checkPoreWaterStiffness(mpm, nMin);
            }
        }
        else
        {
            Info<< "; displacement off (moving soil does not push water"
                << " aside: mixture continuity is not enforced)";
        }
    }
    if (medium_ == mediumType::fixed && dict_.found("displacement"))
    {
        FatalIOErrorInFunction(dict_)
            << "displacement applies to medium soil only (a fixed matrix"
            << " does not move): remove the keyword" << exit(FatalIOError);
    }
    Info<< nl << endl;
    if (medium_ == mediumType::soil)
    {
        reportBrinkmanLayer(scene);
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::physicsEffects::porousFlow::reportBrinkmanLayer
(
    physicsScene& scene
) const
{
    // The lattice's viscous term in the pores is Brinkman's: at a no-slip
    // wall (and where the soil meets clear water) the superficial velocity
    // goes from Darcy's to the wall's across
    // delta = sqrt(nu K/(n nu_w)) (Guo & Zhao's nu_e = nu; Darcy's
    // resistance with the water's nu_w = mu/rho of the drag). A lattice
    // viscosity raised for stability widens it by sqrt(nu/nu_w): a new
    // user's probe (2026-12-07, nu 1.6 m2/s, K 1e-11 m2) had delta 6.3 mm
    // and a column's discharge 29% below Darcy's between no-slip walls,
    // unsaid (slip walls: exact)
    const dragModel& drag =
        scene.effect<physicsEffects::drag>("drag").model();
    const scalar nuWater = drag.muFluid()/drag.rhoFluid();
    const scalar nu = fluid_.units().nu();
    const scalar dx = fluid_.lattice().dx();
    const materialPointSoil& mpm = soil_->mpm();
    const scalarList nMax(porosityBounds(mpm, true));

    Info<< "Porous flow: the Brinkman layer at no-slip walls and the soil's"
        << " faces, sqrt(nu K/(n nu_w)) at each material's loosest:";
    scalar widest = 0;
    forAll(nMax, m)
    {
        if (!(nMax[m] > 0 && nMax[m] <= 1))
        {
            continue;
        }
        const scalar K = drag.permeability(1 - nMax[m]);
        if (!(K < VGREAT))
        {
            continue;
        }
        const scalar delta = std::sqrt(nu*K/(nMax[m]*nuWater));
        widest = max(widest, delta);
        char figures[96];
        std::snprintf
        (
            figures, sizeof(figures), " %.3g m (%.2g cells)", delta, delta/dx
        );
        Info<< " " << mpm.materials()[m].name() << figures;
    }
    Info<< nl << endl;
    bool walls = false;
    for (const auto kind : fluid_.boundaries().patchKinds())
    {
        walls = walls
         || kind == lbmBoundaries::WALL || kind == lbmBoundaries::MOVINGWALL;
    }
    reduce(walls, orOp<bool>());
    if (walls && nu > 1.5*nuWater && widest > 0.5*dx)
    {
        char figures[200];
        std::snprintf
        (
            figures, sizeof(figures),
            "the lattice's viscosity nu %.3g m2/s is %.3g times the"
            " water's (%.3g, the drag's muFluid/rhoFluid), which widens the"
            " Brinkman layer to %.3g m (%.2g cells)",
            nu, nu/nuWater, nuWater, widest, widest/dx
        );
        WarningInFunction
            << figures << ": the seepage discharge between the no-slip"
            << " walls, a width W apart, falls by about 2 delta/W (a new"
            << " user's column: 29%)." << nl
            << "    Make the walls beside seepage slip, or lower nu (tau"
            << " nearer 1/2, or a smaller deltaT)" << endl;
    }
}


Foam::scalarList Foam::physicsEffects::porousFlow::porosityBounds
(
    const materialPointSoil& mpm,
    const bool loosest
)
{
    // (the largest as the least of -n)
    const scalar sign = loosest ? -1 : 1;
    const materialPoints& points = mpm.points();
    scalarList bound(mpm.materials().size(), GREAT);
    forAll(points.porosity, p)
    {
        const label m = points.material[p];
        bound[m] = min(bound[m], sign*points.porosity[p]);
    }
    Pstream::listCombineGather(bound, minEqOp<scalar>());
    Pstream::listCombineScatter(bound);
    for (scalar& b : bound)
    {
        b *= sign;
    }
    return bound;
}


void Foam::physicsEffects::porousFlow::checkPorous
(
    const materialPointSoil& mpm,
    const scalarList& nMin
) const
{
    // The Guo-Zhao lattice divides by the porosity (the pore pressure
    // c_s^2 (rho - 1)/n, the equilibrium's u u/n) and the drag laws'
    // permeability vanishes with it: a soil without pores cannot hold
    // the water (it crashed on the first steps)
    const PtrList<constitutiveModel>& materials = mpm.materials();
    forAll(materials, m)
    {
        if (nMin[m] < GREAT && nMin[m] <= 0)
        {
            FatalIOErrorInFunction(dict_)
                << "medium soil: material " << materials[m].name()
                << " has points of porosity " << nMin[m] << ": the water"
                << " cannot be in a soil without pores (the porous lattice"
                << " divides by the porosity)." << nl
                << "    Allowed: porosity > 0 for every region of"
                << " system/setMaterialPointsDict in a scene with porousFlow"
                << exit(FatalIOError);
        }
    }
}


void Foam::physicsEffects::porousFlow::checkPoreWaterStiffness
(
    const materialPointSoil& mpm,
    const scalarList& nMin
) const
{
    // With displacement the soil's compression raises its pore pressure
    // by K_f/n per unit volumetric strain, K_f = rho_w c_s^2 the lattice's
    // bulk modulus, and the soil feels that pressure once per water step
    // (its sub-steps hold it): a spring integrated explicitly at the
    // water's step. Its grid-scale mode, the soil moving with its pore
    // water (saturated density rho_sat = rho_d + n rho_w, rho_d the
    // material's density, the solid mass per mixture volume), turns by
    // (omega dt)^2 ~ 4 K_f/(n rho_sat) (dt/dx)^2 = 4 rho_w/(3 n rho_sat)
    // per step, whatever dt and dx (K_f grows as (dx/dt)^2): it must stay
    // below 4. Measured on a settling block (rho_s 2650 kg/m3, d 2 mm):
    // rho_w/(3 n rho_sat) = 1.13 (n 0.12), 1.23 (0.11) and 1.34 (0.1) grew
    // from round-off and stopped within 0.11 s; 1.05 (0.13) ran, and a
    // block of grains as dense as water carried by a stream (0.83) ran
    const PtrList<constitutiveModel>& materials = mpm.materials();
    const scalar rhoW = fluid_.units().rho0();
    const scalar limit = 1.1;
    forAll(materials, m)
    {
        if (nMin[m] >= GREAT)
        {
            continue;
        }
        const scalar rhoD = materials[m].rho();
        const scalar rhoSat = rhoD + nMin[m]*rhoW;
        const scalar ratio = rhoW/(3*max(nMin[m], VSMALL)*rhoSat);
        if (ratio > limit)
        {
            char figures[200];
            std::snprintf
            (
                figures, sizeof(figures),
                " (density %.4g kg/m3, porosity down to %.3g) is too dense"
                " a skeleton for the lattice's pore water:"
                " rho_w/(3 n (rho + n rho_w)) = %.3g is above %.3g.",
                rhoD, nMin[m], ratio, limit
            );
            char allowed[80];
            std::snprintf
            (
                allowed, sizeof(allowed),
                "rho_w/(3 n (rho + n rho_w)) <= %.3g", limit
            );
            FatalIOErrorInFunction(dict_)
                << "displacement on: material " << materials[m].name()
                << figures << nl
                << "    Its compression raises its pore pressure by K_f/n"
                << " (K_f = rho_w c_s^2, the lattice's bulk modulus), which"
                << " the soil feels once per water step: above that ratio"
                << " the pressure grows from step to step whatever deltaT"
                << " and the mesh (K_f grows as (dx/dt)^2 as the soil's"
                << " inertia does)." << nl
                << "    Allowed: " << allowed << " (a looser or lighter"
                << " skeleton), or displacement off" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::physicsEffects::porousFlow::requires() const
{
    if (medium_ == mediumType::soil)
    {
        // (without buoyancy the water would feel -grad(n p): a spurious
        // force p grad(n) at the soil's surface)
        return wordList({"fluid", "soil", "drag", "buoyancy"});
    }
    return wordList({"fluid"});
}


void Foam::physicsEffects::porousFlow::setResistance()
{
    const lbmUnits& units = fluid_.units();
    const scalar dt = units.dt();
    // (per unit mass of the Guo-Zhao lattice's superficial momentum; in a
    // zone the lattice carries no porosity: nu/K, see Description)
    const scalar nLattice = (zoned_ ? 1 : porosity_);
    const scalar darcy = nLattice*units.nu()/permeability_;
    const scalar forch = nLattice*forchheimer_/std::sqrt(permeability_);

    if (forch > 0)
    {
        fluid_.nodalVelocity(velocity_, true);
    }
    for
    (
        const label n
      : (zoned_ ? zoneNodes_ : fluid_.lattice().cellNode())
    )
    {
        // (|u| superficial, as the lattice's velocity)
        const scalar a =
            dt*(darcy + (forch > 0 ? forch*mag(velocity_[n]) : 0));
        const dragRelaxation relax = dragRelaxation::oneWay(a);

        // (the matrix is at rest)
        fluid_.setRelaxation(n, relax.kappa(), relax.s(), Zero);
    }
}


void Foam::physicsEffects::porousFlow::mapPorosity()
{
    const scalarList& phi = soil_->solidFraction();
    soilPorosity_.setSize(phi.size());
    forAll(soilPorosity_, n)
    {
        soilPorosity_[n] = 1 - phi[n];
    }
    if (!fluid_.displacement())
    {
        fluid_.setPorosity(soilPorosity_);
        return;
    }

    // The fall of the porosity the soil's coming step will make,
    // -dt div(phi v_s) (central differences; no flux through a wall),
    // given to the water ahead of it
    const List<vector>& soilVelocity = soil_->nodeVelocity();
    const latticeMesh& lattice = fluid_.lattice();
    const List<unsigned char>& kind = lattice.kind();
    const labelVector& stride = lattice.stride();
    const scalar c = fluid_.units().dt()/(2*lattice.dx());
    predictedFall_.setSize(phi.size());
    predictedFall_ = 0;
    for (const label n : lattice.cellNode())
    {
        scalar div = 0;
        for (direction a = 0; a < lattice.nDim(); ++a)
        {
            const scalar own = phi[n]*soilVelocity[n][a];
            const label up = n + stride[a];
            const label down = n - stride[a];
            const scalar fUp =
                kind[up] == latticeMesh::WALL
              ? -own : phi[up]*soilVelocity[up][a];
            const scalar fDown =
                kind[down] == latticeMesh::WALL
              ? -own : phi[down]*soilVelocity[down][a];
            div += fUp - fDown;
        }
        predictedFall_[n] = -c*div;
    }
    fluid_.setPorosity(soilPorosity_, &predictedFall_);
}


Foam::sceneStageList Foam::physicsEffects::porousFlow::stages() const
{
    if (medium_ == mediumType::soil || forchheimer_ > 0)
    {
        return sceneStageList({sceneStage::porosity});
    }
    return sceneStageList();
}


void Foam::physicsEffects::porousFlow::evolve(const sceneStage)
{
    if (medium_ == mediumType::soil)
    {
        mapPorosity();
    }
    else
    {
        setResistance();
    }
}


Foam::scalar Foam::physicsEffects::porousFlow::memoryBytes() const
{
    return
        scalar(fluid_.lattice().nBox())
       *(sizeof(scalar) + (forchheimer_ > 0 ? sizeof(vector) : 0))
      + scalar(zoneNodes_.size())*sizeof(label);
}


// ************************************************************************* //
