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

#include "nodeFieldIO.H"
#include "volFields.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::IOobject nodeFieldIO
(
    const Foam::latticeMesh& lattice,
    const Foam::word& name,
    const Foam::IOobject::readOption r
)
{
    using namespace Foam;
    return IOobject
    (
        name,
        lattice.mesh().time().timeName(),
        lattice.mesh(),
        r,
        IOobject::NO_WRITE,
        false
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::writeNodeField
(
    const latticeMesh& lattice,
    const word& name,
    const scalar* nodeValues
)
{
    const fvMesh& mesh = lattice.mesh();
    volScalarField fld
    (
        nodeFieldIO(lattice, name, IOobject::NO_READ),
        mesh,
        dimensionedScalar(dimless, Zero)
    );
    const labelList& cellNode = lattice.cellNode();
    scalarField& values = fld.primitiveFieldRef();
    forAll(cellNode, celli)
    {
        values[celli] = nodeValues[cellNode[celli]];
    }
    // A uniform field is written "uniform <value>" as text even in binary
    // format, at the stream's precision: 17 digits, so that it reads back
    // exactly (water at rest on a processor: populations uniform)
    const unsigned int precision = IOstream::defaultPrecision(17);
    fld.writeObject
    (
        IOstream::BINARY,
        IOstream::currentVersion,
        mesh.time().writeCompression(),
        true
    );
    IOstream::defaultPrecision(precision);
}


bool Foam::foundNodeField(const latticeMesh& lattice, const word& name)
{
    return
        nodeFieldIO(lattice, name, IOobject::MUST_READ)
       .typeHeaderOk<volScalarField>(true);
}


void Foam::readNodeField
(
    const latticeMesh& lattice,
    const word& name,
    scalar* nodeValues
)
{
    const volScalarField fld
    (
        nodeFieldIO(lattice, name, IOobject::MUST_READ),
        lattice.mesh()
    );
    checkFinite(fld.primitiveField(), fld.objectPath(), "internalField");
    const labelList& cellNode = lattice.cellNode();
    forAll(cellNode, celli)
    {
        nodeValues[cellNode[celli]] = fld[celli];
    }
}


// ************************************************************************* //
