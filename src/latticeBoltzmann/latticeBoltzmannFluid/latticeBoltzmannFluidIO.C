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

#include "latticeBoltzmannFluid.H"
#include "IFstream.H"
#include "OFstream.H"
#include "nodeFieldIO.H"
#include "selectEntry.H"
#include "caseChecks.H"
#include "lbmKernel.H"
#include "vector2D.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeBoltzmannFluid::initialise()
{
    const Time& runTime = mesh_.time();
    const label Q = velocitySet_->Q();
    const label nBox = lattice_.nBox();
    const labelList& cellNode = lattice_.cellNode();

    // (in place: a pad around each direction's slots, lbmLayout.H)
    label pad = 0;
    if (inPlace_)
    {
        for (const label o : offset_)
        {
            pad = max(pad, mag(o));
        }
    }
    layout_ = lbmLayout
    (
        lbmLayout::NATURAL, nBox, velocitySet_->opp(), offset_, pad
    );
    fA_.setSize(layout_.size(), 0.0);
    if (!inPlace_)
    {
        fB_.setSize(layout_.size(), 0.0);
    }
    AisCurrent_ = true;

    auto popIO = [&](const label q, IOobject::readOption r)
    {
        return IOobject
        (
            "lbmF" + Foam::name(q),
            runTime.timeName(),
            mesh_,
            r,
            IOobject::NO_WRITE,
            false
        );
    };

    const bool hasFirst =
        popIO(0, IOobject::MUST_READ).typeHeaderOk<volScalarField>(true);

    restarted_ = hasFirst;
    if (hasFirst)
    {
        if
        (
            !popIO(Q - 1, IOobject::MUST_READ)
                .typeHeaderOk<volScalarField>(true)
         || popIO(Q, IOobject::MUST_READ).typeHeaderOk<volScalarField>(true)
        )
        {
            FatalIOErrorInFunction(dict_)
                << "The populations in " << runTime.timePath() << " were not"
                << " written with velocitySet " << velocitySet_->type()
                << " (" << Q << " files lbmF0..lbmF" << Q - 1 << " expected)."
                << nl << "    Restart with the velocity set of that run, or"
                << " remove the lbmF* files to start from U and p at"
                << " equilibrium." << exit(FatalIOError);
        }

        Info<< "Reading populations lbmF0..lbmF" << Q - 1 << " from time "
            << runTime.timeName() << nl << endl;
        scalarList& f = current();
        for (label q = 0; q < Q; ++q)
        {
            readNodeField
            (
                lattice_, "lbmF" + Foam::name(q), f.data() + layout_.base(q)
            );
        }

        // How the populations carry the hydrostatic pressure (checked at
        // the first step, when every effect has said how this run does).
        // Without the file: written before the analytic mode, the lattice
        // mode. A processor that lacks uniform/ (decomposePar in v1912 may
        // not link it) takes the others'; water without weight (a zero
        // gradient) carries none, the lattice mode
        writtenHydrostaticFile_ =
            runTime.timePath()/"uniform"/"lbmHydrostatic";
        label mode = -1;   // -1 no file, 0 lattice, 1 analytic
        if (isFile(writtenHydrostaticFile_))
        {
            IFstream is(writtenHydrostaticFile_);
            const dictionary state(is);
            const word written(state.get<word>("hydrostatic"));
            if (written != "analytic" && written != "lattice")
            {
                FatalIOErrorInFunction(state)
                    << "hydrostatic " << written << " is not allowed: the"
                    << " populations carry it analytic or lattice"
                    << exit(FatalIOError);
            }
            // The step: the populations hold velocities in dx/dt and
            // pressures in rho (dx/dt)^2/3, read with another step they
            // are another flow (a restart at half the step: the pressure
            // four times, the water thrown about at once)
            scalar writtenDt = 0;
            if
            (
                state.readIfPresent("deltaT", writtenDt)
             && mag(writtenDt - units_.dt()) > 1e-9*units_.dt()
            )
            {
                FatalIOErrorInFunction(state)
                    << "The water's populations in " << runTime.timePath()
                    << " were made with deltaT " << writtenDt << " s;"
                    << " system/controlDict has deltaT " << units_.dt()
                    << " s. The populations hold the water's velocity in"
                    << " units of dx/deltaT and its pressure in rho"
                    << " (dx/deltaT)^2/3: read with another step they are"
                    << " another flow." << nl << "    Continue with deltaT "
                    << writtenDt << ", or start from 0 with the new step"
                    << exit(FatalIOError);
            }
            writtenHydrostaticGradient_ = state.get<vector>("gradient");
            writtenHydrostaticRef_ = state.get<point>("reference");
            mode =
                (written == "analytic" && mag(writtenHydrostaticGradient_) > 0)
              ? 1 : 0;
        }
        const label anyMode = returnReduce(mode, maxOp<label>());
        if (mode >= 0 && mode != anyMode)
        {
            FatalErrorInFunction
                << "The processors' " << writtenHydrostaticFile_.name()
                << " files of time " << runTime.timeName() << " disagree on"
                << " how the populations carry the hydrostatic pressure"
                << exit(FatalError);
        }
        writtenHydrostatic_ = anyMode == 1 ? "analytic" : "lattice";
        if (anyMode == 1)
        {
            // The gradient and reference of the processors that have them
            // (the same on each): the largest of each component
            vector gMax(writtenHydrostaticGradient_), gMin(gMax);
            point rMax(writtenHydrostaticRef_), rMin(rMax);
            if (mode < 0)
            {
                gMax = rMax = vector::uniform(-GREAT);
                gMin = rMin = vector::uniform(GREAT);
            }
            reduce(gMax, maxOp<vector>());
            reduce(gMin, minOp<vector>());
            reduce(rMax, maxOp<point>());
            reduce(rMin, minOp<point>());
            writtenHydrostaticGradient_ = gMax;
            writtenHydrostaticRef_ = rMax;
            if (gMax != gMin || rMax != rMin)
            {
                FatalErrorInFunction
                    << "The processors' " << writtenHydrostaticFile_.name()
                    << " files of time " << runTime.timeName() << " disagree"
                    << " on the hydrostatic pressure's gradient or reference"
                    << exit(FatalError);
            }
        }

        // Porous flow: the porosity the populations were made with
        if (foundNodeField(lattice_, "lbmPorosity"))
        {
            writtenPorosity_.setSize(nBox, 1.0);
            readNodeField(lattice_, "lbmPorosity", writtenPorosity_.data());
        }

        // Outlets that let waves leave: their boundary pressures
        if (boundaries_->hasAbsorbing())
        {
            const fileName file
            (
                runTime.timePath()/"uniform"/outletStateFile
            );
            if (isFile(file))
            {
                IFstream is(file);
                const dictionary state(is);
                const scalarList rho(state.get<scalarList>("rho"));
                if (rho.size() != boundaries_->absorbingState().size())
                {
                    FatalIOErrorInFunction(state)
                        << "rho in " << file << " has " << rho.size()
                        << " values, the outlets' links here "
                        << boundaries_->absorbingState().size() << ": it was"
                        << " written with another mesh or decomposition."
                        << nl << "    Remove it to start the outlets from"
                        << " their patch values of p" << exit(FatalIOError);
                }
                boundaries_->setAbsorbingState(rho);
            }
        }
    }
    else
    {
        Info<< "Initialising populations at equilibrium from U and p"
            << nl << endl;
        scalarList& f = current();
        const List<labelVector>& c = velocitySet_->c();
        const scalarList& w = velocitySet_->w();
        forAll(cellNode, celli)
        {
            const scalar rho = units_.rhoLattice(p_[celli]);
            const vector u = units_.toLattice(U_[celli]);
            for (label q = 0; q < Q; ++q)
            {
                const scalar cu = vector(c[q]) & u;
                f[layout_.at(q, cellNode[celli])] =
                    w[q]*rho*(1 + 3*cu + 4.5*cu*cu - 1.5*magSqr(u));
            }
        }
    }

    // Initial mass
    const scalarList& f = current();
    scalar mass = 0;
    for (const label n : cellNode)
    {
        if (obstacles_->solid(n))
        {
            continue;
        }
        for (label q = 0; q < Q; ++q)
        {
            mass += f[layout_.at(q, n)];
        }
    }
    mass0_ = returnReduce(mass, sumOp<scalar>());
}


// ************************************************************************* //
