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

// The lattice's restart state and its balance: the populations and the
// totals since the case's start written at write times and read back, and
// the balance's global totals.

#include "latticeAdvectionDiffusion.H"
#include "nodeFieldIO.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::latticeAdvectionDiffusion::writtenPopulations() const
{
    // (any processor's: one that lacks them is refused at reading, rather
    // than the processors taking different paths)
    return returnReduce
    (
        foundNodeField(lattice_, C_.name() + "G0"),
        orOp<bool>()
    );
}


bool Foam::latticeAdvectionDiffusion::restartsBalance() const
{
    return
        !ignoreWrittenBalance_
     && writtenPopulations()
     && returnReduce(isFile(balanceFile()), orOp<bool>());
}


Foam::fileName Foam::latticeAdvectionDiffusion::balanceFile() const
{
    return lattice_.mesh().time().timePath()/"uniform"/(C_.name() + "Balance");
}


void Foam::latticeAdvectionDiffusion::readBalance()
{
    // The balance's totals since the case's start, written beside the
    // populations, so that a restart's balance goes on where the written
    // run's stood (its content at the start, what entered and left since).
    // The totals are global, the same in every processor's file; a
    // processor without uniform/ (v1912's decomposePar may not copy it)
    // takes them from the lowest one that has it. Without any (a time
    // written before the file existed) the balance starts at this time
    const fileName file(balanceFile());
    label owner = isFile(file) ? Pstream::myProcNo() : labelMax;
    reduce(owner, minOp<label>());
    if (owner == labelMax || ignoreWrittenBalance_)
    {
        Info<< "    " << (ignoreWrittenBalance_ ? "Not reading " : "No ")
            << file.name() << " of time "
            << lattice_.mesh().time().timeName() << ": the balance of "
            << C_.name() << " counts from this time" << endl;
        return;
    }

    scalar content0 = 0, sourced = 0, deposited = 0, stranded = 0;
    scalarList out(patchOutflow_.size(), Zero);
    if (Pstream::myProcNo() == owner)
    {
        IFstream is(file);
        const dictionary state(is);
        content0 = state.get<scalar>("content0");
        sourced = state.get<scalar>("sourced");
        deposited = state.get<scalar>("deposited");
        stranded = state.get<scalar>("stranded");
        out = state.get<scalarList>("patchOutflow");
        if (out.size() != patchOutflow_.size())
        {
            FatalIOErrorInFunction(state)
                << "patchOutflow has " << out.size() << " entries: one per"
                << " patch of the mesh (" << patchOutflow_.size() << ", the"
                << " processor patches aside) is allowed. Remove " << file
                << " to count the balance from this time"
                << " (with erosion, its totals then count from this time"
                << " too)" << exit(FatalIOError);
        }
        bool finite =
            std::isfinite(content0) && std::isfinite(sourced)
         && std::isfinite(deposited) && std::isfinite(stranded);
        for (const scalar v : out)
        {
            finite = finite && std::isfinite(v);
        }
        if (!finite)
        {
            FatalIOErrorInFunction(state)
                << "content0 " << content0 << ", sourced " << sourced
                << ", deposited " << deposited << ", patchOutflow " << out
                << ", stranded " << stranded << ": finite numbers are"
                << " allowed. Remove " << file << " to count the balance"
                << " from this time (with erosion, its totals then count"
                << " from this time too)" << exit(FatalIOError);
        }
    }
    // (exact: every processor but the owner adds zeros)
    reduce(content0, sumOp<scalar>());
    reduce(sourced, sumOp<scalar>());
    reduce(deposited, sumOp<scalar>());
    reduce(stranded, sumOp<scalar>());
    Pstream::listCombineGather(out, plusEqOp<scalar>());
    Pstream::listCombineScatter(out);

    // The running totals are per processor, summed when asked for: each
    // continues its own where the time was written on this decomposition,
    // else the master carries what came before
    content0_ = content0;
    bool own = false;
    dictionary here;
    if (isFile(file))
    {
        IFstream is(file);
        const dictionary state(is);
        // (the processor's own file: one copied to every processor, as
        // decomposePar copies a reconstructed case's uniform/, is not)
        own =
            state.getOrDefault<label>("nProcessors", -1) == Pstream::nProcs()
         && state.found("here")
         && state.subDict("here").getOrDefault<label>("processor", -1)
         == Pstream::myProcNo();
        if (own)
        {
            here = state.subDict("here");
            own = here.get<scalarList>("patchOutflow").size() == out.size();
        }
    }
    if (returnReduce(own, andOp<bool>()))
    {
        sourced_ = here.get<scalar>("sourced");
        deposited_ = here.get<scalar>("deposited");
        stranded_ = here.get<scalar>("stranded");
        patchOutflow_ = here.get<scalarList>("patchOutflow");
    }
    else if (Pstream::master())
    {
        sourced_ = sourced;
        deposited_ = deposited;
        stranded_ = stranded;
        patchOutflow_ = out;
    }
    else
    {
        sourced_ = 0;
        deposited_ = 0;
        stranded_ = 0;
        patchOutflow_ = Zero;
    }
    Info<< "    The balance of " << C_.name() << " continues from "
        << file.name() << ": content at the start " << content0_
        << ", added since " << sourced << ", out since " << sum(out)
        << endl;
}


Foam::scalar Foam::latticeAdvectionDiffusion::sourced() const
{
    return returnReduce(sourced_, sumOp<scalar>());
}


Foam::scalarList Foam::latticeAdvectionDiffusion::patchOutflow() const
{
    scalarList out(patchOutflow_);
    Pstream::listCombineGather(out, plusEqOp<scalar>());
    Pstream::listCombineScatter(out);
    return out;
}


Foam::scalar Foam::latticeAdvectionDiffusion::deposited() const
{
    return returnReduce(deposited_, sumOp<scalar>());
}


Foam::scalar Foam::latticeAdvectionDiffusion::balanceDefect() const
{
    const scalar now = content();
    const scalar added = sourced();
    const scalar out = sum(patchOutflow()) + deposited();
    const scalar scale =
        max(max(mag(now), mag(content0_)), max(mag(added), mag(out)));
    return scale > 0 ? (now - (content0_ + added - out))/scale : 0;
}


void Foam::latticeAdvectionDiffusion::writePopulations() const
{
    if (!initialised_)
    {
        return;
    }
    const label nBox = lattice_.nBox();
    const scalarList& g = current();
    // (outside the water 0: the gas's slots hold the bounce-back of the
    // last step, which nothing reads)
    scalarList gq(surface_ || bodies_ ? nBox : 0, Zero);
    for (label q = 0; q < Q_; ++q)
    {
        const scalar* data = g.cdata() + q*nBox;
        if (gq.size())
        {
            for (const label n : lattice_.cellNode())
            {
                gq[n] = water(n) ? data[n] : 0;
            }
            data = gq.cdata();
        }
        writeNodeField(lattice_, C_.name() + "G" + Foam::name(q), data);
    }

    // The balance's totals (global: the reductions on every processor)
    const scalar sourcedAll = sourced();
    const scalar depositedAll = deposited();
    const scalar strandedAll = returnReduce(stranded_, sumOp<scalar>());
    const scalarList outAll(patchOutflow());
    const fileName file(balanceFile());
    mkDir(file.path());
    OFstream os(file);
    os.precision(17);
    os  << "// The balance of " << C_.name() << " since the case's start,"
        << " for a restart [" << C_.name() << " x m3]" << nl
        << "content0 " << content0_ << ";" << nl
        << "sourced " << sourcedAll << ";" << nl
        << "deposited " << depositedAll << ";" << nl
        << "stranded " << strandedAll << ";" << nl
        << "patchOutflow " << outAll << ";" << nl
        // (this processor's own running totals, which a restart on the
        // same decomposition continues, so that its sums repeat the
        // uninterrupted run's to the last bit: from the global ones, the
        // sums' order differs, 5e-16)
        << "nProcessors " << Pstream::nProcs() << ";" << nl
        << "here { processor " << Pstream::myProcNo() << "; sourced "
        << sourced_ << "; deposited " << deposited_
        << "; stranded " << stranded_ << "; patchOutflow " << patchOutflow_
        << "; }" << nl;
    os.flush();
    if (!os.good())
    {
        FatalErrorInFunction
            << "Could not write " << os.name() << exit(FatalError);
    }
}


Foam::wordList Foam::latticeAdvectionDiffusion::populationFiles() const
{
    wordList names(initialised_ ? Q_ + 1 : 0);
    for (label q = 0; q < Q_ && initialised_; ++q)
    {
        names[q] = C_.name() + "G" + Foam::name(q);
    }
    if (initialised_)
    {
        names[Q_] = "uniform/" + balanceFile().name();
    }
    return names;
}


// ************************************************************************* //
