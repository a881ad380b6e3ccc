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

#include "materialPointSoil.H"
#include "StringStream.H"
#include "restartManifest.H"
#include "IFstream.H"
#include <fstream>
#include "selectEntry.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::materialPointSoil::updateFields()
{
    // Nodal fields, as the couplings see them: the solid volume fraction
    // phi and the soil's velocity. (The node masses of the step's own
    // nodalFields are kept: addNodeForces shares forces by them, and a
    // refresh for a function object must not change the run.)
    scalarList phi;
    List<vector> vel;
    scalarList stepNodeMass(nodeMass_);
    nodalFields(phi, vel);
    nodeMass_.transfer(stepNodeMass);

    if (!soilFraction_.valid())
    {
        // Registered and written with the other fields at write times
        soilFraction_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    "soilFraction",
                    mesh_.time().timeName(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh_,
                dimensionedScalar(dimless, Zero)
            )
        );
        Usoil_.reset
        (
            new volVectorField
            (
                IOobject
                (
                    "Usoil",
                    mesh_.time().timeName(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh_,
                dimensionedVector(dimVelocity, Zero)
            )
        );
    }
    scalarField& alpha = soilFraction_->primitiveFieldRef();
    vectorField& Us = Usoil_->primitiveFieldRef();
    forAll(lattice_.cellNode(), celli)
    {
        const label n = lattice_.cellNode()[celli];
        alpha[celli] = phi[n];
        Us[celli] = vel[n];
    }
    soilFraction_->correctBoundaryConditions();
    Usoil_->correctBoundaryConditions();
}


void Foam::materialPointSoil::write()
{
    points_.write(mesh_, lattice_);
}


void Foam::materialPointSoil::checkAgainstWriter() const
{
    // The points as setMaterialPoints wrote them: its manifest records a
    // check sum per cloud file, summed over the points, which decomposePar
    // carries to every processor folder. A processor's cloud edited or
    // damaged after decomposePar has no file check sum to find it: these
    // do (serially the files' own check sums report an edit too)
    const Time& runTime = mesh_.time();
    const fileName path
    (
        runTime.timePath()/"uniform"/restartManifest::manifestName
    );
    label found = isFile(path);
    reduce(found, maxOp<label>());
    if (!found)
    {
        return;
    }
    // The master's text, parsed on every processor under the file's name
    // (a dictionary scattered as such is named after the stream, and an
    // entry's error on the other processors named no file; theirs could
    // be the message printed first)
    string text;
    if (Pstream::master() && isFile(path))
    {
        std::ifstream in(path.c_str(), std::ios::binary);
        text.assign
        (
            std::istreambuf_iterator<char>(in),
            std::istreambuf_iterator<char>()
        );
    }
    Pstream::scatter(text);
    dictionary written;
    if (!text.empty())
    {
        IStringStream is(text);
        is.name() = path;
        written = dictionary(is);
    }
    if
    (
        written.getOrDefault<word>("writer", word::null) != "setMaterialPoints"
     || !written.found("global")
    )
    {
        return;
    }
    const dictionary& global = written.subDict("global");
    HashTable<scalar> sums(points_.hashSums());
    wordList differ;
    if (returnReduce(points_.size(), sumOp<label>()) == 0)
    {
        // (no point was read: the positions are what is missing)
        differ.append("coordinates");
    }
    for (const word& name : sums.sortedToc())
    {
        const word key("cloudHash_" + name);
        const scalar here = returnReduce(sums[name], sumOp<scalar>());
        if (global.found(key) && here != global.get<scalar>(key))
        {
            differ.append(name);
        }
    }
    if (differ.size())
    {
        // (each named by its file)
        OStringStream files;
        for (const word& name : differ)
        {
            const fileName file
            (
                runTime.timeName()/"lagrangian"/materialPoints::cloudName
               /name
            );
            files<< " " << file.c_str();
            restartManifest::suspects.append(file);
        }
        WarningInFunction
            << "The material points' files" << files.str().c_str()
            << (Pstream::parRun() ? " (in the processor folders)" : "")
            << " differ from what setMaterialPoints wrote (" << path.name()
            << " of that time): edited, or damaged after it (e.g. after"
            << " decomposePar)." << nl
            << "    They are read as they are now; run setMaterialPoints"
            << (Pstream::parRun() ? " and decomposePar" : "")
            << " again for its points" << nl << endl;
    }
}


// ************************************************************************* //
