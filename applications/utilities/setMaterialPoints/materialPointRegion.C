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

#include "materialPointRegion.H"
#include "selectEntry.H"
#include "optionalEntry.H"
#include "mathematicalConstants.H"
#include "Time.H"
#include "IOobject.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::materialPointRegion::voidMaterial("none");

const Foam::Enum<Foam::materialPointRegion::stressType>
Foam::materialPointRegion::stressTypeNames
({
    { stressType::none, "none" },
    { stressType::geostatic, "geostatic" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::materialPointRegion::readGeostatic
(
    const dictionary& dict,
    const vector& gravity
)
{
    const dictionary& gd = dict.subDict("geostaticCoeffs");
    surfaceHeight_ = gd.get<scalar>("surface");
    K0_ = gd.get<scalar>("K0");
    waterRho_ = optionalEntry<scalar>(gd, "waterDensity", 0);
    // (default: the surface, whose own check follows)
    waterTable_ = optionalEntry<scalar>(gd, "waterTable", surfaceHeight_);
    if
    (
        gd.found("waterTable")
     && (!std::isfinite(waterTable_) || !(mag(waterTable_) <= 1e6))
    )
    {
        FatalIOErrorInFunction(gd)
            << "waterTable " << waterTable_ << " is not allowed: a finite"
            << " height [m] along -gravity, as surface (the level of the"
            << " pore water: dry soil above it)" << exit(FatalIOError);
    }
    // (the buoyant unit weight rho - (1 - n) rho_w must not be negative:
    // 1e300 gave a stress no soil carries, and a trap in the first step)
    if (!(waterRho_ >= 0) || !(rho_ - (1 - porosity_)*waterRho_ >= 0))
    {
        FatalIOErrorInFunction(gd)
            << "waterDensity " << waterRho_ << " is not"
            << " allowed: it must lie in [0, rho/(1 - porosity)] = [0, "
            << rho_/(1 - porosity_) << "] kg/m3 (the soil's buoyant unit"
            << " weight, rho - (1 - n) rho_w, must not be negative)"
            << exit(FatalIOError);
    }
    if (!(K0_ >= 0) || !(K0_ <= 100))
    {
        FatalIOErrorInFunction(gd)
            << "K0 " << K0_ << " is not allowed: it must lie in [0, 100]"
            << " (the ratio of the horizontal to the vertical stress)"
            << exit(FatalIOError);
    }
    if (!std::isfinite(surfaceHeight_) || !(mag(surfaceHeight_) <= 1e6))
    {
        FatalIOErrorInFunction(gd)
            << "surface " << surfaceHeight_ << " is not allowed: it is the"
            << " height [m] of the ground's surface above the region, within"
            << " 1e6 m of the origin" << exit(FatalIOError);
    }
    if (mag(gravity) < SMALL)
    {
        FatalIOErrorInFunction(dict)
            << "Region " << name_ << ": geostatic stress needs the soil's"
            << " gravity: constant/g, and the gravity effect acting on the"
            << " soil in constant/physicsProperties (without it the stress"
            << " is released at the first step and the soil swells)"
            << exit(FatalIOError);
    }
}


void Foam::materialPointRegion::warnBeyondYield
(
    const dictionary& materialDict
) const
{
    // A cohesionless Mohr-Coulomb soil at rest holds sigma_h = K0 sigma_v
    // only for Ka <= K0 <= Kp, Ka = (1 - sin phi)/(1 + sin phi) = 1/Kp
    // (both horizontal stresses K0 sigma_v): outside, the geostatic stress
    // lies beyond the yield surface and the soil yields at its first step
    if (optionalEntry<word>(materialDict, "model", word::null) != "MohrCoulomb")
    {
        return;
    }
    const dictionary& coeffs = optionalDict(materialDict, "MohrCoulombCoeffs");
    const scalar c = optionalEntry<scalar>(coeffs, "cohesion", 0);
    const scalar phi = optionalEntry<scalar>(coeffs, "frictionAngle", 0);
    if (c != 0 || !(phi > 0 && phi < 90))
    {
        return;
    }
    const scalar s = std::sin(phi*constant::mathematical::pi/180);
    const scalar Ka = (1 - s)/(1 + s);
    if (K0_ < Ka*(1 - 1e-9) || K0_ > (1 + 1e-9)/Ka)
    {
        WarningInFunction
            << "Region " << name_ << ": geostatic K0 " << K0_ << " lies"
            << " outside [Ka, Kp] = [" << Ka << ", " << 1/Ka << "] of its"
            << " cohesionless Mohr-Coulomb material (frictionAngle " << phi
            << " deg): the stress starts beyond the yield surface and the"
            << " soil yields at its first step. Jaky's K0 = 1 - sin(phi) = "
            << 1 - s << " lies inside." << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialPointRegion::materialPointRegion
(
    const word& name,
    const dictionary& dict,
    const Time& runTime,
    const dictionary& materialsDict,
    const vector& gravity
)
:
    name_(name),
    dict_(dict),
    surface_
    (
        searchableSurface::New
        (
            dict_.get<word>("type"),
            IOobject
            (
                name,
                runTime.constant(),
                "triSurface",
                runTime,
                IOobject::MUST_READ,
                IOobject::NO_WRITE
            ),
            dict_
        )
    ),
    material_(-1),
    rho_(0),
    velocity_(Zero),
    porosity_(0),
    finesContent_(0),
    stress_(stressType::none),
    surfaceHeight_(0),
    K0_(1),
    waterRho_(0),
    waterTable_(0)
{
    if (!surface_->hasVolumeType())
    {
        FatalIOErrorInFunction(dict_)
            << "Region " << name_ << ": surface type "
            << dict_.get<word>("type")
            << " does not enclose a volume. Use a closed surface"
            << " (searchableBox, searchableCylinder, searchableSphere, a"
            << " closed triSurfaceMesh)" << exit(FatalIOError);
    }

    const wordList materialNames(materialsDict.toc());
    const word mat = dict_.get<word>("material");
    if (mat == voidMaterial)
    {
        // A void: nothing else of the region is read (an entry that would
        // set a property of points it never makes is refused, not ignored)
        if (materialNames.found(voidMaterial))
        {
            FatalIOErrorInFunction(materialsDict)
                << "constant/soilProperties: a material named "
                << voidMaterial << " is not allowed: region " << name_
                << " of setMaterialPointsDict uses material " << voidMaterial
                << " for a void (no points). Rename the material"
                << exit(FatalIOError);
        }
        for
        (
            const word key
          : {"velocity", "porosity", "finesContent", "stress",
             "geostaticCoeffs"}
        )
        {
            if (dict_.found(key, keyType::LITERAL))
            {
                FatalIOErrorInFunction(dict_)
                    << "Region " << name_ << ": " << key << " is not"
                    << " allowed in a region of material " << voidMaterial
                    << " (a void: it gets no points). Remove it, or give the"
                    << " region a material of constant/soilProperties "
                    << materialNames << exit(FatalIOError);
            }
        }
        return;
    }
    material_ = materialNames.find(mat);
    if (material_ < 0)
    {
        FatalIOErrorInFunction(dict_)
            << "Region " << name_ << ": material " << mat << " is not in"
            << " constant/soilProperties materials " << materialNames
            << " (or " << voidMaterial << " for a void)"
            << exit(FatalIOError);
    }
    rho_ = materialsDict.subDict(mat).get<scalar>("rho");
    velocity_ = optionalEntry<vector>(dict_, "velocity", Zero);
    porosity_ = optionalEntry<scalar>(dict_, "porosity", 0);
    if (!(porosity_ >= 0 && porosity_ < 1))
    {
        FatalIOErrorInFunction(dict_)
            << "Region " << name_ << ": porosity " << porosity_
            << " is not allowed: the void fraction must lie in [0, 1)"
            << exit(FatalIOError);
    }
    finesContent_ = optionalEntry<scalar>(dict_, "finesContent", 0);
    if (!(finesContent_ >= 0 && finesContent_ < 1))
    {
        FatalIOErrorInFunction(dict_)
            << "Region " << name_ << ": finesContent " << finesContent_
            << " is not allowed: the erodible fines' mass fraction of the"
            << " solid must lie in [0, 1)" << exit(FatalIOError);
    }
    stress_ = selectEntry(stressTypeNames, "stress", dict_, true, stressType::none);
    if (stress_ == stressType::geostatic)
    {
        readGeostatic(dict_, gravity);
        warnBeyondYield(materialsDict.subDict(mat));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::materialPointRegion::scopeNames(dictionary& dict)
{
    for (entry& e : dict)
    {
        if (e.isDict())
        {
            e.dict().name() = dict.name() + "." + e.keyword();
            scopeNames(e.dict());
        }
    }
}


Foam::PtrList<Foam::materialPointRegion> Foam::materialPointRegion::readList
(
    const IOdictionary& dict,
    const Time& runTime,
    const dictionary& materialsDict,
    const vector& gravity
)
{
    // Read from the list they are nameless blocks: each takes the scoped
    // name of the file and keyword (setMaterialPointsDict.regions.<name>),
    // so that an error names where to look
    PtrList<entry> regionEntries(dict.lookup("regions"));
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
        scopeNames(regionEntries[r].dict());
    }
    if (regionEntries.empty())
    {
        FatalIOErrorInFunction(dict)
            << "regions is empty: give at least one region" << exit(FatalIOError);
    }

    PtrList<materialPointRegion> regions(regionEntries.size());
    forAll(regionEntries, r)
    {
        // OpenFOAM's surfaces raise errors that name no file (searchableBox:
        // "Illegal bounding box"): each is given the region's
        const dictionary& rd = regionEntries[r].dict();
        string ioFile;
        labelPair ioLines(-1, -1);
        const string failure = catchFatal
        (
            [&]()
            {
                regions.set
                (
                    r,
                    new materialPointRegion
                    (
                        regionEntries[r].keyword(),
                        rd,
                        runTime,
                        materialsDict,
                        gravity
                    )
                );
            },
            false,
            &ioFile,
            &ioLines
        );
        if (!failure.empty())
        {
            // (most messages name their region already); an error in
            // another file (the region's material in soilProperties) keeps
            // naming that file and line
            const string prefix("Region " + regionEntries[r].keyword() + ": ");
            // (an entry's own error names it by its scope alone,
            // block.porosity: that is the region's file)
            const fileName& regionFile = rd.topDict().name();
            const bool elsewhere =
                !ioFile.empty() && ioFile[0] == '/'
             && ioFile.compare(0, regionFile.size(), regionFile) != 0;
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__,
                elsewhere ? ioFile : string(rd.name()),
                elsewhere ? ioLines.first() : rd.startLineNumber(),
                elsewhere ? ioLines.second() : rd.endLineNumber()
            )   << (failure.find(prefix) == 0 ? "" : prefix.c_str())
                << failure.c_str() << exit(FatalIOError);
        }
    }
    return regions;
}


Foam::symmTensor Foam::materialPointRegion::initialStress
(
    const point& x,
    const vector& up,
    const scalar magG
) const
{
    if (stress_ != stressType::geostatic)
    {
        return Zero;
    }
    // (above the water table the soil is dry: its own unit weight rho g;
    // below it the buoyant one, (rho - (1 - n) rho_w) g)
    const scalar h = x & up;
    const scalar gammaDry = rho_*magG;
    const scalar gammaWet = (rho_ - (1 - porosity_)*waterRho_)*magG;
    const scalar table = min(waterTable_, surfaceHeight_);
    const scalar sv =
        gammaDry*min(max(h, table) - surfaceHeight_, 0.0)
      + gammaWet*min(h - table, 0.0);
    const symmTensor vv = sqr(up);
    return sv*vv + K0_*sv*(symmTensor::I - vv);
}


// ************************************************************************* //
