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

// The pressure links' values: the patch value where a link crosses the
// patch, the gas's pressure at a free surface, the values that change in
// time (Function1 patches, outlets that let waves leave)

#include "lbmBoundaries.H"
#include "IFstream.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::FixedList<Foam::label, 4> Foam::lbmBoundaries::crossingFaces
(
    const label x,
    const label q,
    const label axis,
    const label patchi,
    const label ownFace
) const
{
    // A diagonal link leaving x through the patch crosses it at x - c/2:
    // half a spacing along the patch from the centre of x's face A, on the
    // edge A shares with the face B of the node x - c_t (c_t: c without
    // its normal component). A patch value that varies along the patch
    // (the hydrostatic pressure on a vertical patch) is taken there
    // (crossingValue). With the value of A alone, the links going up and
    // down through the patch carried densities half a gradient step too
    // high and too low: a vertical patch holding the hydrostatic pressure
    // of water at rest drove a current that grew to 0.3 m/s in 8 s in a
    // 1 m tank (validation/hydrostaticPressurePatch). The faces beyond, C
    // at x + c_t and D at x - 2 c_t, extrapolate where B is missing (the
    // patch's end, a node of another processor) or where the value has a
    // kink between A and B (a reservoir's level). -1: no such face.
    FixedList<label, 4> faces(-1);
    faces[0] = ownFace;

    const List<unsigned char>& kind = lattice_.kind();
    const labelList& nodeCell = lattice_.nodeCell();
    const List<FixedList<label, 6>>& cellFace = lattice_.cellBoundaryFace();
    const labelVector& stride = lattice_.stride();
    const labelVector& c = vs_.c()[q];
    const polyPatch& patch = lattice_.mesh().boundaryMesh()[patchi];

    labelVector ct(c);
    ct[axis] = 0;
    if
    (
        ct == labelVector::zero
     || kind[x - c[axis]*stride[axis]] != latticeMesh::WALL
    )
    {
        // (a link along the normal, or one past a concave corner)
        return faces;
    }
    label offset = 0;
    for (direction a = 0; a < 3; ++a)
    {
        if (ct[a] != 0 && kind[x - ct[a]*stride[a]] == latticeMesh::WALL)
        {
            // (an edge or corner of the domain: the face of x alone)
            return faces;
        }
        offset += ct[a]*stride[a];
    }
    const label dir = 2*axis + (-c[axis] > 0 ? 1 : 0);
    auto faceOnPatch = [&](const label node) -> label
    {
        if (kind[node] != latticeMesh::OWNED || nodeCell[node] < 0)
        {
            return -1;
        }
        const label facei = cellFace[nodeCell[node]][dir];
        return
            facei >= patch.start() && facei < patch.start() + patch.size()
          ? facei - patch.start() : -1;
    };
    faces[1] = faceOnPatch(x - offset);
    faces[2] = faceOnPatch(x + offset);
    if (faces[1] >= 0)
    {
        // (x - offset is owned: x - 2 offset lies in the box)
        faces[3] = faceOnPatch(x - 2*offset);
    }
    return faces;
}


Foam::scalar Foam::lbmBoundaries::crossingValue
(
    const scalarField& pPatch,
    const FixedList<label, 4>& faces,
    const bool linear
) const
{
    // Between A and B: their mean, exact for values linear along the
    // patch. Where one of them holds the gas's pressure or less (air
    // outside: a reservoir's level between them, below which p = rho g
    // (h - y) and above which the gas's), the mean would take the kink in
    // (half of rho g dx too high at the level): the value is extrapolated
    // from the wet face and the one beyond it, no lower than the gas's.
    // Without B: extrapolated from A and C.
    const label A = faces[0], B = faces[1], C = faces[2], D = faces[3];
    const scalar a = pPatch[A];
    if (B < 0)
    {
        return C < 0 ? a : 1.5*a - 0.5*pPatch[C];
    }
    const scalar b = pPatch[B];
    const bool wetA = a > gasPressure_, wetB = b > gasPressure_;
    if (linear || wetA == wetB)
    {
        return 0.5*(a + b);
    }
    const scalar v =
        wetA
      ? (C < 0 ? a : 1.5*a - 0.5*pPatch[C])
      : (D < 0 ? b : 1.5*b - 0.5*pPatch[D]);
    return max(v, gasPressure_);
}


void Foam::lbmBoundaries::setMovingValues
(
    const volVectorField& U,
    const lbmUnits& units
)
{
    // A diagonal link of an inlet with a profile took the velocity at the
    // centre of x's face, so the links going up and down through the patch
    // carried the same velocity: the inlet held no shear, and the profile
    // it fed in was off by a first-order amount that decayed downstream
    // (the Schaefer-Turek channel, two diameters from its inlet: 0.9% of
    // U_m at D/dx 20, 0.4% at 40; with the crossing's value 0.2%, 0.06%)
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = vs_.c();
    const scalarList& w = vs_.w();
    const labelVector& stride = lattice_.stride();
    const List<unsigned char>& kind = lattice_.kind();
    const labelList& nodeCell = lattice_.nodeCell();
    const List<FixedList<label, 6>>& cellFace = lattice_.cellBoundaryFace();
    const polyBoundaryMesh& patches = lattice_.mesh().boundaryMesh();

    // The directions of the faces the links cross (every processor does
    // the same exchanges)
    labelList used(6, Zero);
    forAll(movingCopy_, k)
    {
        const label q = copyGhost_[movingCopy_[k]]/nBox;
        const label axis = movingAxis_[k];
        used[2*axis + (-c[q][axis] > 0 ? 1 : 0)] = 1;
    }
    Pstream::listCombineGather(used, maxEqOp<label>());
    Pstream::listCombineScatter(used);

    for (label dir = 0; dir < 6; ++dir)
    {
        if (!used[dir])
        {
            continue;
        }
        // Each node's moving-wall velocity in this direction (flag 1
        // where it has one), copied into the halo
        List<vector> uFace(nBox, Zero);
        scalarList has(nBox, Zero);
        for (const label n : lattice_.cellNode())
        {
            const label facei = cellFace[nodeCell[n]][dir];
            if (facei < 0)
            {
                continue;
            }
            const label patchi = patches.whichPatch(facei);
            if (patchi < 0 || patchKinds_[patchi] != MOVINGWALL)
            {
                continue;
            }
            uFace[n] = units.toLattice
            (
                U.boundaryField()[patchi][facei - patches[patchi].start()]
            );
            has[n] = 1;
        }
        lattice_.halo().copyToHalo
        (
            {haloExchange::field(uFace), haloExchange::field(has)}
        );

        forAll(movingCopy_, k)
        {
            const label i = movingCopy_[k];
            const label q = copyGhost_[i]/nBox;
            const label axis = movingAxis_[k];
            if (2*axis + (-c[q][axis] > 0 ? 1 : 0) != dir)
            {
                continue;
            }
            const label x = movingNode_[k];
            vector uw = uFace[x];
            labelVector ct(c[q]);
            ct[axis] = 0;
            bool edge =
                ct == labelVector::zero
             || kind[x - c[q][axis]*stride[axis]] != latticeMesh::WALL;
            label offset = 0;
            for (direction a = 0; a < 3 && !edge; ++a)
            {
                if
                (
                    ct[a] != 0
                 && kind[x - ct[a]*stride[a]] == latticeMesh::WALL
                )
                {
                    // (an edge or corner of the domain: x's face alone)
                    edge = true;
                }
                offset += ct[a]*stride[a];
            }
            if (!edge)
            {
                const label B = x - offset, C = x + offset;
                if (has[B] > 0)
                {
                    uw = 0.5*(uFace[x] + uFace[B]);
                }
                else if (has[C] > 0)
                {
                    uw = 1.5*uFace[x] - 0.5*uFace[C];
                }
            }
            const scalar cu =
                c[q].x()*uw.x() + c[q].y()*uw.y() + c[q].z()*uw.z();
            copyValue_[i] = 6.0*w[q]*cu;
        }
    }
}


void Foam::lbmBoundaries::setGasPressure
(
    const scalar pGas,
    const volScalarField& p,
    const lbmUnits& units
)
{
    gasPressure_ = pGas;
    forAll(abbRho_, i)
    {
        if (!absorbing_[abbPatch_[i]])
        {
            abbRho_[i] = units.rhoLattice
            (
                crossingValue(p.boundaryField()[abbPatch_[i]], abbFaces_[i])
            );
        }
    }
}


void Foam::lbmBoundaries::setHydrostatic
(
    const vector& gradP,
    const point& ref,
    const volScalarField& p,
    const lbmUnits& units
)
{
    if (hasAbsorbing())
    {
        forAll(absorbing_, patchi)
        {
            if (absorbing_[patchi])
            {
                const dictionary d(fileDictionary(p.objectPath()));
                FatalIOErrorInFunction
                (
                    d.subDict("boundaryField")
                        .subDict(p.boundaryField()[patchi].patch().name())
                )
                    << "Patch " << p.boundaryField()[patchi].patch().name()
                    << ": p advective (an outlet that lets waves leave) with"
                    << " the hydrostatic pressure off the lattice (buoyancy's"
                    << " hydrostatic analytic, the default): its fieldInf is"
                    << " one value for the whole patch." << nl
                    << "    Use a fixedValue or uniformFixedValue pressure"
                    << " there, or buoyancyCoeffs { hydrostatic lattice; } in"
                    << " constant/physicsProperties" << exit(FatalIOError);
            }
        }
    }
    // (sampled where each link crosses its patch as the patch value is,
    // linearly: with a free surface the patch's value has its kink at the
    // gas's pressure, p_h none)
    hydroRhoGrad_ = (units.rhoLattice(1) - 1)*gradP;
    hydroRef_ = ref;
    const polyBoundaryMesh& patches = lattice_.mesh().boundaryMesh();
    List<scalarField> ph(patches.size());
    abbHydro_.setSize(abbRho_.size());
    forAll(abbHydro_, i)
    {
        const label patchi = abbPatch_[i];
        if (ph[patchi].empty())
        {
            ph[patchi] = gradP & (patches[patchi].faceCentres() - ref);
        }
        abbHydro_[i] =
            units.rhoLattice(crossingValue(ph[patchi], abbFaces_[i], true))
          - 1;
        abbRho_[i] -= abbHydro_[i];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::lbmBoundaries::update
(
    const lbmUnits& units,
    volVectorField& U,
    volScalarField& p,
    const scalar* f,
    const lbmLayout& layout
)
{
    // The patches' Function1 at the current time (every processor, also
    // one with no link on them: the fields' patch values stay consistent).
    // The step runs from t - dt to t: the links take each patch's value at
    // the step's middle, the mean of its values at both ends (second order
    // in time; with the value at t a sinusoidal wall led Stokes' second
    // problem by dt/2 on every grid, a first-order error in dx where dt
    // follows dx). The fields keep the value at t, as a run writes it and
    // function objects read it.
    List<vectorField> endU(varying_.size());
    List<scalarField> endP(varying_.size());
    forAll(varying_, patchi)
    {
        if (!varying_[patchi])
        {
            continue;
        }
        if (patchKinds_[patchi] == PRESSURE)
        {
            fvPatchScalarField& pp = p.boundaryFieldRef()[patchi];
            pp.evaluate();
            endP[patchi] = pp;
            pp == 0.5*(varyingStartP_[patchi] + endP[patchi]);
        }
        else
        {
            fvPatchVectorField& Up = U.boundaryFieldRef()[patchi];
            Up.evaluate();
            endU[patchi] = Up;
            Up == 0.5*(varyingStartU_[patchi] + endU[patchi]);
        }
    }

    // Ladd's bounce-back term 6 w_q c_q.u_w of the wall velocity where
    // each link crosses the patch (setMovingValues, as the constructor
    // sets it), and the pressure links' density
    if (returnReduce(varyingCopy_.size(), sumOp<label>()))
    {
        setMovingValues(U, units);
    }
    forAll(varyingAbb_, k)
    {
        const label i = varyingAbb_[k];
        abbRho_[i] = units.rhoLattice
        (
            crossingValue(p.boundaryField()[varyingAbbPatch_[k]], abbFaces_[i])
        );
        if (abbHydro_.size())
        {
            abbRho_[i] -= abbHydro_[i];
        }
    }

    // (the fields back at the value at t, the start of the next step)
    forAll(varying_, patchi)
    {
        if (varying_[patchi] && patchKinds_[patchi] == PRESSURE)
        {
            p.boundaryFieldRef()[patchi] == endP[patchi];
            varyingStartP_[patchi].transfer(endP[patchi]);
        }
        else if (varying_[patchi])
        {
            U.boundaryFieldRef()[patchi] == endU[patchi];
            varyingStartU_[patchi].transfer(endU[patchi]);
        }
    }

    // Outlets that let waves leave: the boundary density advected out at
    // the lattice's speed of sound from the node's, relaxed to fieldInf,
    // implicit in time (the header gives the equation)
    const scalar k2c = 2.0/std::sqrt(3.0);
    const label Q = vs_.Q();
    forAll(absorbAbb_, k)
    {
        const label i = absorbAbb_[k];
        const label x = abbNode_[i];
        scalar rhoX = 0;
        for (label q = 0; q < Q; ++q)
        {
            rhoX += f[layout.at(q, x)];
        }
        const label patchi = abbPatch_[i];
        const scalar m = absorbRelax_[patchi];
        abbRho_[i] =
            (abbRho_[i] + k2c*rhoX + m*absorbRhoInf_[patchi])
           /(1 + k2c + m);
    }
}


void Foam::lbmBoundaries::setAbsorbingValues
(
    const lbmUnits& units,
    volScalarField& p
) const
{
    forAll(absorbAbb_, k)
    {
        const label i = absorbAbb_[k];
        scalarField& pf = p.boundaryFieldRef()[abbPatch_[i]];
        pf[absorbFace_[k]] = units.pressure(abbRho_[i]);
    }
}


Foam::scalarList Foam::lbmBoundaries::absorbingState() const
{
    scalarList rho(absorbAbb_.size());
    forAll(absorbAbb_, k)
    {
        rho[k] = abbRho_[absorbAbb_[k]];
    }
    return rho;
}


void Foam::lbmBoundaries::setAbsorbingState(const scalarList& rho)
{
    forAll(absorbAbb_, k)
    {
        abbRho_[absorbAbb_[k]] = rho[k];
    }
}


// ************************************************************************* //
