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

// The suspensions' fields as the erosion reads them at its start

#include "erosionEffect.H"
#include "physicsScene.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::physicsEffects::erosion::checkSuspensions() const
{
    // No more grains in a volume of water than grains fill it (the field a
    // run starts from; the limit the erosion keeps may be overshot: a time
    // it wrote is not checked) and no inflow above that limit
    const Time& runTime = scene_.mesh().time();
    const bool written = returnReduce
    (
        isFile(runTime.timePath()/"uniform"/"erosionState"),
        orOp<bool>()
    );
    const scalar rhoS = law_->rhoSolid();
    // (a law proportional to the suspended fines erodes nothing from clear
    // water: whether any water holds or brings fines)
    scalar mostSuspended = 0;
    for (const latticeAdvectionDiffusion& susp : suspensions_)
    {
        const volScalarField& C = susp.field();
        if (C.dimensions() != dimDensity)
        {
            FatalIOErrorInFunction(dict_)
                << C.objectPath() << ": the suspended fines are a mass per"
                << " volume of water " << dimDensity << ", not "
                << C.dimensions() << exit(FatalIOError);
        }
        // (the file as a dictionary, for a message naming its line: read
        // only for one, in the format its header names)
        auto fieldDict = [&C]() { return fileDictionary(C.objectPath()); };
        forAll(C, celli)
        {
            mostSuspended = max(mostSuspended, C[celli]);
            if (!written && C[celli] > rhoS)
            {
                FatalIOErrorInFunction(fieldDict())
                    << C.objectPath() << ": " << C.name() << " " << C[celli]
                    << " kg/m3 in cell " << celli << " is more grains than"
                    << " a volume of them holds: the suspended fines must"
                    << " lie in [0, rhoSolid " << rhoS << "] kg/m3"
                    << " (maxConcentration " << maxConcentration_ << ")"
                    << exit(FatalIOError);
            }
        }
        forAll(C.boundaryField(), patchi)
        {
            const fvPatchScalarField& Cp = C.boundaryField()[patchi];
            const tmp<scalarField> tgiven
            (
                latticeAdvectionDiffusion::inflowValues(Cp)
            );
            const scalarField& given = tgiven();
            if (given.size())
            {
                mostSuspended = max(mostSuspended, max(given));
            }
            if (given.size() && max(given) > maxConcentration_)
            {
                FatalIOErrorInFunction
                (
                    fieldDict().subDict("boundaryField")
                        .subDict(Cp.patch().name())
                )
                    << C.objectPath() << ": patch " << Cp.patch().name()
                    << " (" << Cp.type() << ") brings in " << max(given)
                    << " kg/m3 of " << C.name() << ", above the most fines"
                    << " the pore water carries, maxConcentration "
                    << maxConcentration_ << " kg/m3 (rhoSolid " << rhoS
                    << "): give a concentration in [0, " << maxConcentration_
                    << "]" << exit(FatalIOError);
            }
        }
    }
    reduce(mostSuspended, maxOp<scalar>());
    if
    (
        !written && suspensions_.size() && law_->needsSuspendedFines()
     && !(mostSuspended > 0)
    )
    {
        const word lawName(dict_.get<word>("erosionLaw"));
        IOWarningInFunction(dict_.subOrEmptyDict(lawName + "Coeffs"))
            << "erosionLaw " << lawName << " with seedConcentration 0"
            << " erodes in proportion to the fines already in suspension,"
            << " and the water holds none (" << suspensions_[0].field().name()
            << " 0 in every cell) and no patch brings any in: nothing will"
            << " erode. Give a seedConcentration > 0 (e.g. 1e-3, a seed of"
            << " fluidized fines) or fines in 0/"
            << suspensions_[0].field().name() << nl << endl;
    }
}


// ************************************************************************* //
