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

// The water's hydrostatic pressure off the lattice: the lattice carries
// p_rgh = p - rho_0 g.(x - x_top) and no weight

#include "latticeBoltzmannFluid.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeBoltzmannFluid::useAnalyticHydrostatic()
{
    if (hydrostatic_.size())
    {
        return;
    }
    if (freeSurface_)
    {
        FatalErrorInFunction
            << "the hydrostatic pressure cannot leave the lattice with a"
            << " free surface (its gas pressure is set on the lattice)"
            << abort(FatalError);
    }
    if (nSteps_ > 0)
    {
        FatalErrorInFunction
            << "the hydrostatic pressure leaves the lattice before the first"
            << " step" << abort(FatalError);
    }

    // x_top: the mesh's corner highest against g (the pressure is zero
    // there; a tank full to its top at rest then carries p_rgh = 0)
    const vector g(bodyAcceleration_);
    const boundBox& bb = mesh_.bounds();
    for (direction j = 0; j < 3; ++j)
    {
        hydrostaticRef_[j] = g[j] < 0 ? bb.max()[j] : bb.min()[j];
    }
    hydrostaticGradient_ = units_.rho0()*g;

    const vectorField& C = mesh_.C();
    const labelList& cellNode = lattice_.cellNode();
    hydrostatic_.setSize(lattice_.nBox(), 0.0);
    forAll(cellNode, celli)
    {
        hydrostatic_[cellNode[celli]] =
            hydrostaticGradient_ & (C[celli] - hydrostaticRef_);
    }
    boundaries_->setHydrostatic
    (
        hydrostaticGradient_, hydrostaticRef_, p_, units_
    );

    if (!restarted_)
    {
        // A run from U and p: its populations (at the equilibrium of the
        // pore pressure p and the superficial velocity U, setPorosity) now
        // hold p - p_h: the lattice density falls by n (rho(p_h) - 1)
        const label Q = velocitySet_->Q();
        const List<labelVector>& c = velocitySet_->c();
        const scalarList& w = velocitySet_->w();
        scalarList& f = current();
        momentumStale_ = true;
        scalar mass = 0;
        for (const label n : cellNode)
        {
            if (obstacles_->solid(n))
            {
                continue;
            }
            scalar rho = 0;
            vector j(Zero);
            for (label q = 0; q < Q; ++q)
            {
                rho += f[layout_.at(q, n)];
                j += f[layout_.at(q, n)]*vector(c[q]);
            }
            const scalar eps = porosity_.size() ? porosity_[n] : 1.0;
            const scalar rhoNew =
                rho - eps*(units_.rhoLattice(hydrostatic_[n]) - 1);
            const vector u = j/rho;
            for (label q = 0; q < Q; ++q)
            {
                const scalar cu = vector(c[q]) & u;
                f[layout_.at(q, n)] =
                    w[q]*rhoNew*(1 + 3*cu + (4.5*cu*cu - 1.5*magSqr(u))/eps);
            }
            mass += rhoNew;
        }
        mass0_ = returnReduce(mass - displacedMass_, sumOp<scalar>());
        updateFields();
    }

    Info<< "The water's hydrostatic pressure " << units_.rho0() << " g.(x - "
        << hydrostaticRef_ << ") is off the lattice: it carries p_rgh and no"
        << " weight" << nl << endl;
}


// ************************************************************************* //
