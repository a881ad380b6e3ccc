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

#include "physicsEffect.H"
#include "fvMesh.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(physicsEffect, 0);
    defineRunTimeSelectionTable(physicsEffect, scene);
    defineMemberFunctionSelectionTable(physicsEffect, haloWidth, mesh);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::autoPtr<Foam::functionObjects::writeFile>
Foam::physicsEffect::newStepFile
(
    const fvMesh& mesh,
    const word& dir,
    const word& name,
    const string& header,
    const wordList& columns
)
{
    dictionary fileDict;
    fileDict.add("writePrecision", 17);
    autoPtr<functionObjects::writeFile> file
    (
        new functionObjects::writeFile(mesh, dir, name, fileDict)
    );
    OFstream& os = file->file();
    file->writeHeader(os, header);
    file->writeCommented(os, "Time");
    for (const word& col : columns)
    {
        file->writeTabbed(os, col);
    }
    os  << endl;
    return file;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::physicsEffect::physicsEffect(physicsScene& scene)
:
    scene_(scene)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::physicsEffect> Foam::physicsEffect::New
(
    const word& name,
    physicsScene& scene,
    const dictionary& dict
)
{
    auto cstrIter = sceneConstructorTablePtr_->cfind(name);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "effect",
            name,
            *sceneConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(scene);
}


Foam::label Foam::physicsEffect::haloWidthOf
(
    const word& name,
    const fvMesh& mesh,
    const dictionary& dict
)
{
    if (!sceneConstructorTablePtr_->found(name))
    {
        FatalIOErrorInLookup
        (
            dict,
            "effect",
            name,
            *sceneConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    auto widthIter = haloWidthmeshMemberFunctionTablePtr_->cfind(name);
    if (!widthIter.found())
    {
        FatalErrorInFunction
            << "effect " << name << " does not declare its halo width:"
            << " add addToMemberFunctionSelectionTable(physicsEffect, "
            << name << ", haloWidth, mesh) beside its constructor's"
            << " registration" << exit(FatalError);
    }

    return widthIter()(mesh);
}


// ************************************************************************* //
