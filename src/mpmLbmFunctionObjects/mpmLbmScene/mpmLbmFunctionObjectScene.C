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

#include "mpmLbmFunctionObjectScene.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::physicsScene& Foam::mpmLbmScene
(
    const fvMesh& mesh,
    const word& functionObjectType,
    const word& functionObjectName,
    const word& needs
)
{
    if (!mesh.foundObject<physicsScene>(physicsScene::registryName))
    {
        FatalErrorInFunction
            << "Function object " << functionObjectName << " (type "
            << functionObjectType << ") reads the lattice and the material"
            << " points of the running solver mpmLbmFoam: run it in the"
            << " case's controlDict functions, not with postProcess"
            << exit(FatalError);
    }
    physicsScene& scene =
        mesh.lookupObjectRef<physicsScene>(physicsScene::registryName);
    if (!scene.has(needs))
    {
        FatalIOErrorInFunction(scene.dict())
            << "Function object " << functionObjectName << " (type "
            << functionObjectType << ") needs the effect " << needs
            << ", which this scene does not select: effects "
            << scene.dict().get<wordList>("effects") << exit(FatalIOError);
    }
    return scene;
}


Foam::boolList Foam::selectNames
(
    const dictionary& dict,
    const word& keyword,
    const wordRes& selection,
    const wordList& names,
    const string& namesFrom
)
{
    boolList selected(names.size(), false);
    for (const wordRe& pattern : selection)
    {
        bool found = false;
        forAll(names, i)
        {
            if (pattern.match(names[i]))
            {
                selected[i] = true;
                found = true;
            }
        }
        if (!found)
        {
            FatalIOErrorInFunction(dict)
                << keyword << ": " << pattern << " matches none of "
                << (namesFrom.empty() ? "" : namesFrom.c_str())
                << (namesFrom.empty() ? "" : " ") << names
                << exit(FatalIOError);
        }
    }
    return selected;
}


// ************************************************************************* //
