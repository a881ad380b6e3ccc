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

Description
    The water's checks: the velocity set against the mesh, tau and the
    lattice's units at start-up, and the instability's message

\*---------------------------------------------------------------------------*/

#include "latticeBoltzmannFluid.H"
#include "lbmFreeSurface.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::latticeBoltzmannFluid::checkVelocitySet() const
{
    const label D = velocitySet_->D();
    if (D != lattice_.nDim())
    {
        FatalIOErrorInFunction(dict_)
            << "velocitySet " << velocitySet_->type() << " is " << D
            << "D but the mesh is " << lattice_.nDim() << "D." << nl
            << "    Allowed: "
            << (lattice_.twoD() ? "D2Q9 (the mesh is one cell thick in z"
                " with empty patches)" : "D3Q19 or D3Q27")
            << exit(FatalIOError);
    }
}


void Foam::latticeBoltzmannFluid::checkUnits() const
{
    const scalar tauMinusHalf = units_.tau() - 0.5;
    if (!(tauMinusHalf > 0))
    {
        FatalIOErrorInFunction(dict_)
            << "The relaxation time tau = " << units_.tau()
            << " is not above 1/2 (lattice viscosity "
            << units_.nuLattice() << "): the lattice Boltzmann method needs"
            << " a positive viscosity." << exit(FatalIOError);
    }
    {
        // The method's expansion (Chapman-Enskog) needs the particles'
        // mean free path, about tau - 1/2 lattice spacings, well below the
        // flow's size: beyond the domain's smallest extent it models a
        // rarefied gas, not a liquid
        const labelVector& N = lattice_.globalN();
        label nMin = labelMax;
        for (direction d = 0; d < lattice_.nDim(); ++d)
        {
            nMin = min(nMin, N[d]);
        }
        if (tauMinusHalf > nMin)
        {
            FatalIOErrorInFunction(dict_)
                << "nu " << units_.nu() << " is not allowed with dx "
                << units_.dx() << " and deltaT " << units_.dt() << ": tau"
                << " - 1/2 = " << tauMinusHalf << " exceeds the domain's "
                << nMin << " cells across, so the lattice would model a"
                << " rarefied gas, not water." << nl
                << "    Check nu's units (m2/s), or use a smaller deltaT in"
                << " system/controlDict (tau - 1/2 = 3 nu deltaT/dx^2)."
                << exit(FatalIOError);
        }
    }
    if (tauMinusHalf < collision_->marginalTauMinusHalf())
    {
        // Advice the case does not follow yet
        string advice;
        const word model = collision_->type();
        if (model != "regularized" && model != "MRT")
        {
            advice += "collisionModel regularized or MRT, ";
        }
        advice += "a smaller dx, a larger deltaT (if the Mach number allows)";
        if (!(smagorinsky_ > 0))
        {
            advice += ", smagorinskyConstant 0.1";
        }
        WarningInFunction
            << "tau - 1/2 = " << tauMinusHalf << " is below "
            << collision_->marginalTauMinusHalf() << ", where collision model "
            << model << " is known to lose stability unless the"
            << " flow is well resolved." << nl
            << "    To stay stable: " << advice.c_str() << "."
            << (smagorinsky_ > 0 ? " (The Smagorinsky model the case uses"
                " raises the local tau where the flow shears.)" : "")
            << endl;
    }
}


bool Foam::latticeBoltzmannFluid::besidePressurePatch(const label n) const
{
    const labelList& nodes = boundaries_->pressureLinkNodes();
    const List<labelVector>& c = velocitySet_->c();
    const labelVector& stride = lattice_.stride();
    // (within two links: an instability fed by the patch's links shows
    // first where the flow through it carries the disturbance)
    forAll(c, q)
    {
        const label step =
            c[q].x()*stride.x() + c[q].y()*stride.y() + c[q].z()*stride.z();
        if (nodes.found(n + step) || nodes.found(n + 2*step))
        {
            return true;
        }
    }
    return false;
}


void Foam::latticeBoltzmannFluid::instability(const scalarList& f) const
{
    const label Q = velocitySet_->Q();
    const List<labelVector>& c = velocitySet_->c();
    const labelList& cellNode = lattice_.cellNode();
    const scalar maxU2 = sqr(machLimit_)*lattice::cs2;

    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        if (!water(n))
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
        const vector u = j/rho;
        const bool bad =
            !std::isfinite(rho) || !std::isfinite(magSqr(u))
         || !(rho > 0) || magSqr(u) > maxU2;
        if (!bad)
        {
            continue;
        }

        const word where =
            Pstream::parRun()
          ? word(" on processor " + Foam::name(Pstream::myProcNo()), false)
          : word::null;
        FatalErrorInFunction
            << "The lattice Boltzmann water became unstable at time "
            << mesh_.time().timeName() << " s (step " << nSteps_ << ")"
            << nl << "    cell " << celli << " at "
            << mesh_.cellCentres()[celli] << where.c_str()
            << nl << "    lattice density " << rho << ", lattice velocity "
            << u << ", Mach " << mag(u)/std::sqrt(lattice::cs2)
            << " (limit machLimit " << machLimit_ << ")" << nl;
        if (freeSurface_)
        {
            FatalError
                << "    free surface: " << freeSurface_->describe(n) << nl;
        }
        FatalError
            << "    tau = " << units_.tau() << ", collision model "
            << collision_->type() << nl
            << "    Nothing of this step was written. To stay stable:" << nl
            << "    - reduce deltaT in system/controlDict (lattice Mach ="
            << " U deltaT/dx sqrt(3))," << nl
            << "    - or refine the mesh, or raise nu in"
            << " constant/fluidProperties," << nl;
        // (the models the case does not use yet)
        const word model = collision_->type();
        string others;
        for (const word m : {"regularized", "MRT", "TRT"})
        {
            if (m != model)
            {
                others += (others.empty() ? "" : " or ") + m;
            }
        }
        FatalError
            << "    - or use collisionModel " << others.c_str()
            << (smagorinsky_ > 0 ? "." : ", or smagorinskyConstant 0.1.")
            << nl;
        if (porosity_.size())
        {
            // (the least porosity within a link: an instability at a
            // soil's face shows in the water beside it)
            scalar nMin = porosity_[n];
            forAll(c, q)
            {
                nMin = min
                (
                    nMin,
                    porosity_
                    [
                        n + lattice_.offset(c[q].x(), c[q].y(), c[q].z())
                    ]
                );
            }
            if (nMin < 1)
            {
                FatalError
                    << "    The node is in or beside porous soil (porosity "
                    << nMin << ")";
                if (!displacement_)
                {
                    FatalError
                        << ": where soil moves through the water, set"
                        << " displacement on in"
                        << " constant/porousFlowProperties (without it the"
                        << " water does not make way for the soil, nor fill"
                        << " the space it leaves: a block carried by a"
                        << " stream ran ahead of it and stopped this way)";
                }
                FatalError << "." << nl;
            }
        }
        const bool besidePatch = besidePressurePatch(n);
        if (!collision_->splitRelaxation() && besidePatch)
        {
            FatalError
                << "    The node is beside a pressure patch, whose links take"
                << " the non-equilibrium part of the nodes beside them: with "
                << model << " near tau = 1/2 a flow through the patch can grow"
                << " from it; TRT and MRT hold (regularized held to"
                << " tau - 1/2 = 0.0077 where BGK did not)." << nl;
        }
        if (freeSurface_ && besidePatch)
        {
            // (a probe: both floor patches of a reservoir and a tailwater
            // at the reservoir's pressure drove the tailwater's node to
            // 7.5 m/s, and the advice above did not name the cause)
            FatalError
                << "    The node is beside a pressure patch under a free"
                << " surface: if the patch's p in 0/p is not the hydrostatic"
                << " pressure of the water above it (rho g (level - y) plus"
                << " the gasPressure), the difference dp drives water through"
                << " the patch at up to sqrt(2 dp/rho); a water only a cell"
                << " or two deep over the patch is not stable either." << nl;
        }
        FatalError << exit(FatalError);
    }

    FatalErrorInFunction
        << "The lattice Boltzmann water became unstable at time "
        << mesh_.time().timeName() << " s: total mass is not finite"
        << exit(FatalError);
}


// ************************************************************************* //
