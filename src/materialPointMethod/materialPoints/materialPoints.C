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

#include "materialPoints.H"
#include "passiveParticleCloud.H"
#include "IOField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::materialPoints::cloudName("materialPoints");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

template<class Type>
void writeField
(
    const Foam::passiveParticleCloud& cloud,
    const Foam::word& name,
    const Foam::UList<Type>& values,
    const bool binary
)
{
    Foam::IOField<Type> fld
    (
        cloud.fieldIOobject(name, Foam::IOobject::NO_READ),
        values.size()
    );
    fld.Foam::UList<Type>::deepCopy(values);
    if (binary)
    {
        fld.writeObject
        (
            Foam::IOstream::BINARY,
            Foam::IOstream::currentVersion,
            Foam::IOstream::UNCOMPRESSED,
            true
        );
    }
    else
    {
        fld.write();
    }
}


template<class Type>
bool readField
(
    const Foam::passiveParticleCloud& cloud,
    const Foam::word& name,
    Foam::List<Type>& values
)
{
    Foam::IOobject io(cloud.fieldIOobject(name, Foam::IOobject::MUST_READ));
    if (!io.typeHeaderOk<Foam::IOField<Type>>(true))
    {
        return false;
    }
    Foam::IOField<Type> fld(io);
    if (fld.size() != cloud.size())
    {
        FatalErrorInFunction
            << "Field " << fld.objectPath() << " of the material points has "
            << fld.size() << " values for " << cloud.size() << " points"
            << Foam::exit(Foam::FatalError);
    }
    values.transfer(fld);
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::materialPoints::setSize(const label n)
{
    x.setSize(n);
    v.setSize(n);
    m.setSize(n);
    V.setSize(n);
    V0.setSize(n);
    F.setSize(n);
    sigma.setSize(n);
    plasticStrain.setSize(n);
    C.setSize(n);
    material.setSize(n);
    halfLength.setSize(n);
    porosity.setSize(n);
}


void Foam::materialPoints::append
(
    const vector& position,
    const vector& velocity,
    const scalar mass,
    const scalar volume,
    const symmTensor& stress,
    const label materialIndex,
    const vector& halfSize,
    const scalar pointPorosity
)
{
    const label i = size();
    setSize(i + 1);
    x[i] = position;
    v[i] = velocity;
    m[i] = mass;
    V[i] = volume;
    V0[i] = volume;
    F[i] = tensor::I;
    sigma[i] = stress;
    plasticStrain[i] = 0;
    C[i] = Zero;
    material[i] = materialIndex;
    halfLength[i] = halfSize;
    porosity[i] = pointPorosity;
}


Foam::label Foam::materialPoints::memoryPerPoint()
{
    return
        4*sizeof(vector)/3*3       // x, v, halfLength, + spare
      + 2*sizeof(tensor)           // F, C
      + sizeof(symmTensor)         // sigma
      + 5*sizeof(scalar)           // m, V, V0, plasticStrain, porosity
      + sizeof(label);             // material
}


bool Foam::materialPoints::read(const fvMesh& mesh, const word& timeName)
{
    IOobject posIO
    (
        "positions",
        timeName,
        cloud::prefix/cloudName,
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    IOobject coordIO(posIO);
    coordIO.rename("coordinates");
    if
    (
        !posIO.typeHeaderOk<IOField<vector>>(false)
     && !coordIO.typeHeaderOk<IOField<vector>>(false)
    )
    {
        return false;
    }

    passiveParticleCloud cloud(mesh, cloudName, false);
    const label n = cloud.size();
    setSize(n);

    // Positions from the cloud, unless the exact binary copy is there
    if (!readField(cloud, "x", x))
    {
        label i = 0;
        for (const passiveParticle& p : cloud)
        {
            x[i++] = p.position();
        }
    }

    auto required = [&](const word& name, auto& values)
    {
        if (!readField(cloud, name, values))
        {
            FatalErrorInFunction
                << "The material points in " << mesh.time().path()/timeName
                << "/lagrangian/" << cloudName << " have no field " << name
                << ": write them with setMaterialPoints or mpmLbmFoam"
                << exit(FatalError);
        }
    };
    required("U", v);
    required("mass", m);
    required("volume", V);
    required("initialVolume", V0);
    required("stress", sigma);
    required("plasticStrain", plasticStrain);
    required("material", material);
    required("halfLength", halfLength);
    required("porosity", porosity);
    if (!readField(cloud, "F", F))
    {
        F = tensor::I;
    }
    if (!readField(cloud, "C", C))
    {
        C = Zero;
    }
    return true;
}


void Foam::materialPoints::write
(
    const fvMesh& mesh,
    const latticeMesh& lattice
) const
{
    passiveParticleCloud cloud(mesh, cloudName, IDLList<passiveParticle>());

    // Attach each point to its cell through the lattice (no search)
    const scalar dx = lattice.dx();
    const vector& origin = lattice.origin();
    const labelVector& bs = lattice.boxStart();
    const labelList& nodeCell = lattice.nodeCell();
    forAll(x, i)
    {
        labelVector b;
        for (direction d = 0; d < 3; ++d)
        {
            b[d] = (d == 2 && lattice.twoD())
                 ? 0
                 : label(std::floor((x[i][d] - origin[d])/dx)) - bs[d];
        }
        const label celli = nodeCell[lattice.node(b.x(), b.y(), b.z())];
        cloud.addParticle(new passiveParticle(mesh, x[i], celli));
    }
    cloud.write();

    // All in binary, whatever the case's format: a restart continues
    // exactly, and ParaView reads binary fields as well
    writeField(cloud, "x", x, true);
    writeField(cloud, "U", v, true);
    writeField(cloud, "mass", m, true);
    writeField(cloud, "volume", V, true);
    writeField(cloud, "initialVolume", V0, true);
    writeField(cloud, "stress", sigma, true);
    writeField(cloud, "plasticStrain", plasticStrain, true);
    writeField(cloud, "material", material, true);
    writeField(cloud, "halfLength", halfLength, true);
    writeField(cloud, "porosity", porosity, true);
    writeField(cloud, "F", F, true);
    writeField(cloud, "C", C, true);
    scalarList pressure(size());
    forAll(pressure, i)
    {
        pressure[i] = -tr(sigma[i])/3.0;
    }
    writeField(cloud, "pressure", pressure, true);
}


// ************************************************************************* //
