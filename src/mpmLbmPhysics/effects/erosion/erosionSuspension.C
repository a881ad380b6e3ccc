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
    erosion: what the suspension does back. Deep-bed filtration (a
    filtrationLaw: the points catch fines from the suspension at their
    node, their porosity falling) and the mixture's weight on the water
    (mixtureDensity).

\*---------------------------------------------------------------------------*/

#include "erosionEffect.H"
#include "physicsScene.H"
#include "soilEffect.H"
#include "materialPointSoil.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::physicsEffects::erosion::filterPoints()
{
    const scalarList& phi = soil_.solidFraction();
    const List<vector>& soilVelocity = soil_.nodeVelocity();
    materialPoints& pts = soil_.mpm().points();

    const scalar dt = scene_.mesh().time().deltaTValue();
    const scalar Vcell = fluid_.lattice().cellVolume();
    const scalar rhoS = law_->rhoSolid();
    const scalar fMax = filtration_->maxFinesContent();

    // The points' porosity never falls below this: a pore space the drag
    // laws still hold (Kozeny-Carman's permeability ~ n^3)
    const scalar nMin = 0.01;

    // What each point would catch, and its node's total
    catchPoint_.setSize(pts.x.size());
    catchDemand_ = 0;
    forAll(pts.x, p)
    {
        catchPoint_[p] = 0;
        const scalar f = pts.fines[p];
        if (!(f < fMax) || !(pts.porosity[p] > nMin))
        {
            continue;
        }
        const label n = nodeOf(pts.x[p]);
        const scalar wet = wetFraction(n);
        if (!(wet > 0))
        {
            // Dry: no suspension to catch
            continue;
        }
        const scalar nNode = max(1 - phi[n], 0.01);
        const scalar q = mag(uPhysical_[n] - nNode*soilVelocity[n]);
        const scalar C = Phi(n)/(nNode*wet);
        const scalar m = pts.m[p];
        const scalar dm = min
        (
            filtration_->rate(C, q, f)*pts.V[p]*dt,
            min
            (
                m*(fMax - f)/(1 - fMax),
                rhoS*pts.V[p]*(pts.porosity[p] - nMin)
            )
        );
        if (dm > 0)
        {
            catchPoint_[p] = dm;
            catchDemand_[n] += dm;
        }
    }

    // Each node gives what its points ask, at most what it holds (the
    // points then share it in proportion to what they asked)
    forAll(catchDemand_, n)
    {
        if (catchDemand_[n] > 0)
        {
            const scalar held = Phi(n)*Vcell;
            catchDemand_[n] =
                catchDemand_[n] > held
              ? held/catchDemand_[n]*(1 - 1e-12)
              : 1;
        }
    }

    // The points gain what their mass can hold exactly ((m + dm) - m:
    // a tiny dm added to m rounds, the same way step after step), and
    // each node gives exactly the sum its points gained, so the
    // suspension's loss and the points' gain are one number
    bool changed = false;
    forAll(pts.x, p)
    {
        if (!(catchPoint_[p] > 0))
        {
            continue;
        }
        const label n = nodeOf(pts.x[p]);
        const scalar m = pts.m[p];
        const scalar mNew = m + catchPoint_[p]*catchDemand_[n];
        const scalar gained = mNew - m;
        catchPoint_[p] = 0;
        if (!(gained > 0))
        {
            continue;
        }
        pts.fines[p] = min((pts.fines[p]*m + gained)/mNew, fMax);
        pts.porosity[p] = max(pts.porosity[p] - gained/(rhoS*pts.V[p]), nMin);
        pts.m[p] = mNew;
        catchPoint_[p] = gained;
        changed = true;
    }
    catchDemand_ = 0;
    forAll(pts.x, p)
    {
        if (catchPoint_[p] > 0)
        {
            catchDemand_[nodeOf(pts.x[p])] += catchPoint_[p];
        }
    }
    // (with several suspensions, from each in proportion to what it
    // holds there)
    forAll(catchDemand_, n)
    {
        if (catchDemand_[n] > 0)
        {
            if (suspensions_.size() == 1)
            {
                filtered_[0] +=
                    suspensions_[0].take(n, catchDemand_[n]/Vcell)*Vcell;
                continue;
            }
            const scalar total = Phi(n);
            forAll(suspensions_, s)
            {
                const scalar share = max(suspensions_[s].Phi(n), scalar(0));
                if (share > 0 && total > 0)
                {
                    filtered_[s] +=
                        suspensions_[s].take
                        (
                            n, catchDemand_[n]/Vcell*share/total
                        )*Vcell;
                }
            }
        }
    }
    if (returnReduce(changed, orOp<bool>()))
    {
        soil_.pointsChanged();
    }
}


void Foam::physicsEffects::erosion::mixtureWeight()
{
    // Before the suspension's populations are set: on a restart read
    // them now (the weight is then the written state's to the last bit);
    // at a fresh start they are set from the field at the transport stage
    // of the first step, with the porosity the water has then (this stage
    // comes before porousFlow gives it), so that step has no weight yet
    for (latticeAdvectionDiffusion& susp : suspensions_)
    {
        if (!susp.initialised())
        {
            if (!susp.writtenPopulations())
            {
                return;
            }
            susp.prepare(u_, nullptr);
        }
    }
    const lbmUnits& units = fluid_.units();

    // Phi [kg/m3 of mixture] x (1 - rho_w/rho_s) x a [m/s2] = N/m3
    const vector a =
        mixtureFactor_*units.forceDensityToLattice()
       *fluid_.bodyAcceleration();
    for (const label n : fluid_.lattice().cellNode())
    {
        mixtureForce_[n] = Phi(n)*a;
    }
}


// ************************************************************************* //
