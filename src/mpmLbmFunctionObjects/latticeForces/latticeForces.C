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

#include "latticeForces.H"
#include "optionalEntry.H"
#include "mpmLbmFunctionObjectScene.H"
#include "fluidEffect.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(latticeForces, 0);
    addToRunTimeSelectionTable(functionObject, latticeForces, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::functionObjects::latticeForces::createFiles()
{
    if (!Pstream::master() || headerDone_)
    {
        return;
    }
    headerDone_ = true;
    auto header = [this](OFstream& os, const string& title,
                         const wordList& columns)
    {
        writeHeader(os, title);
        writeCommented(os, "Time");
        for (const word& col : columns)
        {
            writeTabbed(os, col);
        }
        os  << endl;
    };
    auto make = [&](const word& file, const string& title,
                    const wordList& columns)
    {
        autoPtr<OFstream> os = createFile(file);
        header(os(), title, columns);
        return os;
    };
    // (force.dat: writeFile's own file)
    header
    (
        file(), "Force of the water [N] (momentum exchange)",
        wordList({"Fx", "Fy", "Fz"})
    );
    momentFile_ = make
    (
        "moment", "Moment of the water [N m] about CofR",
        wordList({"Mx", "My", "Mz"})
    );
    if (coefficients_)
    {
        coefficientFile_ = make
        (
            "coefficient",
            "Force coefficients: Cd = F.dragDir/(rhoInf magUInf^2 Aref/2),"
            " Cl = F.liftDir/(...), Cm = M.(dragDir ^ liftDir)/(... lRef)",
            wordList({"Cd", "Cl", "Cm"})
        );
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::latticeForces::latticeForces
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "force", dict),
    bodiesSelected_(false),
    CofR_(Zero),
    pRef_(0),
    coefficients_(false),
    magUInf_(0),
    Aref_(0),
    lRef_(0),
    rhoInf_(0),
    dragDir_(1, 0, 0),
    liftDir_(0, 1, 0),
    force_(Zero),
    moment_(Zero),
    headerDone_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::latticeForces::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    dict_ = dict;

    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    obstacleNames_ = optionalEntry<wordRes>(dict, "obstacles", wordRes());
    selectedBodies_.clear();
    bodiesSelected_ = false;
    if (!foundEntry(dict, "patches") && obstacleNames_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Give the patches, the obstacles or both whose force is"
            << " wanted, e.g. patches (walls); or obstacles (pier);"
            << exit(FatalIOError);
    }
    selected_ = selectNames
    (
        dict,
        "patches",
        optionalEntry<wordRes>(dict, "patches", wordRes()),
        patches.names()
    );

    CofR_ = optionalEntry<point>(dict, "CofR", Zero);
    pRef_ = optionalEntry<scalar>(dict, "pRef", 0);

    coefficients_ = foundEntry(dict, "magUInf");
    if (coefficients_)
    {
        auto positive = [&dict](const word& key)
        {
            // (bounded so that rhoInf magUInf^2 Aref/2 x lRef, the
            // coefficients' divisor, can neither overflow nor vanish)
            const scalar v = dict.get<scalar>(key);
            if (!(v >= 1e-30 && v <= 1e30))
            {
                FatalIOErrorInFunction(dict)
                    << key << " " << v << " is not allowed: a positive"
                    << " number in [1e-30, 1e30] (SI units) is required"
                    << exit(FatalIOError);
            }
            return v;
        };
        magUInf_ = positive("magUInf");
        Aref_ = positive("Aref");
        lRef_ = positive("lRef");
        rhoInf_ = foundEntry(dict, "rhoInf") ? positive("rhoInf") : 0;

        auto direction = [&dict](const word& key, const vector& deflt)
        {
            // (scaled by its largest component before its magnitude is
            // taken: the square of 1e300 overflows)
            const vector d = optionalEntry<vector>(dict, key, deflt);
            const scalar largest = cmptMax(cmptMag(d));
            if
            (
                !(largest > 0) || !std::isfinite(d.x())
             || !std::isfinite(d.y()) || !std::isfinite(d.z())
            )
            {
                FatalIOErrorInFunction(dict)
                    << key << " " << d << " is not allowed: a non-zero"
                    << " vector of finite components is required"
                    << exit(FatalIOError);
            }
            const vector unit = d/largest;
            return unit/mag(unit);
        };
        dragDir_ = direction("dragDir", vector(1, 0, 0));
        liftDir_ = direction("liftDir", vector(0, 1, 0));
        if (mag(dragDir_ & liftDir_) > 1e-6)
        {
            FatalIOErrorInFunction(dict)
                << "dragDir " << dragDir_ << " and liftDir " << liftDir_
                << " must be perpendicular" << exit(FatalIOError);
        }
    }

    return true;
}


bool Foam::functionObjects::latticeForces::execute()
{
    physicsScene& scene = mpmLbmScene(mesh_, type(), name(), "fluid");
    latticeBoltzmannFluid& lbm =
        scene.effect<physicsEffects::fluid>("fluid").lbm();
    if (!bodiesSelected_)
    {
        bodiesSelected_ = true;
        // (the obstacles of constant/fluidProperties)
        selectedBodies_ = selectNames
        (
            dict_,
            "obstacles",
            obstacleNames_,
            lbm.obstacles().names(),
            "the obstacles of "
          + string(mesh_.time().constant()/"fluidProperties")
        );
    }
    lbm.wallForce
    (
        selected_,
        selectedBodies_,
        CofR_,
        pRef_,
        force_,
        moment_
    );
    return true;
}


bool Foam::functionObjects::latticeForces::write()
{
    Log << type() << " " << name() << " write:" << nl
        << "    force  " << force_ << " N" << nl
        << "    moment " << moment_ << " N m" << nl;

    scalar Cd = 0, Cl = 0, Cm = 0;
    if (coefficients_)
    {
        const physicsScene& scene =
            mpmLbmScene(mesh_, type(), name(), "fluid");
        const scalar rho =
            rhoInf_ > 0
          ? rhoInf_
          : scene.findEffect<physicsEffects::fluid>("fluid")
                ->lbmConst().units().rho0();
        const scalar q = 0.5*rho*sqr(magUInf_)*Aref_;
        Cd = (force_ & dragDir_)/q;
        Cl = (force_ & liftDir_)/q;
        Cm = (moment_ & (dragDir_ ^ liftDir_))/(q*lRef_);
        Log << "    Cd " << Cd << ", Cl " << Cl << ", Cm " << Cm << nl;
    }
    Log << endl;

    if (!Pstream::master() || !writeToFile())
    {
        return true;
    }
    createFiles();
    auto row = [this](OFstream& os, const vector& v)
    {
        writeCurrentTime(os);
        os  << tab << v.x() << tab << v.y() << tab << v.z() << endl;
    };
    row(file(), force_);
    row(momentFile_(), moment_);
    if (coefficients_)
    {
        row(coefficientFile_(), vector(Cd, Cl, Cm));
    }
    return true;
}


// ************************************************************************* //
