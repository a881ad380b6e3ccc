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

#include "lbmBoundaries.H"
#include "lbmFreeSurface.H"
#include "Map.H"
#include "IFstream.H"
#include "caseChecks.H"
#include "DynamicList.H"
#include "emptyPolyPatch.H"
#include "wordRes.H"
#include "advectiveFvPatchFields.H"
#include "lbmBoundariesLinkValuesI.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::lbmBoundaries::patchKind>
Foam::lbmBoundaries::patchKindNames
({
    { patchKind::NONE, "none" },
    { patchKind::WALL, "bounceBack" },
    { patchKind::MOVINGWALL, "movingWall" },
    { patchKind::SLIP, "specular" },
    { patchKind::PRESSURE, "pressure" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::lbmBoundaries::classifyPatches
(
    const volVectorField& U,
    const volScalarField& p,
    const lbmUnits& units
)
{
    const fvMesh& mesh = lattice_.mesh();
    const polyBoundaryMesh& patches = mesh.boundaryMesh();

    // The field files as dictionaries: for messages naming file and line
    autoPtr<dictionary> Udict, pdict;
    auto fieldDict = [](const volScalarField::Mesh&, const regIOobject& fld)
    {
        return autoPtr<dictionary>::New(fileDictionary(fld.objectPath()));
    };

    const wordList wallTypes({"noSlip"});
    const wordList movingTypes
    ({
        "fixedValue", "movingWallVelocity", "uniformFixedValue",
        "fixedProfile"
    });
    const wordList slipTypes({"slip"});
    const wordList openUTypes
        ({"zeroGradient", "inletOutlet", "pressureInletOutletVelocity"});
    const wordList closedPTypes({"zeroGradient", "fixedFluxPressure"});
    const wordList openPTypes({"fixedValue", "uniformFixedValue", "advective"});
    // Values from a Function1 of time: set again at every step
    const word varyingType("uniformFixedValue");

    patchKinds_.setSize(patches.size(), NONE);
    varying_.setSize(patches.size(), false);
    absorbing_.setSize(patches.size(), false);
    absorbRhoInf_.setSize(patches.size(), 1.0);
    absorbRelax_.setSize(patches.size(), 0.0);

    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (pp.coupled() || isA<emptyPolyPatch>(pp))
        {
            continue;
        }

        const word Utype = U.boundaryField()[patchi].type();
        const word ptype = p.boundaryField()[patchi].type();

        auto bad = [&](const regIOobject& fld, const word& type,
                       const wordList& allowed, const string& why)
        {
            autoPtr<dictionary> d = fieldDict(mesh, fld);
            const dictionary& patchDict =
                d->subDict("boundaryField").subDict(pp.name());
            FatalIOErrorInFunction(patchDict)
                << "Patch " << pp.name() << ": type " << type
                << " is not supported by the lattice Boltzmann water "
                << why << nl
                << "    Allowed types here: " << allowed << nl
                << "    Supported pairs (U / p): noSlip / zeroGradient,"
                << " fixedValue, movingWallVelocity, uniformFixedValue or"
                << " fixedProfile / zeroGradient, slip / zeroGradient, zeroGradient"
                << " / fixedValue or uniformFixedValue, cyclic / cyclic,"
                << " empty / empty"
                << exit(FatalIOError);
        };

        if (openPTypes.found(ptype))
        {
            if (!openUTypes.found(Utype))
            {
                bad(U, Utype, openUTypes, "on a fixed-pressure patch");
            }
            patchKinds_[patchi] = PRESSURE;
            varying_[patchi] = (ptype == varyingType);
            if (ptype == "advective")
            {
                // The outlet relaxes to fieldInf over lInf: both needed
                const auto& adv =
                    refCast<const advectiveFvPatchField<scalar>>
                    (
                        p.boundaryField()[patchi]
                    );
                if (!(adv.lInf() > 0) || !std::isfinite(adv.lInf()))
                {
                    autoPtr<dictionary> d = fieldDict(mesh, p);
                    FatalIOErrorInFunction
                    (
                        d->subDict("boundaryField").subDict(pp.name())
                    )
                        << "Patch " << pp.name() << ": p advective (an"
                        << " outlet that lets waves leave) needs lInf, the"
                        << " distance [m] over which it relaxes to the"
                        << " pressure fieldInf beyond it, e.g. fieldInf 0;"
                        << " lInf 1; (lInf > 0; a few channel widths)"
                        << exit(FatalIOError);
                }
                // (the lattice's density there must stay in (0, 2), as
                // for p itself: 1e300 blew up in the first step)
                const scalar pMax = units.rho0()*sqr(units.soundSpeed());
                if (!(mag(adv.fieldInf()) < pMax))
                {
                    autoPtr<dictionary> d = fieldDict(mesh, p);
                    FatalIOErrorInFunction
                    (
                        d->subDict("boundaryField").subDict(pp.name())
                    )
                        << "Patch " << pp.name() << ": fieldInf "
                        << adv.fieldInf() << " Pa is not allowed: the"
                        << " pressure beyond the outlet must be one the"
                        << " lattice holds, |p| < rho c_s^2 = " << pMax
                        << " Pa at this deltaT and cell size"
                        << exit(FatalIOError);
                }
                absorbing_[patchi] = true;
                absorbRhoInf_[patchi] = units.rhoLattice(adv.fieldInf());
                absorbRelax_[patchi] =
                    lattice_.dx()/(std::sqrt(3.0)*adv.lInf());
            }
            continue;
        }

        if (!closedPTypes.found(ptype))
        {
            wordList allowed(closedPTypes);
            allowed.append(openPTypes);
            bad(p, ptype, allowed, "for the pressure");
        }

        if (wallTypes.found(Utype))
        {
            patchKinds_[patchi] = WALL;
        }
        else if (movingTypes.found(Utype))
        {
            // (a value that changes in time may start at rest)
            varying_[patchi] = (Utype == varyingType);
            const bool moving =
                varying_[patchi]
             || returnReduce
                (
                    max(mag(U.boundaryField()[patchi])) > 0,
                    orOp<bool>()
                );
            patchKinds_[patchi] = moving ? MOVINGWALL : WALL;
            if (Utype == "movingWallVelocity")
            {
                // A wall that moves along its normal on a fixed mesh is a
                // flow through it (OpenFOAM's movingWallVelocity keeps the
                // value on a static mesh, as fixedValue): say so, it is
                // seldom what a wall was meant to do (a closed channel
                // whose lid had a normal component lost a fifth of its
                // water without a word)
                const fvPatchVectorField& Up = U.boundaryField()[patchi];
                const scalar un = gMax(mag(Up & Up.patch().nf())());
                if (un > 1e-9*max(gMax(mag(Up)()), VSMALL))
                {
                    WarningInFunction
                        << "Patch " << pp.name() << " of 0/U:"
                        << " movingWallVelocity has a velocity of up to "
                        << un << " m/s along the patch's normal: the"
                        << " lattice lets that flow through the wall (an"
                        << " inflow or outflow, as fixedValue). A wall that"
                        << " slides moves in its own plane." << endl;
                }
            }
        }
        else if (slipTypes.found(Utype))
        {
            patchKinds_[patchi] = SLIP;
        }
        else
        {
            wordList allowed(wallTypes);
            allowed.append(movingTypes);
            allowed.append(slipTypes);
            bad
            (
                U, Utype, allowed,
                "on a wall (p " + ptype + "); an open boundary needs p"
                " fixedValue"
            );
        }
    }
}


Foam::Pair<Foam::label> Foam::lbmBoundaries::wallFace
(
    const label x,
    const label q
) const
{
    const List<unsigned char>& kind = lattice_.kind();
    const labelList& nodeCell = lattice_.nodeCell();
    const List<FixedList<label, 6>>& cellFace = lattice_.cellBoundaryFace();
    const labelVector& stride = lattice_.stride();
    const labelVector& c = vs_.c()[q];

    // The link leaves x along -c: a face of x on a wall side. A diagonal
    // link at an edge or corner crosses two or three faces. Bounce-back
    // walls take precedence: the no-slip wall goes on past the pressure
    // patch, so a population that would cross both comes from inside the
    // wall. A slip wall next to a pressure patch is a mirror plane of the
    // flow: the mirror image of the link crosses the pressure patch alone,
    // and the population the extrapolation gives for the link itself is
    // that image's (the mirror flow has the same density and normal
    // velocity). Reflecting instead would close the corner to the flow:
    // a narrow channel then loses pressure at its inlet and outlet in
    // proportion to the flux.
    auto rank = [this](const label facei)
    {
        const label patchi = lattice_.mesh().boundaryMesh().whichPatch(facei);
        switch (patchKinds_[patchi])
        {
            case WALL:
            case MOVINGWALL: return 0;
            case PRESSURE: return 1;
            default: return 2;
        }
    };

    const label cellx = nodeCell[x];
    Pair<label> best(-1, -1);
    for (direction a = 0; a < 3; ++a)
    {
        if (c[a] == 0)
        {
            continue;
        }
        const label y = x - c[a]*stride[a];
        if (kind[y] == latticeMesh::WALL)
        {
            const label dir = 2*a + (-c[a] > 0 ? 1 : 0);
            const label facei = cellFace[cellx][dir];
            if
            (
                facei >= 0
             && (best.first() < 0 || rank(facei) < rank(best.first()))
            )
            {
                best = Pair<label>(facei, a);
            }
        }
    }
    if (best.first() >= 0)
    {
        return best;
    }

    // Concave corner: the axis neighbours are fluid, the diagonal is not
    for (direction a = 0; a < 3; ++a)
    {
        if (c[a] == 0)
        {
            continue;
        }
        const label y = x - c[a]*stride[a];
        if (kind[y] != latticeMesh::OWNED)
        {
            continue;
        }
        for (direction b = 0; b < 3; ++b)
        {
            if (b == a || c[b] == 0)
            {
                continue;
            }
            const label dir = 2*b + (-c[b] > 0 ? 1 : 0);
            const label facei = cellFace[nodeCell[y]][dir];
            if (facei >= 0)
            {
                return Pair<label>(facei, b);
            }
        }
    }

    return Pair<label>(-1, -1);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lbmBoundaries::lbmBoundaries
(
    const latticeMesh& lattice,
    const velocitySet& vs,
    const lbmUnits& units,
    const volVectorField& U,
    const volScalarField& p,
    const lbmObstacles& obstacles
)
:
    lattice_(lattice),
    vs_(vs),
    hydroRhoGrad_(Zero),
    hydroRef_(Zero),
    gasPressure_(-GREAT),
    nUnclassified_(0)
{
    classifyPatches(U, p, units);

    const fvMesh& mesh = lattice_.mesh();
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const List<unsigned char>& kind = lattice_.kind();
    const labelVector& stride = lattice_.stride();
    const label nBox = lattice_.nBox();
    const label Q = vs_.Q();
    const List<labelVector>& c = vs_.c();
    const labelList& opp = vs_.opp();

    DynamicList<label> copyGhost, copySource;
    DynamicList<scalar> copyValue;
    DynamicList<label> abbGhost, abbSource, abbNode, abbDir, abbFrom;
    DynamicList<label> slipNode, slipDir, slipGhost, slipSource;
    DynamicList<scalar> abbRho;
    DynamicList<FixedList<label, 4>> abbFaces;
    DynamicList<label> copyPatch, abbPatch;
    DynamicList<label> bodyGhost, bodyA, bodyB, bodyOf;
    DynamicList<scalar> bodyWa, bodyWb, bodyFraction;
    DynamicList<label> varyingCopy, varyingCopyPatch, varyingCopyFace;
    DynamicList<label> movingCopy, movingNode, movingAxis;
    DynamicList<label> varyingAbb, varyingAbbPatch, varyingAbbFace;
    DynamicList<label> absorbAbb, absorbFace;
    DynamicList<label> bodyNode, bodyBehind;
    patchLinks_.setSize(patches.size(), 0);

    auto offsetOf = [&stride](const labelVector& v)
    {
        return v.x()*stride.x() + v.y()*stride.y() + v.z()*stride.z();
    };

    for (const label x : lattice_.cellNode())
    {
        if (obstacles.solid(x))
        {
            continue;
        }
        for (label q = 1; q < Q; ++q)
        {
            const label s = x - offsetOf(c[q]);
            if (kind[s] != latticeMesh::WALL && obstacles.solid(s))
            {
                // Into a body: Bouzidi, Firdaouss & Lallemand 2001 (linear),
                // i = opp(q) the direction from x into the body, y = x - c_i
                // the water node behind x
                const label i = opp[q];
                const scalar qw = obstacles.wallFraction(x, s);
                const label y = x + offsetOf(c[q]);
                const bool behind =
                    kind[y] != latticeMesh::WALL && !obstacles.solid(y);
                bodyGhost.append(q*nBox + s);
                bodyA.append(i*nBox + x);
                bodyBehind.append(qw < 0.5 && behind ? y : -1);
                if (qw < 0.5 && behind)
                {
                    bodyWa.append(2*qw);
                    bodyB.append(i*nBox + y);
                    bodyWb.append(1 - 2*qw);
                }
                else if (qw >= 0.5)
                {
                    bodyWa.append(0.5/qw);
                    bodyB.append(q*nBox + x);
                    bodyWb.append((2*qw - 1)/(2*qw));
                }
                else
                {
                    // (no water behind x: half-way bounce-back)
                    bodyWa.append(1);
                    bodyB.append(i*nBox + x);
                    bodyWb.append(0);
                }
                bodyOf.append(obstacles.body(s));
                bodyFraction.append(qw);
                bodyNode.append(x);
                continue;
            }
            if (kind[s] != latticeMesh::WALL)
            {
                continue;
            }

            const label ghost = q*nBox + s;
            const Pair<label> fa = wallFace(x, q);
            const label facei = fa.first();

            if (facei < 0)
            {
                // No face found (a corner of missing cells): wall at rest
                ++nUnclassified_;
                copyPatch.append(-1);
                copyGhost.append(ghost);
                copySource.append(opp[q]*nBox + x);
                copyValue.append(0);
                continue;
            }

            const label patchi = patches.whichPatch(facei);
            const label patchFacei = facei - patches[patchi].start();
            ++patchLinks_[patchi];

            switch (patchKinds_[patchi])
            {
                case PRESSURE:
                {
                    if (varying_[patchi])
                    {
                        varyingAbb.append(abbGhost.size());
                        varyingAbbPatch.append(patchi);
                        varyingAbbFace.append(patchFacei);
                    }
                    if (absorbing_[patchi])
                    {
                        absorbAbb.append(abbGhost.size());
                        absorbFace.append(patchFacei);
                    }
                    abbPatch.append(patchi);
                    abbGhost.append(ghost);
                    abbSource.append(opp[q]*nBox + x);
                    abbNode.append(x);
                    abbDir.append(q);
                    {
                        // The wall node's row: x less the link's parts
                        // along the axes it does not leave the domain by
                        labelVector tangential(c[q]);
                        for (direction a = 0; a < 3; ++a)
                        {
                            if
                            (
                                c[q][a] != 0
                             && kind[x - c[q][a]*stride[a]]
                             == latticeMesh::WALL
                            )
                            {
                                tangential[a] = 0;
                            }
                        }
                        const label y = x - offsetOf(tangential);
                        abbFrom.append
                        (
                            tangential != c[q]
                         && (
                                kind[y] == latticeMesh::OWNED
                             || kind[y] == latticeMesh::HALO
                            )
                         && !obstacles.solid(y)
                          ? y : x
                        );
                    }
                    abbFaces.append
                    (
                        crossingFaces(x, q, fa.second(), patchi, patchFacei)
                    );
                    abbRho.append
                    (
                        units.rhoLattice
                        (
                            crossingValue
                            (
                                p.boundaryField()[patchi], abbFaces.last()
                            )
                        )
                    );
                    break;
                }
                case SLIP:
                {
                    // Mirror the link in every axis along which it leaves
                    // the domain (one at a face, two at an edge, three at
                    // a corner): the population arriving at x left node
                    // y = x - c_tangential in the mirrored direction
                    labelVector mirror(c[q]);
                    labelVector tangential(c[q]);
                    for (direction a = 0; a < 3; ++a)
                    {
                        if
                        (
                            c[q][a] != 0
                         && kind[x - c[q][a]*stride[a]] == latticeMesh::WALL
                        )
                        {
                            mirror[a] = -mirror[a];
                            tangential[a] = 0;
                        }
                    }
                    // At a wall's edge pointing into the water (only the
                    // diagonal node is a wall) the link bounces back: a
                    // mirror through one axis took the population that
                    // node y sends past the edge into the water (which
                    // the water node there takes too), and the one x
                    // sends into the edge reached no node (an L-shaped
                    // container with slip walls lost or gained water at
                    // its inner corner at every step)
                    const bool edge = (tangential == c[q]);
                    const label qm = vs_.direction(mirror);
                    const label y = x - offsetOf(tangential);
                    if
                    (
                        !edge
                     && qm > 0
                     && (
                            kind[y] == latticeMesh::OWNED
                         || kind[y] == latticeMesh::HALO
                        )
                    )
                    {
                        copyPatch.append(patchi);
                        copyGhost.append(ghost);
                        copySource.append(qm*nBox + y);
                        copyValue.append(0);
                        slipNode.append(x);
                        slipDir.append(q);
                        slipGhost.append(ghost);
                        slipSource.append(y);
                        break;
                    }
                    // No such node (a corner of missing cells), or an
                    // edge: bounce back
                    copyPatch.append(patchi);
                    copyGhost.append(ghost);
                    copySource.append(opp[q]*nBox + x);
                    copyValue.append(0);
                    break;
                }
                case MOVINGWALL:
                {
                    // (the value where the link crosses the patch:
                    // setMovingValues, below)
                    if (varying_[patchi])
                    {
                        varyingCopy.append(copyGhost.size());
                        varyingCopyPatch.append(patchi);
                        varyingCopyFace.append(patchFacei);
                    }
                    movingCopy.append(copyGhost.size());
                    movingNode.append(x);
                    movingAxis.append(fa.second());
                    copyPatch.append(patchi);
                    copyGhost.append(ghost);
                    copySource.append(opp[q]*nBox + x);
                    copyValue.append(0);
                    break;
                }
                default:
                {
                    copyPatch.append(patchi);
                    copyGhost.append(ghost);
                    copySource.append(opp[q]*nBox + x);
                    copyValue.append(0);
                }
            }
        }
    }

    copyGhost_.transfer(copyGhost);
    copyPatch_.transfer(copyPatch);
    abbPatch_.transfer(abbPatch);
    bodyGhost_.transfer(bodyGhost);
    bodySourceA_.transfer(bodyA);
    bodySourceB_.transfer(bodyB);
    bodyWeightA_.transfer(bodyWa);
    bodyWeightB_.transfer(bodyWb);
    bodyOf_.transfer(bodyOf);
    bodyFraction_.transfer(bodyFraction);
    bodyNode_.transfer(bodyNode);
    bodyBehind_.transfer(bodyBehind);
    bodyCorrection_.setSize(bodyNode_.size(), Zero);

    // Each body's links, all processors (none: no body)
    bodyLinks_.setSize(obstacles.names().size(), Zero);
    for (const label b : bodyOf_)
    {
        ++bodyLinks_[b];
    }
    Pstream::listCombineGather(bodyLinks_, plusEqOp<label>());
    Pstream::listCombineScatter(bodyLinks_);
    if (sum(bodyLinks_) == 0)
    {
        // (no interpolated link anywhere: nothing to share, no exchange)
        bodyLinks_.clear();
    }

    copySource_.transfer(copySource);
    copyValue_.transfer(copyValue);
    slipNode_.transfer(slipNode);
    slipDir_.transfer(slipDir);
    slipGhost_.transfer(slipGhost);
    slipSource_.transfer(slipSource);
    abbGhost_.transfer(abbGhost);
    abbSource_.transfer(abbSource);
    abbNode_.transfer(abbNode);
    abbDir_.transfer(abbDir);
    abbFrom_.transfer(abbFrom);
    abbRho_.transfer(abbRho);
    abbFaces_.transfer(abbFaces);
    varyingCopy_.transfer(varyingCopy);
    varyingCopyPatch_.transfer(varyingCopyPatch);
    varyingCopyFace_.transfer(varyingCopyFace);
    movingCopy_.transfer(movingCopy);
    movingNode_.transfer(movingNode);
    movingAxis_.transfer(movingAxis);
    varyingAbb_.transfer(varyingAbb);
    varyingAbbPatch_.transfer(varyingAbbPatch);
    varyingAbbFace_.transfer(varyingAbbFace);
    absorbAbb_.transfer(absorbAbb);
    absorbFace_.transfer(absorbFace);

    setMovingValues(U, units);

    // The time-varying patches' values at the start time (or a restart's),
    // the first step's start (update() takes each step's middle; a field
    // refreshed after the time advanced, as the porous flow's first
    // setPorosity does, would give the end's)
    varyingStartU_.setSize(varying_.size());
    varyingStartP_.setSize(varying_.size());
    forAll(varying_, patchi)
    {
        if (varying_[patchi] && patchKinds_[patchi] == PRESSURE)
        {
            varyingStartP_[patchi] = p.boundaryField()[patchi];
        }
        else if (varying_[patchi])
        {
            varyingStartU_[patchi] = U.boundaryField()[patchi];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::lbmBoundaries::linkSlots& Foam::lbmBoundaries::slots
(
    const lbmLayout& layout
) const
{
    linkSlots& s = slots_[layout.layout()];
    if (!s.made)
    {
        s.copyGhost = layout.remap(copyGhost_);
        s.copySource = layout.remap(copySource_);
        s.bodyGhost = layout.remap(bodyGhost_);
        s.bodyA = layout.remap(bodySourceA_);
        s.bodyB = layout.remap(bodySourceB_);
        s.bodyRest = layout.remap(bodyNode_);
        s.abbGhost = layout.remap(abbGhost_);
        s.made = true;
    }
    return s;
}


void Foam::lbmBoundaries::fill
(
    scalar* f,
    const lbmLayout& layout,
    const scalar* porosity,
    const lbmFreeSurface* freeSurface,
    const vector& g
) const
{
    const linkSlots& sl = slots(layout);
    const label n = copyGhost_.size();
    const label* ghost = sl.copyGhost.cdata();
    const label* src = sl.copySource.cdata();
    const scalar* val = copyValue_.cdata();
    for (label i = 0; i < n; ++i)
    {
        f[ghost[i]] = f[src[i]] + val[i];
    }

    // Into bodies (their sources are water nodes' populations, never a
    // wall slot). The interpolation gives the water back more or less
    // than its links took into a body (a body at rest takes no mass: the
    // half-way bounce-back returns each population whole), so the water
    // leaked: a free surface's water around a cylinder gained 1.35e-2 in
    // 8000 steps, 1.7e-7 once the interpolation kept the water at rest.
    // (Bao, Yuan & Schaefer 2008, J. Comput. Phys. 227, 8472, correct it
    // at each node.) Here each body's imbalance over all its links is
    // shared equally by its links' nodes, in their rest populations
    // (which carry no momentum), so the water's mass is exact to
    // round-off. Given back
    // at each node, the node's own imbalance changed the flow near the
    // wall: Schaefer-Turek's C_L went from 0.0% to 2.7% off and C_D's
    // order from 2.4 to 1.4. (A gas node's links count for nothing.)
    forAll(bodyGhost_, i)
    {
        const scalar in =
            bodyLinkValue(f, layout, sl, i, porosity, g, freeSurface);
        f[sl.bodyGhost[i]] = in;
        bodyCorrection_[i] =
            freeSurface && freeSurface->gas(bodyNode_[i])
          ? 0
          : f[sl.bodyA[i]] - in;
    }
    if (bodyLinks_.size())
    {
        // Per body its imbalance and its links at water nodes, summed over
        // the processors in one reduction (the sums' order differs with
        // the decomposition: parallel = serial to round-off)
        const label nBodies = bodyLinks_.size();
        scalarList sums(2*nBodies, Zero);
        forAll(bodyGhost_, i)
        {
            sums[bodyOf_[i]] += bodyCorrection_[i];
            sums[nBodies + bodyOf_[i]] +=
                !(freeSurface && freeSurface->gas(bodyNode_[i]));
        }
        Pstream::listCombineGather(sums, plusEqOp<scalar>());
        Pstream::listCombineScatter(sums);
        const SubList<scalar> imbalance(sums, nBodies);
        const SubList<scalar> wet(sums, nBodies, nBodies);
        forAll(bodyGhost_, i)
        {
            const label b = bodyOf_[i];
            bodyCorrection_[i] =
                (freeSurface && freeSurface->gas(bodyNode_[i]))
             || !(wet[b] > 0)
              ? 0
              : imbalance[b]/wet[b];
            f[sl.bodyRest[i]] += bodyCorrection_[i];
        }
    }

    if (abbGhost_.empty())
    {
        return;
    }

    if (freeSurface)
    {
        // A pressure patch that the surface meets: no link of a gas node
        // (no water: no pull reads its slots); where the patch holds the
        // gas's pressure or less (air outside: above the reservoir's
        // level), an interface node's link takes the gas's pressure
        // carried from the surface to where it crosses the patch, as the
        // free surface's links to the gas do (the patch's value there,
        // the gas's, sat above the water's own pressure beside the
        // surface and drove water in). Extrapolated as the patch's other
        // links, not rebuilt as a gas link: rebuilt, it held a current of
        // 3e-3 m/s through the patch beside a reservoir at the tank's
        // level
        const scalar rhoGas = freeSurface->rhoGas();
        forAll(abbGhost_, i)
        {
            const label x = abbNode_[i];
            if (freeSurface->gas(x))
            {
                continue;
            }
            // (the wall node's row node y has no water of its own where
            // it is gas: x's velocity and non-equilibrium then)
            const bool fromItself = freeSurface->gas(abbFrom_[i]);
            f[sl.abbGhost[i]] =
                freeSurface->interface(x) && dryPressureLink(i, rhoGas)
              ? pressureLinkValue
                (
                    f, layout, porosity, i,
                    freeSurface->gasLinkDensity(x, abbDir_[i], g),
                    fromItself
                )
              : pressureLinkValue(f, layout, porosity, i, -1, fromItself);
        }
        return;
    }
    forAll(abbGhost_, i)
    {
        f[sl.abbGhost[i]] = pressureLinkValue(f, layout, porosity, i);
    }
}


void Foam::lbmBoundaries::fillHomogeneous
(
    scalar* f,
    const lbmFreeSurface* freeSurface
) const
{
    forAll(copyGhost_, i)
    {
        f[copyGhost_[i]] = f[copySource_[i]];
    }
    forAll(bodyGhost_, i)
    {
        f[bodyGhost_[i]] =
            bodyWeightA_[i]*f[bodySourceA_[i]]
          + bodyWeightB_[i]*f[bodySourceB_[i]];
    }
    const label nBox = lattice_.nBox();
    forAll(abbGhost_, i)
    {
        const label y =
            freeSurface && freeSurface->gas(abbFrom_[i])
          ? abbNode_[i] : abbFrom_[i];
        f[abbGhost_[i]] = f[abbDir_[i]*nBox + y];
    }
}


Foam::labelList Foam::lbmBoundaries::pressureNodes() const
{
    labelList nodes(abbNode_);
    Foam::sort(nodes);
    label nUnique = 0;
    forAll(nodes, i)
    {
        if (i == 0 || nodes[i] != nodes[nUnique - 1])
        {
            nodes[nUnique++] = nodes[i];
        }
    }
    nodes.setSize(nUnique);
    return nodes;
}


void Foam::lbmBoundaries::report(Ostream& os) const
{
    const polyBoundaryMesh& patches = lattice_.mesh().boundaryMesh();

    // Processor patches differ between processors: gather the others only
    labelList links(SubList<label>(patchLinks_, patches.nNonProcessor()));
    Pstream::listCombineGather(links, plusEqOp<label>());
    Pstream::listCombineScatter(links);

    os  << "Lattice Boltzmann boundaries" << nl;
    forAll(links, patchi)
    {
        if (patchKinds_[patchi] == NONE)
        {
            continue;
        }
        os  << "    " << patches[patchi].name() << ": "
            << patchKindNames[patchKinds_[patchi]] << " (" << links[patchi]
            << " links" << (varying_[patchi] ? ", value in time" : "")
            << (absorbing_[patchi] ? ", lets waves leave" : "")
            << ")" << nl;
    }
    const label nBody = returnReduce(bodyGhost_.size(), sumOp<label>());
    if (nBody)
    {
        os  << "    obstacles: interpolated bounce-back (" << nBody
            << " links)" << nl;
    }
    const label nUn = returnReduce(nUnclassified_, sumOp<label>());
    if (nUn)
    {
        os  << "    " << nUn << " corner links with no face to classify them:"
            << " bounce-back" << nl;
    }
    os  << endl;
}


// ************************************************************************* //
