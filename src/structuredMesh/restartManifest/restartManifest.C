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

#include "restartManifest.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "Pstream.H"
#include "stringList.H"
#include "StringStream.H"
#include "caseChecks.H"
#include "HashTable.H"
#include <fstream>
#include <iterator>
#include <cstdio>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::restartManifest::incompleteMarker("writeIncomplete");
const Foam::word Foam::restartManifest::manifestName("restartManifest");
Foam::DynamicList<Foam::fileName> Foam::restartManifest::suspects;
Foam::wordList Foam::restartManifest::droppedEffects;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The files of a time folder, relative to it, sorted; without the marker
// and the manifest
void listFiles
(
    const fileName& root,
    const fileName& rel,
    DynamicList<fileName>& out
)
{
    const fileName dir = rel.empty() ? root : root/rel;
    // (no .gz filtering: a compressed file is listed by its real name)
    for (const fileName& f : readDir(dir, fileName::FILE, false))
    {
        const fileName name = rel.empty() ? f : rel/f;
        if
        (
            name != restartManifest::incompleteMarker
         && name != fileName("uniform")/restartManifest::manifestName
        )
        {
            out.append(name);
        }
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY, false))
    {
        listFiles(root, rel.empty() ? d : rel/d, out);
    }
}


// Whether name is one of the exact files or lies in one of the folders
bool isExact(const fileName& name, const wordList& exactFiles)
{
    for (const word& e : exactFiles)
    {
        if
        (
            name == e
         || (name.size() > e.size() && name.substr(0, e.size() + 1) == e + '/')
        )
        {
            return true;
        }
    }
    return false;
}


word checksumWord(const uint64_t sum)
{
    char buf[20];
    std::snprintf
    (
        buf, sizeof(buf), "x%016llx", static_cast<unsigned long long>(sum)
    );
    return word(buf);
}


bool sameValue(const scalar a, const scalar b)
{
    return mag(a - b) <= 1e-12*max(mag(a), mag(b));
}


// Write text to a file and say whether it reached the file: the standard
// stream's own state (OpenFOAM's OFstream does not report a failed flush)
bool writeChecked(const fileName& path, const std::string& text)
{
    std::ofstream os(path.c_str(), std::ios::binary | std::ios::trunc);
    os << text;
    os.flush();
    const bool written = bool(os);
    os.close();
    return written && !os.fail();
}


// A dictionary file's text: OpenFOAM's header, the body, the end divider
std::string dictionaryText
(
    const Time& runTime,
    const word& name,
    const fileName& local,
    const std::string& body
)
{
    OStringStream os;
    os.precision(17);
    IOobject io(name, runTime.timeName(), local, runTime);
    io.writeHeader(os, "dictionary");
    os  << body.c_str();
    IOobject::writeEndDivider(os);
    return os.str();
}


dictionary readManifest(const fileName& path)
{
    IFstream is(path);
    return dictionary(is);
}


// Stop naming the manifest when reading it failed (OpenFOAM's list and
// token errors name no file; nor does a stream parsed from a string)
void unreadableManifest
(
    const fileName& path,
    const Time& runTime,
    const string& failure
)
{
    if (!failure.empty())
    {
        FatalErrorInFunction
            << "file: " << path.c_str() << " cannot be read: "
            << failure.c_str() << nl
            << "    It lists what a restart from time " << runTime.timeName()
            << " must find: restore it, or restart from an earlier time"
            << exit(FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

bool Foam::restartManifest::checksum
(
    const fileName& file,
    uint64_t& sum,
    scalar& size,
    bool& complete
)
{
    std::ifstream in(file.c_str(), std::ios::binary);
    if (!in)
    {
        return false;
    }

    // FNV-1a (Fowler, Noll, Vo) taken over 8-byte words for speed, bytes
    // for the tail, and a final avalanche: a damage detector, not a
    // cryptographic hash
    const uint64_t prime = 1099511628211ULL;
    uint64_t h = 14695981039346656037ULL;
    std::vector<char> buf(1 << 20);
    uint64_t nBytes = 0;
    bool header = false;
    char tail[5] = {0, 0, 0, 0, 0};
    label nTail = 0;
    while (in)
    {
        in.read(buf.data(), buf.size());
        const std::streamsize n = in.gcount();
        if (n <= 0)
        {
            break;
        }
        if (nBytes == 0)
        {
            header =
                std::string(buf.data(), std::min<std::streamsize>(n, 2048))
               .find("FoamFile") != std::string::npos;
        }
        const std::streamsize nWords = n/8;
        for (std::streamsize w = 0; w < nWords; ++w)
        {
            uint64_t word64;
            std::memcpy(&word64, buf.data() + 8*w, 8);
            h = (h ^ word64)*prime;
        }
        for (std::streamsize b = 8*nWords; b < n; ++b)
        {
            h = (h ^ uint64_t(static_cast<unsigned char>(buf[b])))*prime;
        }
        // The last five bytes of the file so far
        const std::streamsize from = std::max<std::streamsize>(0, n - 5);
        for (std::streamsize b = from; b < n; ++b)
        {
            for (int k = 0; k < 4; ++k)
            {
                tail[k] = tail[k + 1];
            }
            tail[4] = buf[b];
            ++nTail;
        }
        nBytes += uint64_t(n);
    }
    h ^= nBytes;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    sum = h;
    size = scalar(nBytes);
    // A file OpenFOAM wrote ends with its end divider "// *** ... *** //":
    // one cut short by a full disk does not (other files are not judged)
    complete = !header || (nTail >= 5 && std::string(tail, 5) == "* //\n");
    return true;
}


void Foam::restartManifest::setAsideIncompleteTimes(const argList& args)
{
    const fileName casePath = args.path();

    // The incomplete times of this processor, then of every processor
    List<wordList> incomplete(Pstream::nProcs());
    {
        DynamicList<word> names;
        for (const instant& t : Time::findTimes(casePath))
        {
            if (isFile(casePath/t.name()/incompleteMarker))
            {
                names.append(t.name());
            }
        }
        incomplete[Pstream::myProcNo()] = names;
    }
    Pstream::gatherList(incomplete);
    Pstream::scatterList(incomplete);
    wordHashSet names;
    for (const wordList& l : incomplete)
    {
        names.insert(l);
    }
    if (names.empty())
    {
        return;
    }
    const wordList sorted(names.sortedToc());

    // A start time named explicitly that is incomplete: refused
    const fileName controlDictPath =
        args.rootPath()/args.globalCaseName()/"system"/"controlDict";
    IFstream cis(controlDictPath);
    if (cis.good())
    {
        const dictionary controlDict(cis);
        const word startFrom =
            controlDict.getOrDefault<word>("startFrom", "latestTime");
        if (startFrom == "startTime" && controlDict.found("startTime"))
        {
            const scalar start = controlDict.get<scalar>("startTime");
            for (const word& t : sorted)
            {
                if (sameValue(readScalar(t), start))
                {
                    FatalIOErrorInFunction(controlDict)
                        << "startTime " << t << ": that time was not written"
                        << " completely (it holds the marker "
                        << incompleteMarker << ": the run writing it was"
                        << " stopped, or the disk was full)." << nl
                        << "    Start from an earlier time, or use startFrom"
                        << " latestTime (the incomplete time is then kept"
                        << " as " << t << ".incomplete)"
                        << exit(FatalIOError);
                }
            }
        }
    }

    for (const word& t : sorted)
    {
        if (!isDir(casePath/t))
        {
            continue;
        }
        fileName target = casePath/(t + ".incomplete");
        for (label k = 2; exists(target, false); ++k)
        {
            target = casePath/(t + ".incomplete" + Foam::name(k));
        }
        if (!mv(casePath/t, target))
        {
            FatalErrorInFunction
                << "Time " << t << " in " << casePath << " was not written"
                << " completely and cannot be set aside (renamed to "
                << target.name() << "): the case folder is not writable."
                << exit(FatalError);
        }
    }
    WarningInFunction
        << "Times " << sorted << " were not written completely (the run"
        << " writing them was stopped or the disk was full). They are kept"
        << " as <time>.incomplete" << (Pstream::parRun() ? " on every"
        " processor" : "") << " and the run starts from the latest complete"
        << " time." << nl << endl;
}


void Foam::restartManifest::checkWritable(const argList& args)
{
    const fileName probe =
        args.path()/(".mpmLbmFoam.writeTest" + Foam::name(pid()));
    const bool ok = writeChecked(probe, "probe\n") && isFile(probe);
    rm(probe);
    if (!ok)
    {
        FatalErrorInFunction
            << "The case folder " << args.path() << " cannot be written"
            << " (permissions, or a full disk): the run would compute and"
            << " then fail at its first write time." << nl
            << "    Make the folder writable or free space, then run again."
            << exit(FatalError);
    }
}


void Foam::restartManifest::beginWrite
(
    const Time& runTime,
    const bool markIncomplete
)
{
    const fileName dir = runTime.timePath();
    mkDir(dir);
    // decomposePar links a processor's <time>/uniform to the case's: this
    // processor's manifest needs a folder of its own
    if (isDir(dir/"uniform") && type(dir/"uniform", false) == fileName::LINK)
    {
        rm(dir/"uniform");
    }
    rm(dir/"uniform"/manifestName);
    if (!markIncomplete)
    {
        return;
    }
    const bool ok = writeChecked
    (
        dir/incompleteMarker,
        dictionaryText
        (
            runTime,
            incompleteMarker,
            fileName::null,
            "// This time folder is being written, or its writing was stopped"
            " (killed, disk full).\n// A restart from the latest time sets it"
            " aside.\n"
        )
    );
    if (!ok)
    {
        FatalErrorInFunction
            << "Cannot write in " << dir << " (permissions, or a full disk):"
            << " time " << runTime.timeName() << " is not written." << nl
            << "    The last complete time is kept; free space and restart"
            << " from it." << exit(FatalError);
    }
}


void Foam::restartManifest::endWrite
(
    const Time& runTime,
    const word& writer,
    const stateTable& localState,
    const wordList& exactFiles,
    const wordList& recordOnly,
    const wordList& effects
)
{
    const fileName dir = runTime.timePath();

    DynamicList<fileName> all;
    listFiles(dir, fileName::null, all);
    Foam::sort(all);

    DynamicList<string> names;
    DynamicList<scalar> sizes;
    DynamicList<word> sums;
    DynamicList<label> exact;
    DynamicList<fileName> bad;
    for (const fileName& name : all)
    {
        const bool isState = isExact(name, exactFiles);
        if (recordOnly.size() && !isExact(name, recordOnly))
        {
            continue;
        }
        uint64_t sum = 0;
        scalar size = 0;
        bool complete = false;
        if (!checksum(dir/name, sum, size, complete) || !complete)
        {
            bad.append(name);
            continue;
        }
        names.append(name);
        sizes.append(size);
        sums.append(checksumWord(sum));
        exact.append(isState);
    }
    for (const word& e : exactFiles)
    {
        if (!exists(dir/e))
        {
            bad.append(e + " (missing)");
        }
    }
    if (bad.size())
    {
        FatalErrorInFunction
            << "Writing time " << runTime.timeName() << " in " << dir
            << " failed: these files are cut short or missing: " << bad
            << nl << "    Is the disk full, or the folder not writable? The"
            << " time keeps the marker " << incompleteMarker << ": a restart"
            << " from the latest time sets it aside and starts from the last"
            << " complete time." << exit(FatalError);
    }

    // The totals over all processors (the same names on every processor)
    dictionary local, global;
    for (const word& key : localState.sortedToc())
    {
        local.add(key, localState[key]);
        global.add(key, returnReduce(localState[key], sumOp<scalar>()));
    }

    const fileName uniformDir = dir/"uniform";
    mkDir(uniformDir);
    const fileName path = uniformDir/manifestName;
    OStringStream body;
    body.precision(17);
    body<< "// What a restart from this time must find: written by the run,"
        << " checked at a restart" << nl << nl;
    body.writeEntry("writer", writer);
    body.writeEntry("nProcessors", Pstream::nProcs());
    body.writeEntry("processor", Pstream::myProcNo());
    if (effects.size())
    {
        body.writeEntry("effects", effects);
    }
    local.writeEntry("local", body);
    global.writeEntry("global", body);
    body.writeEntry("files", stringList(names));
    body.writeEntry("sizes", scalarList(sizes));
    body.writeEntry("checksums", wordList(sums));
    body.writeEntry("exact", labelList(exact));
    const bool ok = writeChecked
    (
        path,
        dictionaryText(runTime, manifestName, "uniform", body.str())
    );
    uint64_t sum = 0;
    scalar size = 0;
    bool complete = false;
    if (!ok || !checksum(path, sum, size, complete) || !complete)
    {
        rm(path);
        FatalErrorInFunction
            << "Writing " << path << " failed (is the disk full?): time "
            << runTime.timeName() << " keeps the marker " << incompleteMarker
            << " and is set aside at a restart from the latest time."
            << exit(FatalError);
    }

    // Complete: the marker goes last
    if (isFile(dir/incompleteMarker))
    {
        rm(dir/incompleteMarker);
    }
}


void Foam::restartManifest::checkFiles(const Time& runTime)
{
    const fileName dir = runTime.timePath();
    const fileName path = dir/"uniform"/manifestName;
    const bool here = isFile(path);
    if (!returnReduce(here, orOp<bool>()))
    {
        // A written state without its manifest: said, not silently used
        const bool state = isFile(dir/"lbmF0") || isDir(dir/"lagrangian");
        if (returnReduce(state, orOp<bool>()))
        {
            WarningInFunction
                << "Time " << runTime.timeName() << " in " << dir << " has no"
                << " uniform/" << manifestName << ": the state read from it"
                << " (populations, the cloud) is not checked against what"
                << " was written (a time written by an older version, or"
                << " whose manifest was removed)." << nl << endl;
        }
        return;
    }
    if (!here)
    {
        // (decomposePar may leave a processor without the link to the
        // case's uniform/: the state is compared over all processors)
        return;
    }
    // (OpenFOAM's list and token errors name no file: it is given here)
    dictionary manifest;
    label nProcs = 0;
    stringList names;
    scalarList sizes;
    wordList sums;
    labelList exact;
    const string unreadable = catchFatal
    (
        [&]()
        {
            manifest = readManifest(path);
            nProcs = manifest.get<label>("nProcessors");
            if (nProcs == Pstream::nProcs())
            {
                names = manifest.get<stringList>("files");
                sizes = manifest.get<scalarList>("sizes");
                sums = manifest.get<wordList>("checksums");
                exact = manifest.get<labelList>("exact");
            }
        },
        false
    );
    unreadableManifest(path, runTime, unreadable);
    if (nProcs != Pstream::nProcs())
    {
        // Decomposed or reconstructed since: the files are new, the state
        // is compared over all processors (checkState)
        return;
    }

    if
    (
        sizes.size() != names.size() || sums.size() != names.size()
     || exact.size() != names.size()
    )
    {
        FatalIOErrorInFunction(manifest)
            << "file: " << path << ": the lists files, sizes, checksums and"
            << " exact differ in length: the manifest is damaged." << nl
            << "    Restore it, restart from an earlier time, or remove it"
            << " to restart from what is there unchecked"
            << exit(FatalIOError);
    }

    DynamicList<string> damaged, edited;
    forAll(names, i)
    {
        const fileName file = dir/names[i];
        uint64_t sum = 0;
        scalar size = 0;
        bool complete = false;
        string problem;
        if (!isFile(file) || !checksum(file, sum, size, complete))
        {
            problem = names[i] + " is missing";
        }
        else if (size != sizes[i])
        {
            problem =
                names[i] + " has " + Foam::name(size) + " bytes, "
              + Foam::name(sizes[i]) + " were written";
        }
        else if (checksumWord(sum) != sums[i])
        {
            problem = names[i] + " has changed (checksum)";
        }
        if (!problem.empty())
        {
            (exact[i] ? damaged : edited).append(problem);
        }
    }

    if (damaged.size())
    {
        FatalErrorInFunction
            << "A restart from time " << runTime.timeName() << " in " << dir
            << " would not be exact: files holding the state differ from"
            << " what " << manifest.get<word>("writer") << " wrote ("
            << path.name() << " in uniform/):" << nl;
        for (const string& s : damaged)
        {
            FatalError<< "        " << s.c_str() << nl;
        }
        FatalError
            << "    Restore them or restart from an earlier time (startFrom"
            << " startTime). To start from what is there anyway, not"
            << " exactly, remove " << path << exit(FatalError);
    }
    if (edited.size())
    {
        OStringStream list;
        for (const string& s : edited)
        {
            list<< "        " << s.c_str() << nl;
        }
        WarningInFunction
            << "Files of time " << runTime.timeName() << " in " << dir
            << " changed since " << manifest.get<word>("writer")
            << " wrote them:" << nl << list.str().c_str()
            << "    They are read as they are now. (In a time the solver"
            << " wrote, the state comes from the files that hold it exactly,"
            << " the populations and the cloud: of an edited field only"
            << " what is not state counts, e.g. its boundary conditions.)"
            << nl << endl;
    }
}


Foam::string Foam::restartManifest::effectsText(const wordList& effects)
{
    // (as a scene's effects entry reads, without OpenFOAM's size prefix)
    string text("(");
    forAll(effects, i)
    {
        text += (i ? " " : "") + effects[i];
    }
    return text + ")";
}


void Foam::restartManifest::checkEffects
(
    const Time& runTime,
    const wordList& effects
)
{
    droppedEffects.clear();
    const fileName path = runTime.timePath()/"uniform"/manifestName;
    wordList written;
    if (Pstream::master() && isFile(path))
    {
        // (an unreadable manifest is checkFiles' to report)
        catchFatal
        (
            [&]() { readManifest(path).readIfPresent("effects", written); },
            false
        );
    }
    Pstream::scatter(written);
    DynamicList<word> dropped;
    for (const word& e : written)
    {
        if (!effects.found(e))
        {
            dropped.append(e);
        }
    }
    droppedEffects = dropped;
    if (dropped.size())
    {
        WarningInFunction
            << "Time " << runTime.timeName() << " was written by a run with"
            << " the effects " << effectsText(written).c_str() << "; this run has "
            << effectsText(effects).c_str() << ": the state of "
            << effectsText(droppedEffects).c_str() << " in that time (the"
            << " fields, points or populations it keeps) is not read, and"
            << " is not written from here on." << nl
            << "    To keep it, restart with the effects of that run" << nl
            << endl;
    }
}


void Foam::restartManifest::checkState
(
    const Time& runTime,
    const stateTable& localState,
    const stateSources& sources
)
{
    const fileName path = runTime.timePath()/"uniform"/manifestName;

    // Every processor's manifest text (empty where it has none): decomposePar
    // links each processor's <time>/uniform to the case's, but may leave one
    // processor without the link; the counts over all processors are then
    // compared from the manifest of any processor that has one
    List<string> texts(Pstream::nProcs());
    if (isFile(path))
    {
        std::ifstream in(path.c_str(), std::ios::binary);
        texts[Pstream::myProcNo()].assign
        (
            std::istreambuf_iterator<char>(in),
            std::istreambuf_iterator<char>()
        );
    }
    Pstream::gatherList(texts);
    Pstream::scatterList(texts);
    label first = -1;
    forAll(texts, proci)
    {
        if (!texts[proci].empty())
        {
            first = proci;
            break;
        }
    }
    if (first < 0)
    {
        return;
    }
    const bool here = !texts[Pstream::myProcNo()].empty();

    // The manifest's entries (parsed from the text gathered across the
    // processors: an error would name no file, so it is given this one)
    label nProcs = 0;
    word writer;
    HashTable<scalar> expected;
    const string damaged = catchFatal
    (
        [&]()
        {
            IStringStream is(texts[here ? Pstream::myProcNo() : first]);
            // (an entry's error names the file, not "IOstream": the
            // processors' messages may come in either order)
            is.name() = path;
            const dictionary manifest(is);
            nProcs = manifest.get<label>("nProcessors");
            writer = manifest.get<word>("writer");
            const dictionary& written =
                manifest.subDict
                (
                    nProcs == Pstream::nProcs() ? "local" : "global"
                );
            for (const word& key : written.sortedToc())
            {
                expected.set(key, written.get<scalar>(key));
            }
        },
        false
    );
    unreadableManifest(path, runTime, damaged);
    // (agreed by all processors: one whose manifest says otherwise took
    // the other branch's collective calls, and the run hung)
    const bool sameHere = !here || nProcs == Pstream::nProcs();
    const bool sameDecomposition = returnReduce(sameHere, andOp<bool>());
    if (!sameDecomposition && returnReduce(here && sameHere, orOp<bool>()))
    {
        FatalErrorInFunction
            << "Time " << runTime.timeName() << ": the processors' "
            << manifestName << " files disagree on nProcessors ("
            << path << " says " << (here ? nProcs : -1) << ", this run has "
            << Pstream::nProcs() << "): a manifest is damaged." << nl
            << "    Restore it or restart from an earlier time"
            << exit(FatalError);
    }
    if (sameDecomposition && !here)
    {
        FatalErrorInFunction
            << "Time " << runTime.timeName() << " has uniform/"
            << manifestName << " on other processors but not in "
            << runTime.timePath() << ": this processor's time folder is"
            << " incomplete." << nl
            << "    Restore it or restart from an earlier time"
            << exit(FatalError);
    }
    DynamicList<string> problems;
    for (const word& key : expected.sortedToc())
    {
        scalar value = localState.lookup(key, 0);
        label has = localState.found(key);
        if (!sameDecomposition)
        {
            reduce(value, sumOp<scalar>());
            reduce(has, sumOp<label>());
        }
        const scalar written = expected[key];
        if (has && !sameValue(value, written))
        {
            OStringStream os;
            os.precision(17);
            os  << key << ": read " << value << ", written " << written;
            if (sources.found(key) && sources[key].size())
            {
                // (the files it was read from, as the case names them)
                const fileName dir
                (
                    Pstream::parRun()
                  ? fileName
                    (
                        "processor" + Foam::name(Pstream::myProcNo())
                       /runTime.timeName()
                    )
                  : fileName(runTime.timeName())
                );
                os  << " (read from";
                for (const word& f : sources[key])
                {
                    os  << " " << (dir/f).c_str();
                }
                os  << ")";
            }
            problems.append(os.str());
        }
    }
    if (problems.size())
    {
        FatalErrorInFunction
            << "The state read from time " << runTime.timeName() << " does"
            << " not match what " << writer << " wrote ("
            << path << ", " << nProcs << " processor(s)"
            << (sameDecomposition && Pstream::parRun()
                ? ", compared on this processor" : ", compared over all")
            << "):" << nl;
        for (const string& s : problems)
        {
            FatalError<< "        " << s.c_str() << nl;
        }
        if (suspects.size())
        {
            FatalError<< "    Changed since they were written:";
            for (const fileName& f : suspects)
            {
                FatalError<< " " << f.c_str();
            }
            FatalError<< nl;
        }
        if (droppedEffects.size())
        {
            // (not damage: the state an effect kept, its own and the
            // others' totals with it, e.g. the water a free surface holds)
            FatalError
                << "    The run that wrote it had the effects "
                << effectsText(droppedEffects).c_str() << ", which this run lacks:"
                << " their state"
                << " is part of these totals. Restart with the effects of"
                << " that run, or start from 0" << exit(FatalError);
        }
        FatalError
            << "    A file of that time is missing or damaged"
            << (Pstream::parRun() ? " (e.g. a processor's lagrangian"
                " folder)" : "") << ": restore it or restart from an earlier"
            << " time." << exit(FatalError);
    }
}


// ************************************************************************* //
