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

#include "caseChecks.H"
#include "optionalEntry.H"
#include "IFstream.H"
#include "StringStream.H"
#include "selectEntry.H"
#include "restartManifest.H"
#include "Time.H"
#include <fenv.h>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::checkFunctionIntervals
(
    const dictionary& controlDict,
    const scalar span
)
{
    // OpenFOAM's timeControl divides the time since the run's start by a
    // function object's runTime (adjustableRunTime, clockTime, cpuTime)
    // interval and takes a label of the quotient: an interval of 0,
    // 1e-300 or NaN trapped there, inside Time::run, with only a stack
    // trace. span: the run's simulated time [s] from its start, a step
    // beyond its end
    if (!controlDict.isDict("functions"))
    {
        return;
    }
    for (const entry& e : controlDict.subDict("functions"))
    {
        if (!e.isDict())
        {
            continue;
        }
        const dictionary& fo = e.dict();
        // (OpenFOAM builds no disabled function object)
        if (!optionalEntry<bool>(fo, "enabled", true))
        {
            continue;
        }
        for (const word prefix : {"write", "execute", "output"})
        {
            // (with the deprecated outputControl OpenFOAM reads that and
            // ignores writeControl)
            if (prefix == "write" && fo.found("outputControl"))
            {
                continue;
            }
            const word control(prefix + "Control");
            const word interval(prefix + "Interval");
            if (!fo.found(control) || !fo.found(interval))
            {
                continue;
            }
            ITstream& cts = fo.lookup(control);
            ITstream& its = fo.lookup(interval);
            if
            (
                cts.size() != 1 || !cts[0].isWord()
             || its.size() != 1 || !its[0].isNumber()
            )
            {
                continue;
            }
            const word how(cts[0].wordToken());
            const scalar value = its[0].number();
            const bool simTime =
                how == "runTime" || how == "adjustableRunTime"
             || how == "adjustable";
            const bool wallTime = how == "clockTime" || how == "cpuTime";
            if (!simTime && !wallTime)
            {
                continue;
            }
            // As many intervals as a label can count
            const scalar smallest = simTime ? span/1e9 : 1e-3;
            if (!std::isfinite(value) || !(value > 0) || value < smallest)
            {
                entryNotAllowed
                (
                    fo, interval, value,
                    "with " + control + " " + how + " it is a time ["
                  + word(simTime ? "s of the run" : "s of wall time")
                  + "]: a positive, finite number of at least "
                  + Foam::name(smallest) + " is allowed"
                );
            }
        }
    }
}


Foam::dictionary Foam::fileDictionary(const fileName& path)
{
    IFstream is(path);
    token first(is);
    if (is.good() && first.isWord() && first.wordToken() == "FoamFile")
    {
        // (as IOobject::readHeader sets the stream's format)
        const dictionary header(is);
        is.format(optionalEntry<word>(header, "format", "ascii"));
    }
    else
    {
        is.putBack(first);
    }
    return dictionary(is);
}


void Foam::checkControlDict(const argList& args)
{
    const fileName path =
        args.rootPath()/args.globalCaseName()/"system"/"controlDict";
    IFstream is(path);
    if (!is.good())
    {
        // (OpenFOAM's own message names the missing file)
        return;
    }
    const dictionary dict(is);

    auto positive = [&](const word& key)
    {
        if (!dict.found(key))
        {
            return;
        }
        // A number: anything else is refused by OpenFOAM itself
        ITstream& its = dict.lookup(key);
        if (its.size() != 1 || !its[0].isNumber())
        {
            return;
        }
        const scalar value = its[0].number();
        if (!(value > 0) || !std::isfinite(value))
        {
            entryNotAllowed
            (
                dict, key, value, "it must be a positive, finite number"
            );
        }
    };
    positive("deltaT");
    positive("writeInterval");

    if (dict.found("endTime"))
    {
        const scalar endTime = dict.get<scalar>("endTime");
        const word startFrom =
            optionalEntry<word>(dict, "startFrom", "latestTime");
        const scalar startTime = optionalEntry<scalar>(dict, "startTime", 0);
        scalar runStart = startTime;
        if (!std::isfinite(endTime) || endTime < 0)
        {
            entryNotAllowed
            (
                dict, "endTime", endTime, "it must be >= 0 and finite"
            );
        }
        // As many steps as a run can count (a label), not 1e300 s
        const scalar deltaT = optionalEntry<scalar>(dict, "deltaT", 0);
        if (deltaT > 0 && (endTime - min(startTime, endTime))/deltaT > 1e9)
        {
            entryNotAllowed
            (
                dict, "endTime", endTime,
                "it would take " + Foam::name((endTime - startTime)/deltaT)
              + " steps of deltaT " + Foam::name(deltaT) + ": a run counts"
                " at most 1e9"
            );
        }
        if (startFrom == "startTime" && endTime < startTime)
        {
            entryNotAllowed
            (
                dict, "endTime", endTime,
                "the run starts at startTime " + Foam::name(startTime)
              + ": it must not end before it"
            );
        }
        if (startFrom == "latestTime")
        {
            // The latest complete time (one a stopped run left incomplete
            // is set aside before the run starts)
            scalar latest = -GREAT;
            word latestName;
            for (const instant& t : Time::findTimes(args.path()))
            {
                if
                (
                    !isFile
                    (
                        args.path()/t.name()/restartManifest::incompleteMarker
                    )
                 && t.value() > latest
                )
                {
                    latest = t.value();
                    latestName = t.name();
                }
            }
            // (a step's worth of round-off: endTime equal to the latest
            // time is a finished run, which does nothing)
            if (latestName.size() && endTime < latest - 1e-6*mag(deltaT))
            {
                entryNotAllowed
                (
                    dict, "endTime", endTime,
                    "the run starts from the latest time " + latestName
                  + " (startFrom latestTime): it must not end before it"
                );
            }
            if (latestName.size())
            {
                runStart = latest;
            }
        }
        else if (startFrom == "firstTime")
        {
            const instantList times(Time::findTimes(args.path()));
            if (times.size())
            {
                runStart = times.first().value();
            }
        }
        // (with the end checked: an endTime of 1e300 is refused as such,
        // not as a function object's interval too small for it)
        checkFunctionIntervals(dict, max(endTime - runStart, 0) + deltaT);
    }
}


void Foam::checkInPlane
(
    const bool twoD,
    const vector& value,
    const word& keyword,
    const dictionary& dict
)
{
    if (twoD && value.z() != 0)
    {
        FatalIOErrorInFunction(dict)
            << keyword << " " << value << " is not allowed: this case is"
            << " 2D (one cell thick in z), so its z component must be 0"
            << exit(FatalIOError);
    }
}


bool Foam::suspendInputTraps()
{
    const bool trapped = fegetexcept() & (FE_OVERFLOW | FE_INVALID);
    if (trapped)
    {
        fedisableexcept(FE_OVERFLOW | FE_INVALID);
    }
    return trapped;
}


Foam::IOobject::fileCheckTypes Foam::readGlobalFilesOnEveryProcessor()
{
    const IOobject::fileCheckTypes setting =
        IOobject::fileModificationChecking;
    if (!Pstream::parRun())
    {
        return setting;
    }
    if (IOobject::fileModificationChecking == IOobject::timeStampMaster)
    {
        IOobject::fileModificationChecking = IOobject::timeStamp;
    }
    else if (IOobject::fileModificationChecking == IOobject::inotifyMaster)
    {
        IOobject::fileModificationChecking = IOobject::inotify;
    }
    return setting;
}


void Foam::restoreInputTraps(const bool wasTrapped)
{
    if (wasTrapped)
    {
        // (a flag raised while reading must not fire at once)
        feclearexcept(FE_OVERFLOW | FE_INVALID);
        feenableexcept(FE_OVERFLOW | FE_INVALID);
    }
}


void Foam::restoreRunClock(Time& runTime)
{
    const fileName path = runTime.timePath()/"uniform"/"time";
    if (!isFile(path))
    {
        return;
    }
    IFstream is(path);
    const dictionary timeDict(is);
    scalar stored = 0;
    if
    (
        timeDict.readIfPresent("value", stored)
     && std::isfinite(stored)
     && stored != runTime.value()
     && mag(stored - runTime.value()) <= 1e-9*max(1, mag(stored))
     && runTime.timeName(stored) == runTime.timeName()
    )
    {
        runTime.setTime(stored, runTime.timeIndex());
    }
}


Foam::string Foam::catchFatal
(
    const std::function<void()>& work,
    const bool whole,
    string* ioFile,
    labelPair* ioLines
)
{
    // ioFile, ioLines: where an IOerror was, for a caller that re-raises
    // the message with context (left as they were after any other error)
    const bool throwing = FatalError.throwExceptions();
    const bool ioThrowing = FatalIOError.throwExceptions();
    string failure;
    try
    {
        work();
    }
    catch (const Foam::IOerror& err)
    {
        OStringStream os;
        os << err;
        failure = whole ? os.str() : err.message();
        if (ioFile && !err.ioFileName().empty())
        {
            *ioFile = err.ioFileName();
            if (ioLines)
            {
                *ioLines =
                    labelPair(err.ioStartLineNumber(), err.ioEndLineNumber());
            }
        }
    }
    catch (const Foam::error& err)
    {
        OStringStream os;
        os << err;
        failure = whole ? os.str() : err.message();
    }
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(ioThrowing);
    return failure;
}


void Foam::runSetup(const std::function<void()>& setup)
{
    const string failure = catchFatal(setup, true);
    if (!failure.empty())
    {
        Perr<< nl << failure.c_str() << nl;
        if (Pstream::parRun())
        {
            Perr<< "\nFOAM parallel run exiting\n" << endl;
            Pstream::exit(1);
        }
        Perr<< "\nFOAM exiting\n" << endl;
        std::exit(1);
    }
}


// ************************************************************************* //
