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


// ************************************************************************* //
