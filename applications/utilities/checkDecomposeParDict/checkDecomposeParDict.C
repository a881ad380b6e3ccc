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

Application
    checkDecomposeParDict

Group
    grpParallelUtilities

Description
    Checks system/decomposeParDict (and system/controlDict) the way
    OpenFOAM's decomposePar will read them, and refuses with a FatalIOError
    naming the file, the keyword, the value and what is allowed what
    v1912's decomposePar crashes on or misreads:
    - a number such as 1e400 anywhere in the file (decomposePar's parser
      raises the overflow flag that FOAM_SIGFPE traps: a signal and a stack
      trace), or a header's version such as 1e300 (its conversion to an
      integer overflows);
    - numberOfSubdomains below 1 (a negative count aborts it, 0 ends in an
      error that does not name the file);
    - for the methods simple and hierarchical, a split n with a component
      below 1 or whose product is not numberOfSubdomains, or a delta that
      is not in [0, 1);
    - a weightField that is not a field of the start time.
    Run by bin/decomposePar before OpenFOAM's decomposePar, silent when the
    dictionary is fine. Options as decomposePar's:

    \verbatim
        checkDecomposeParDict [-case DIR] [-region NAME]
            [-decomposeParDict FILE]
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "optionalEntry.H"
#include "Time.H"
#include "IOdictionary.H"
#include "polyMesh.H"
#include "Vector.H"
#include "IFstream.H"
#include "caseChecks.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The sub-dictionary a geometric method reads its coefficients from, as
//  decompositionMethod::findCoeffsDict finds it: <method>Coeffs, else
//  coeffs, else the dictionary itself
const dictionary& methodCoeffs(const dictionary& dict, const word& method)
{
    if (const dictionary* coeffs = dict.findDict(method + "Coeffs"))
    {
        return *coeffs;
    }
    if (const dictionary* coeffs = dict.findDict("coeffs"))
    {
        return *coeffs;
    }
    return dict;
}


//- decomposePar converts the header's version to an int (ten times it):
//  a version such as 1e300 overflows the conversion, which FOAM_SIGFPE
//  traps
void checkHeaderVersion(const fileName& file)
{
    IFstream is(file);
    dictionary whole;
    whole.read(is, true);       // (keeping the header)
    const dictionary* header = whole.findDict("FoamFile");
    scalar version = 2;
    if (header && header->readIfPresent("version", version))
    {
        if (!(std::isfinite(version) && version >= 0 && version < 1e8))
        {
            FatalIOErrorInFunction(is)
                << "FoamFile { version " << version << "; }" << " is not allowed: it is the"
                << " format's version number, 2.0 for every OpenFOAM file"
                << " since 2.0" << exit(FatalIOError);
        }
    }
}


void checkDecomposition(const Time& runTime, const dictionary& dict,
    const word& regionDir)
{
    const label nDomains = dict.get<label>("numberOfSubdomains");
    if (nDomains < 1)
    {
        FatalIOErrorInFunction(dict)
            << "numberOfSubdomains " << nDomains << " is not allowed: it is"
            << " the number of processors the case is split into, a whole"
            << " number of at least 1" << exit(FatalIOError);
    }

    const word method = dict.get<word>("method");
    if (method == "simple" || method == "hierarchical")
    {
        const dictionary& coeffs = methodCoeffs(dict, method);
        const Vector<label> n = coeffs.get<Vector<label>>("n");
        for (direction d = 0; d < 3; ++d)
        {
            if (n[d] < 1)
            {
                FatalIOErrorInFunction(coeffs)
                    << "n " << n << " is not allowed: method " << method
                    << " splits the mesh into n.x() n.y() n.z() parts along"
                    << " x, y, z, each a whole number of at least 1"
                    << exit(FatalIOError);
            }
        }
        // (a product of three labels read as such may overflow a label)
        const double parts = double(n.x())*double(n.y())*double(n.z());
        if (parts != double(nDomains))
        {
            FatalIOErrorInFunction(coeffs)
                << "n " << n << " splits the mesh into " << parts
                << " parts, but numberOfSubdomains is " << nDomains
                << ": n.x() n.y() n.z() must equal numberOfSubdomains"
                << exit(FatalIOError);
        }
        scalar delta = 0.001;
        if
        (
            readIfPresentEntry(coeffs, "delta", delta)
         && !(std::isfinite(delta) && delta >= 0 && delta < 1)
        )
        {
            FatalIOErrorInFunction(coeffs)
                << "delta " << delta << " is not allowed: it is the small"
                << " rotation (in radians) of the split directions that"
                << " breaks ties between cell centres, in [0, 1)"
                << " (default 0.001)" << exit(FatalIOError);
        }
    }

    word weightName;
    if (readIfPresentEntry(dict, "weightField", weightName))
    {
        // decomposePar reads it at the start time, in the mesh's region
        const fileName field = runTime.timePath()/regionDir/weightName;
        if (!isFile(field) && !isFile(field + ".gz"))
        {
            FatalIOErrorInFunction(dict)
                << "weightField " << weightName << " is not a field of the"
                << " start time: no file "
                << (runTime.timeName()/regionDir/weightName).c_str()
                << " in the case. Give the name of a"
                << " cell field (volScalarField) of the start time, e.g."
                << " cellWork (written by setMaterialPoints), or remove the"
                << " entry to share the cells equally" << exit(FatalIOError);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Check system/decomposeParDict as decomposePar will read it;"
        " silent when it is fine, a FatalIOError naming the file and the"
        " entry when it is not"
    );
    argList::noBanner();
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "decomposeParDict",
        "file",
        "Use the specified decomposePar dictionary, as decomposePar"
    );
    argList::addOption("region", "name", "The mesh region, as decomposePar");

    #include "setRootCase.H"
    // A number such as 1e400 in the input: the parser's error, not a trap;
    // and OpenFOAM's fatal errors end it cleanly (caseChecks.H)
    suspendInputTraps();
    runSetup
    (
        [&]()
        {
            checkControlDict(args);
            Time runTime(Time::controlDictName, args);

            const word regionName =
                args.get<word>("region", polyMesh::defaultRegion);
            const word regionDir =
                regionName == polyMesh::defaultRegion ? word::null : regionName;
            const fileName altFile =
                args.get<fileName>("decomposeParDict", "");

            const IOdictionary dict
            (
                IOobject::selectIO
                (
                    IOobject
                    (
                        "decomposeParDict",
                        runTime.system(),
                        regionDir,
                        runTime,
                        IOobject::MUST_READ,
                        IOobject::NO_WRITE,
                        false
                    ),
                    altFile
                )
            );
            checkHeaderVersion(dict.objectPath());
            checkDecomposition(runTime, dict, regionDir);
        }
    );

    return 0;
}


// ************************************************************************* //
