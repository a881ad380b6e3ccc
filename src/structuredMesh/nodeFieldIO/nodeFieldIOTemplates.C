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

#include "volFields.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::writeNodeField
(
    const latticeMesh& lattice,
    const word& name,
    const UList<Type>& nodeValues,
    const dimensionSet& dims,
    const bool exact
)
{
    const fvMesh& mesh = lattice.mesh();
    GeometricField<Type, fvPatchField, volMesh> fld
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensioned<Type>("zero", dims, pTraits<Type>::zero)
    );
    const labelList& cellNode = lattice.cellNode();
    Field<Type>& values = fld.primitiveFieldRef();
    forAll(cellNode, celli)
    {
        values[celli] = nodeValues[cellNode[celli]];
    }
    if (exact)
    {
        // (17 digits: a uniform field is written as text even in binary)
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
    else
    {
        fld.write();
    }
}


// ************************************************************************* //
