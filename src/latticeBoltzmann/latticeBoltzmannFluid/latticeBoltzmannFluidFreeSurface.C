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

// The free surface: its start (or restart) and its forces

#include "latticeBoltzmannFluid.H"
#include "nodeFieldIO.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeBoltzmannFluid::enableFreeSurface
(
    const scalar gasPressure,
    const scalar fillMargin,
    const scalar surfaceTension,
    const scalarField& alpha,
    const label excessMassTo
)
{
    // (the storage the free surface reads: a porous zone's, or the
    // lattice's porosity, kept by setPorosity; empty: clear water)
    if (storageFollowsPorosity_)
    {
        storage_ = porosity_;
    }
    freeSurface_.reset
    (
        new lbmFreeSurface
        (
            lattice_, velocitySet_(), units_, obstacles_(), porosity_,
            storage_,
            gasPressure, fillMargin, surfaceTension, excessMassTo
        )
    );
    // (where the populations are: read through the fluid's layout)
    freeSurface_->setLayout(layout_);
    momentumStale_ = true;
    // (a pressure patch's value at or below the gas's is air outside)
    boundaries_->setGasPressure(gasPressure, p_, units_);
    scalarList& f = current();
    if (restarted_)
    {
        // (the fill levels are optional: recomputed from the masses where
        // a time was written without them)
        for (const word& name : freeSurface_->stateFiles())
        {
            if (name != "lbmFreeSurfaceFill" && !foundNodeField(lattice_, name))
            {
                FatalErrorInFunction
                    << "The populations of time " << mesh_.time().timeName()
                    << " were written without the free surface: "
                    << mesh_.time().timePath()/name << " is missing." << nl
                    << "    Restart a free-surface run from a time it wrote,"
                    << " or remove the lbmF* files to start from U, p and"
                    << " alpha.water" << exit(FatalError);
            }
        }
        freeSurface_->readState(f.data());
        if (foundNodeField(lattice_, "lbmDragX"))
        {
            // (applied at the first step: the drag's effect may be built
            // after this one and clear it)
            const label nBox = lattice_.nBox();
            writtenDrag_.setSize(3*nBox, 0.0);
            readNodeField(lattice_, "lbmDragX", writtenDrag_.data());
            readNodeField(lattice_, "lbmDragY", writtenDrag_.data() + nBox);
            readNodeField(lattice_, "lbmDragZ", writtenDrag_.data() + 2*nBox);
        }
    }
    else
    {
        freeSurface_->setFromFraction(alpha, f.data());
    }
    mass0_ = returnReduce(freeSurface_->mass(f.cdata()), sumOp<scalar>());
}


void Foam::latticeBoltzmannFluid::setFreeSurfaceStaticForce
(
    const List<vector>* X
)
{
    if (freeSurface_)
    {
        freeSurface_->setStaticForce(X);
    }
}


void Foam::latticeBoltzmannFluid::setFreeSurfaceForces()
{
    if (Fx_.empty())
    {
        freeSurface_->setForces(nullptr);
        return;
    }
    const scalar* forces[6] =
    {
        Fx_.cdata(), Fy_.cdata(), Fz_.cdata(),
        dragX_.cdata(), dragY_.cdata(), dragZ_.cdata()
    };
    freeSurface_->setForces(forces, relaxK_.cdata());
}


void Foam::latticeBoltzmannFluid::updateInterface()
{
    if (!freeSurface_)
    {
        return;
    }
    scalarList& f = current();
    momentumStale_ = true;
    setFreeSurfaceForces();
    freeSurface_->convert
    (
        f.data(),
        latticeAcceleration()
    );
}


// ************************************************************************* //
