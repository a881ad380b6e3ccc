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
    erosion: its restart state. The totals since erosion started and the
    surface's reference values in <time>/uniform/erosionState (global, and
    each processor's own running totals), the suspensions' populations and
    balances; read back at a restart (readState), written at every write
    time (write), listed for the restart manifest (stateFiles).

\*---------------------------------------------------------------------------*/

#include "erosionEffect.H"
#include "physicsScene.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::erosion::readState()
{
    // Each processor's file holds the global totals; a processor without
    // uniform/ (v1912's decomposePar may not copy it) takes them from the
    // lowest one that has it. A time without the file (erosion added at
    // this restart) starts the totals at zero
    const Time& runTime = scene_.mesh().time();
    const fileName file(runTime.timePath()/"uniform"/"erosionState");
    label owner = isFile(file) ? Pstream::myProcNo() : labelMax;
    reduce(owner, minOp<label>());
    if (owner == labelMax)
    {
        // (the suspensions' balances count from here with the totals)
        for (latticeAdvectionDiffusion& susp : suspensions_)
        {
            susp.ignoreWrittenBalance();
        }
        return;
    }

    // The totals and the suspensions' balances (content at the start, out
    // since) go together: where either was not written, both count from
    // this time
    bool suspensionsRestart = true;
    for (const latticeAdvectionDiffusion& susp : suspensions_)
    {
        suspensionsRestart = suspensionsRestart && susp.restartsBalance();
    }
    bool totalsWritten = false;

    const label nS = suspensions_.size();
    scalarList eroded(nS, Zero), filtered(nS, Zero);
    scalar densest = 0, largest = 0;
    if (Pstream::myProcNo() == owner)
    {
        IFstream is(file);
        const dictionary state(is);
        // (a time written before the totals were kept: they start here)
        totalsWritten = state.found("eroded");
        if (totalsWritten && suspensionsRestart)
        {
            eroded = state.get<scalarList>("eroded");
            filtered = state.get<scalarList>("filtered");
            for (const scalarList* l : {&eroded, &filtered})
            {
                bool finite = true;
                for (const scalar v : *l)
                {
                    finite = finite && std::isfinite(v);
                }
                if (l->size() != nS || !finite)
                {
                    FatalIOErrorInFunction(state)
                        << (l == &eroded ? "eroded " : "filtered ") << *l
                        << " is not allowed: " << nS << " finite totals"
                        << " (one per suspension of this run) are. Restart"
                        << " with the erosionProperties of the run that"
                        << " wrote it, or remove the entries eroded and"
                        << " filtered from " << file << " to count the"
                        << " totals (and the suspensions' balances) from"
                        << " this time" << exit(FatalIOError);
                }
            }
        }
        if (law_->surface() && state.found("densestSolidFraction"))
        {
            densest = state.get<scalar>("densestSolidFraction");
            largest = state.get<scalar>("largestPointVolume");
            if (!(densest > 0 && densest <= 1) || !(largest > 0))
            {
                FatalIOErrorInFunction(state)
                    << "densestSolidFraction " << densest << " and"
                    << " largestPointVolume " << largest << ": a fraction"
                    << " in (0, 1] and a positive volume [m3] are allowed."
                    << " Remove " << file << " to take them from the"
                    << " points of this time" << exit(FatalIOError);
            }
        }
    }
    // (exact: every processor but the owner adds zeros)
    Pstream::listCombineGather(eroded, plusEqOp<scalar>());
    Pstream::listCombineScatter(eroded);
    Pstream::listCombineGather(filtered, plusEqOp<scalar>());
    Pstream::listCombineScatter(filtered);
    reduce(densest, sumOp<scalar>());
    reduce(largest, sumOp<scalar>());
    reduce(totalsWritten, orOp<bool>());
    if (!(totalsWritten && suspensionsRestart))
    {
        for (latticeAdvectionDiffusion& susp : suspensions_)
        {
            susp.ignoreWrittenBalance();
        }
        Info<< "    Erosion's totals count from time " << runTime.timeName()
            << " (" << (totalsWritten ? "the suspension's populations or"
               " uniform/<field>Balance" : "the totals in " + file.name())
            << " not written there)" << endl;
    }

    // The running totals are per processor, summed when asked for: each
    // continues its own where the time was written on this decomposition,
    // else the master carries what came before
    eroded_ = Pstream::master() ? eroded : scalarList(nS, Zero);
    filtered_ = Pstream::master() ? filtered : scalarList(nS, Zero);
    bool own = false;
    scalarList erodedHere, filteredHere;
    if (totalsWritten && suspensionsRestart && isFile(file))
    {
        IFstream is(file);
        const dictionary state(is);
        // (the processor's own file: one copied to every processor, as
        // decomposePar copies a reconstructed case's uniform/, is not)
        if
        (
            state.getOrDefault<label>("nProcessors", -1) == Pstream::nProcs()
         && state.found("here")
         && state.subDict("here").getOrDefault<label>("processor", -1)
         == Pstream::myProcNo()
        )
        {
            const dictionary& here = state.subDict("here");
            erodedHere = here.get<scalarList>("eroded");
            filteredHere = here.get<scalarList>("filtered");
            own = erodedHere.size() == nS && filteredHere.size() == nS;
        }
    }
    if (returnReduce(own, andOp<bool>()))
    {
        eroded_ = erodedHere;
        filtered_ = filteredHere;
    }
    densest_ = densest;
    largest_ = largest;
    if (totalsWritten && suspensionsRestart)
    {
        Info<< "    Erosion's totals continue from " << file.name()
            << " of time " << runTime.timeName() << ": eroded "
            << sum(eroded) << " kg, filtered " << sum(filtered) << " kg"
            << endl;
    }
}


void Foam::physicsEffects::erosion::write()
{
    if (law_->surface())
    {
        writeWallShearStress();
    }

    // What a restart from this time must start from, to the last bit: the
    // totals (global, the same in each processor's file) and the
    // surface's reference values
    scalarList eroded(eroded_), filtered(filtered_);
    Pstream::listCombineGather(eroded, plusEqOp<scalar>());
    Pstream::listCombineScatter(eroded);
    Pstream::listCombineGather(filtered, plusEqOp<scalar>());
    Pstream::listCombineScatter(filtered);
    {
        const fileName dir(scene_.mesh().time().timePath()/"uniform");
        mkDir(dir);
        OFstream os(dir/"erosionState");
        os.precision(17);
        os  << "// Fines [kg] eroded and filtered since erosion started, per"
            << " suspension" << nl
            << "eroded " << eroded << ";" << nl
            << "filtered " << filtered << ";" << nl
            // (this processor's own running totals, which a restart on
            // the same decomposition continues: its sums then repeat the
            // uninterrupted run's to the last bit)
            << "nProcessors " << Pstream::nProcs() << ";" << nl
            << "here { processor " << Pstream::myProcNo() << "; eroded "
            << eroded_ << "; filtered " << filtered_ << "; }" << nl;
        if (law_->surface())
        {
            os  << "densestSolidFraction " << densest_ << ";" << nl
                << "largestPointVolume " << largest_ << ";" << nl;
        }
        os.flush();
        if (!os.good())
        {
            FatalErrorInFunction
                << "Could not write " << os.name() << exit(FatalError);
        }
    }
    for (const latticeAdvectionDiffusion& susp : suspensions_)
    {
        susp.writePopulations();
    }
}


Foam::wordList Foam::physicsEffects::erosion::stateFiles() const
{
    wordList files(1, "uniform/erosionState");
    for (const latticeAdvectionDiffusion& susp : suspensions_)
    {
        files.append(susp.populationFiles());
    }
    return files;
}


// ************************************************************************* //
