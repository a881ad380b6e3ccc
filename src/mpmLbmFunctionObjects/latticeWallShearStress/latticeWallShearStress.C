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

#include "latticeWallShearStress.H"
#include "optionalEntry.H"
#include "mpmLbmFunctionObjectScene.H"
#include "fluidEffect.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(latticeWallShearStress, 0);
    addToRunTimeSelectionTable
    (
        functionObject,
        latticeWallShearStress,
        dictionary
    );
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::volVectorField&
Foam::functionObjects::latticeWallShearStress::resultField()
{
    if (!mesh_.foundObject<volVectorField>(result_))
    {
        volVectorField* fld = new volVectorField
        (
            IOobject
            (
                result_,
                mesh_.time().timeName(),
                mesh_,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh_,
            dimensionedVector(dimPressure, Zero)
        );
        mesh_.objectRegistry::store(fld);
    }
    return mesh_.lookupObjectRef<volVectorField>(result_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::latticeWallShearStress::latticeWallShearStress
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, "wallShearStress", dict),
    result_("wallShearStress"),
    headerDone_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::latticeWallShearStress::read
(
    const dictionary& dict
)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    patchNames_ = optionalEntry<wordRes>(dict, "patches", wordRes());
    result_ = optionalEntry<word>(dict, "result", "wallShearStress");
    selected_.clear();

    // (checked now: a name that matches no patch is refused at start-up)
    selectNames(dict, "patches", patchNames_, mesh_.boundaryMesh().names());
    return true;
}


bool Foam::functionObjects::latticeWallShearStress::execute()
{
    physicsScene& scene = mpmLbmScene(mesh_, type(), name(), "fluid");
    latticeBoltzmannFluid& lbm =
        scene.effect<physicsEffects::fluid>("fluid").lbm();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();

    if (selected_.empty())
    {
        // The walls: the named patches, or every bounce-back wall
        const List<lbmBoundaries::patchKind>& kinds =
            lbm.boundaries().patchKinds();
        // (the names were checked by read)
        selected_ = selectNames
        (
            dictionary::null, "patches", patchNames_, patches.names()
        );
        if (patchNames_.empty())
        {
            forAll(patches, patchi)
            {
                selected_[patchi] =
                    kinds[patchi] == lbmBoundaries::WALL
                 || kinds[patchi] == lbmBoundaries::MOVINGWALL;
            }
        }
    }

    List<symmTensor> sigma;
    lbm.viscousStress(sigma);

    const latticeMesh& lattice = lbm.lattice();
    const labelList& cellNode = lattice.cellNode();
    const List<unsigned char>& kind = lattice.kind();
    const labelVector& stride = lattice.stride();
    const lbmObstacles& bodies = lbm.obstacles();

    volVectorField& tau = resultField();
    tau.primitiveFieldRef() = Zero;
    volVectorField::Boundary& tauBf = tau.boundaryFieldRef();

    mean_.setSize(patches.size());
    largest_.setSize(patches.size());
    scalarList area(patches.size(), Zero);
    mean_ = Zero;
    largest_ = 0;
    forAll(patches, patchi)
    {
        vectorField& tp = tauBf[patchi];
        tp = Zero;
        if (!selected_[patchi] || patches[patchi].coupled())
        {
            continue;
        }
        const labelUList& faceCells = patches[patchi].faceCells();
        const vectorField& Sf = mesh_.boundary()[patchi].Sf();
        const scalarField& magSf = mesh_.boundary()[patchi].magSf();
        forAll(faceCells, facei)
        {
            const label n1 = cellNode[faceCells[facei]];
            if (bodies.solid(n1))
            {
                continue;
            }
            const vector nf = Sf[facei]/magSf[facei];
            // The second water node inward, along the lattice axis
            // nearest the face's normal
            const direction a = findMax(cmptMag(nf));
            const label n2 = n1 - (nf[a] > 0 ? 1 : -1)*stride[a];
            symmTensor s = sigma[n1];
            if
            (
                n2 >= 0 && n2 < kind.size()
             && kind[n2] == latticeMesh::OWNED && !bodies.solid(n2)
            )
            {
                s = 1.5*sigma[n1] - 0.5*sigma[n2];
            }
            const vector t = -(s & nf);
            tp[facei] = t - (t & nf)*nf;
            mean_[patchi] += magSf[facei]*tp[facei];
            area[patchi] += magSf[facei];
            largest_[patchi] = max(largest_[patchi], mag(tp[facei]));
        }
    }
    Pstream::listCombineGather(mean_, plusEqOp<vector>());
    Pstream::listCombineGather(area, plusEqOp<scalar>());
    Pstream::listCombineGather(largest_, maxEqOp<scalar>());
    Pstream::listCombineScatter(mean_);
    Pstream::listCombineScatter(area);
    Pstream::listCombineScatter(largest_);
    forAll(mean_, patchi)
    {
        if (area[patchi] > 0)
        {
            mean_[patchi] /= area[patchi];
        }
    }
    return true;
}


bool Foam::functionObjects::latticeWallShearStress::write()
{
    if (selected_.empty())
    {
        return true;
    }
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    Log << type() << " " << name() << " write:" << nl;
    forAll(patches, patchi)
    {
        if (selected_[patchi] && !patches[patchi].coupled())
        {
            Log << "    " << patches[patchi].name() << ": mean "
                << mean_[patchi] << " Pa, largest " << largest_[patchi]
                << " Pa" << nl;
        }
    }
    Log << endl;

    // The field, in the current time's folder
    volVectorField& tau = resultField();
    tau.instance() = mesh_.time().timeName();
    tau.write();

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        if (!headerDone_)
        {
            headerDone_ = true;
            writeHeader(os, "Wall shear stress of the water [Pa]: per patch"
                " the area-weighted mean vector and the largest magnitude");
            writeCommented(os, "Time");
            writeTabbed(os, "patch");
            writeTabbed(os, "mean");
            writeTabbed(os, "largest");
            os  << endl;
        }
        forAll(patches, patchi)
        {
            if (selected_[patchi] && !patches[patchi].coupled())
            {
                writeCurrentTime(os);
                os  << tab << patches[patchi].name() << tab << mean_[patchi]
                    << tab << largest_[patchi] << endl;
            }
        }
    }
    return true;
}


// ************************************************************************* //
