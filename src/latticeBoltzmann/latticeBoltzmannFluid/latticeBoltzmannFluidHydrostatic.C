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
// p_rgh = p - rho_0 g_h.(x - x_top) and no weight but g - g_h (g_h the part
// of g across the directions that are not periodic)

#include "latticeBoltzmannFluid.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeBoltzmannFluid::updateLatticeAcceleration()
{
    latticeAcceleration_ = units_.accelerationToLattice
    (
        hydrostatic_.size()
      ? vector(bodyAcceleration_ - hydrostaticAcceleration())
      : bodyAcceleration_
    );
}


bool Foam::latticeBoltzmannFluid::canUseAnalyticHydrostatic() const
{
    for (direction j = 0; j < 3; ++j)
    {
        if (lattice_.periodic()[j] && bodyAcceleration_[j] != 0)
        {
            return false;
        }
    }
    return true;
}


void Foam::latticeBoltzmannFluid::useAnalyticHydrostatic()
{
    if (hydrostatic_.size())
    {
        return;
    }
    if (nSteps_ > 0)
    {
        FatalErrorInFunction
            << "the hydrostatic pressure leaves the lattice before the first"
            << " step" << abort(FatalError);
    }

    // x_top: the mesh's corner highest against g (the pressure is zero
    // there; a tank full to its top at rest then carries p_rgh = 0)
    // (along periodic directions the weight stays on the lattice)
    const vector g(hydrostaticAcceleration());
    const boundBox& bb = mesh_.bounds();
    for (direction j = 0; j < 3; ++j)
    {
        hydrostaticRef_[j] = g[j] < 0 ? bb.max()[j] : bb.min()[j];
    }
    hydrostaticGradient_ = units_.rho0()*g;

    const vectorField& C = mesh_.C();
    const labelList& cellNode = lattice_.cellNode();
    if (freeSurface_ && mag(g) > 0)
    {
        // With a free surface the reference is the highest water's level
        // (its nodes' centres), not the mesh's top: p_rgh is then about the
        // gas pressure at the surface and the water's lattice density near
        // 1 (from the mesh's top, a reservoir far below it would hold
        // rho_0 g (x_top - x_s) less everywhere, and every force would
        // accelerate it more by the ratio). A restart keeps the level its
        // populations were written with: the reference is the mesh's
        // corner moved along g (checkWrittenHydrostatic compares the
        // written one with it across g, and its level within the mesh).
        const vector up(-g/mag(g));
        if (restarted_ && writtenHydrostatic_ == "analytic")
        {
            const point& w = writtenHydrostaticRef_;
            const vector across =
                (w - hydrostaticRef_) - ((w - hydrostaticRef_) & up)*up;
            const scalar level = up & w;
            if
            (
                mag(across) <= 1e-9*max(mag(hydrostaticRef_), lattice_.dx())
             && level <= (up & hydrostaticRef_) + 1e-9*lattice_.dx()
             && level >= (up & hydrostaticRef_) - mag(bb.span())
            )
            {
                hydrostaticRef_ = w;
            }
            // (otherwise the mesh moved: checkWrittenHydrostatic stops)
        }
        else
        {
            scalar level = -GREAT;
            forAll(cellNode, celli)
            {
                const label n = cellNode[celli];
                if (freeSurface_->liquid(n) || freeSurface_->interface(n))
                {
                    level = max(level, up & C[celli]);
                }
            }
            reduce(level, maxOp<scalar>());
            if (level > -GREAT)
            {
                hydrostaticRef_ -= ((up & hydrostaticRef_) - level)*up;
            }
        }
    }
    hydrostatic_.setSize(lattice_.nBox(), 0.0);
    updateLatticeAcceleration();
    forAll(cellNode, celli)
    {
        hydrostatic_[cellNode[celli]] =
            hydrostaticGradient_ & (C[celli] - hydrostaticRef_);
    }
    // (with no weight at all, p_h = 0: the lattice carries p as before,
    // the mode recorded for a restart)
    boundaries_->setHydrostatic
    (
        hydrostaticGradient_, hydrostaticRef_, p_, units_
    );
    if (freeSurface_)
    {
        freeSurface_->setHydrostatic(hydrostatic_, g);
    }

    if (!restarted_)
    {
        // A run from U and p: its populations (at the equilibrium of the
        // pore pressure p and the superficial velocity U, setPorosity) now
        // hold p - p_h: the lattice density falls by n (rho(p_h) - 1)
        momentumStale_ = true;
        scalar mass = 0;
        for (const label n : cellNode)
        {
            if (obstacles_->solid(n) || (freeSurface_ && freeSurface_->gas(n)))
            {
                // (the gas's populations are never streamed into water)
                continue;
            }
            const scalar eps = porosity_.size() ? porosity_[n] : 1.0;
            const scalar rho = setEquilibrium
            (
                n, eps, -eps*(units_.rhoLattice(hydrostatic_[n]) - 1), 1
            );
            if (!(rho > 0))
            {
                const label celli = lattice_.nodeCell()[n];
                FatalErrorInFunction
                    << "The water's initial pressure less the hydrostatic "
                    << units_.rho0() << " g.(x - " << hydrostaticRef_ << "),"
                    << " which the lattice carries (buoyancy's hydrostatic"
                    << " analytic), is " << units_.pressure(1 + (rho - 1)/eps)
                    << " Pa at cell " << celli << " (" << C[celli] << "):"
                    << " beyond what the lattice can hold (-rho c_s^2 = "
                    << -units_.rho0()*sqr(units_.soundSpeed()) << " Pa)." << nl
                    << "    Start the water from the hydrostatic pressure in"
                    << " 0/p (setExprFields with p = rho g (h - y), as the"
                    << " tutorials do), or smaller deltaT (a faster lattice"
                    << " sound speed)"
                    << (
                           freeSurface_
                         ? "; with a free surface, water far below the"
                           " highest level holds p_rgh = -rho g times that"
                           " depth: keep the pressure on the lattice,"
                           " buoyancyCoeffs { hydrostatic lattice; } (the"
                           " default with a free surface)"
                         : ""
                       )
                    << exit(FatalError);
            }
            mass += rho;
        }
        // (as massDefect sums it: with a free surface, the interface
        // nodes keep their fill levels and their masses follow their new
        // densities)
        scalar mass0 = mass - displacedMass_;
        if (freeSurface_)
        {
            freeSurface_->resetMasses(current().cdata());
            mass0 = freeSurface_->mass(current().cdata());
        }
        mass0_ = returnReduce(mass0, sumOp<scalar>());
        updateFields();
    }

    Info<< "The water's hydrostatic pressure " << units_.rho0() << " g.(x - "
        << hydrostaticRef_ << "), g = " << g << ", is off the lattice: it"
        << " carries p_rgh and ";
    if (mag(bodyAcceleration_ - g) > 0)
    {
        Info<< "the weight along the periodic directions, "
            << (bodyAcceleration_ - g) << " m/s2 (it drives the flow)";
    }
    else
    {
        Info<< "no weight";
    }
    Info<< nl << endl;
}


void Foam::latticeBoltzmannFluid::checkWrittenHydrostatic() const
{
    const word mode(hydrostatic_.size() ? "analytic" : "lattice");
    const fileName& file = writtenHydrostaticFile_;
    if (writtenHydrostatic_ != mode)
    {
        FatalErrorInFunction
            << "The water's populations in " << file.path().path()
            << " were written with the hydrostatic pressure "
            << (
                   writtenHydrostatic_ == "analytic"
                 ? "off the lattice (buoyancy's hydrostatic analytic: they"
                   " hold p_rgh)"
                 : "on the lattice"
               )
            << " (" << file
            << (isFile(file) ? "" : ": none, as before that mode") << ");"
            << " this run carries it "
            << (mode == "analytic" ? "off the lattice" : "on the lattice")
            << "." << nl
            << "    Continue that run with the effects and buoyancyCoeffs"
            << " { hydrostatic " << writtenHydrostatic_ << "; } it had, or"
            << " start from 0" << exit(FatalError);
    }
    if
    (
        mode == "analytic"
     && (
            mag(writtenHydrostaticGradient_ - hydrostaticGradient_)
          > 1e-12*mag(hydrostaticGradient_)
         || mag(writtenHydrostaticRef_ - hydrostaticRef_)
          > 1e-9*max(mag(hydrostaticRef_), lattice_.dx())
        )
    )
    {
        FatalErrorInFunction
            << "The water's populations in " << file.path().path()
            << " hold p_rgh = p - " << writtenHydrostaticGradient_ << ".(x - "
            << writtenHydrostaticRef_ << ") (" << file << "); this run's"
            << " hydrostatic pressure is " << hydrostaticGradient_ << ".(x - "
            << hydrostaticRef_ << "): constant/g, rho or the mesh changed"
            << " since." << nl
            << "    Restart with the g, rho and mesh of that run, or start"
            << " from 0" << exit(FatalError);
    }
}


void Foam::latticeBoltzmannFluid::writeHydrostaticState() const
{
    const fileName dir(mesh_.time().timePath()/"uniform");
    mkDir(dir);
    OFstream os(dir/"lbmHydrostatic");
    os.precision(17);
    os  << "hydrostatic " << (hydrostatic_.size() ? "analytic" : "lattice")
        << ";" << nl
        << "gradient " << hydrostaticGradient_ << ";" << nl
        << "reference " << hydrostaticRef_ << ";" << nl
        // (the step the populations' lattice units were made with: a
        // restart with another is refused)
        << "deltaT " << units_.dt() << ";" << nl;
    os.flush();
    if (!os.good())
    {
        FatalErrorInFunction
            << "Could not write " << os.name() << exit(FatalError);
    }
}


// ************************************************************************* //
