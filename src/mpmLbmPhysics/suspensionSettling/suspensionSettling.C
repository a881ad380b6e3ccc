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

#include "suspensionSettling.H"
#include "uniformDimensionedFields.H"
#include "dimensionSets.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// constant/g, which the settling needs whether or not gravity acts on the
// phases
vector gravityOf(const fvMesh& mesh, const dictionary& dict)
{
    IOobject io
    (
        "g",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<uniformDimensionedVectorField>(true))
    {
        FatalIOErrorInFunction(dict)
            << "settlingModel " << dict.get<word>("settlingModel")
            << " needs constant/g: grains settle along gravity"
            << exit(FatalIOError);
    }
    return uniformDimensionedVectorField(io).value();
}


dictionary modelDict
(
    const dictionary& dict,
    const scalar rhoFluid,
    const scalar nuFluid,
    const scalar g
)
{
    dictionary d(dict);
    d.set("rhoFluid", rhoFluid);
    d.set("nuFluid", nuFluid);
    d.set("g", g);
    return d;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::suspensionSettling::suspensionSettling
(
    const dictionary& dict,
    const scalar rhoFluid,
    const scalar nuFluid,
    const latticeAdvectionDiffusion& s
)
:
    model_(nullptr),
    down_(Zero),
    toLattice_(s.lattice().mesh().time().deltaTValue()/s.lattice().dx()),
    ws_(s.lattice().nBox(), Zero)
{
    const vector g = gravityOf(s.lattice().mesh(), dict);
    model_ = settlingModel::New(modelDict(dict, rhoFluid, nuFluid, mag(g)));
    down_ = g/mag(g);
    if (model_->hindered() && s.field().dimensions() != dimDensity)
    {
        FatalIOErrorInFunction(dict)
            << "settlingModel " << model_->type() << " hindered: the volume"
            << " fraction of grains C/rhoSolid needs " << s.field().name()
            << " in kg/m3 " << dimDensity << ", not "
            << s.field().dimensions() << " (or set hindered false in "
            << model_->type() << "Coeffs)" << exit(FatalIOError);
    }
    const scalar wLattice = model_->terminalVelocity()*toLattice_;
    if (!(wLattice*wLattice < 0.1))
    {
        FatalIOErrorInFunction(dict)
            << "settlingModel " << model_->type() << ": the terminal"
            << " velocity " << model_->terminalVelocity() << " m/s is "
            << wLattice << " in lattice units (dx/dt): the lattice carries"
            << " at most about 0.3. Use a smaller deltaT or a larger dx"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::suspensionSettling::update
(
    latticeAdvectionDiffusion& s,
    const scalarList* porosity,
    const scalarList* mixturePhi
)
{
    const settlingModel& m = *model_;
    const scalar rhoS = m.rhoSolid();
    for (const label n : s.lattice().cellNode())
    {
        // (Phi = n C phi_w: the suspension per volume of mixture, phi_w
        // the share of the pores that holds water, 1 without a free
        // surface; nothing settles outside the water)
        const scalar wet = s.wetFraction(n);
        const scalar eps = (porosity ? (*porosity)[n] : 1)*max(wet, SMALL);
        const scalar Phi = mixturePhi ? (*mixturePhi)[n] : s.Phi(n);
        const scalar phi = m.hindered() ? Phi/(eps*rhoS) : 0;
        ws_[n] = (m.velocity(phi)*toLattice_)*down_;
    }
    s.setSettling(&ws_);
}


// ************************************************************************* //
