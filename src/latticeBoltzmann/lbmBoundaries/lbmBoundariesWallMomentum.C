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
#include "lbmBoundariesLinkValuesI.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::lbmBoundaries::wallMomentum
(
    const scalar* f,
    const lbmLayout& layout,
    const scalar* porosity,
    const vector& g,
    const lbmFreeSurface* freeSurface,
    const boolList& selected,
    const boolList& selectedBodies,
    const point& CofR,
    vector& P,
    vector& M,
    vector& Prest,
    vector& Mrest
) const
{
    const label nBox = lattice_.nBox();
    const List<labelVector>& c = vs_.c();
    const scalarList& w = vs_.w();
    const labelList& opp = vs_.opp();
    const labelVector& stride = lattice_.stride();
    const vectorField& C = lattice_.mesh().C();
    const labelList& nodeCell = lattice_.nodeCell();
    const List<unsigned char>& kind = lattice_.kind();
    const List<FixedList<label, 6>>& cellFace = lattice_.cellBoundaryFace();
    const polyBoundaryMesh& patches = lattice_.mesh().boundaryMesh();
    const scalar dx = lattice_.dx();

    P = Zero;
    M = Zero;
    Prest = Zero;
    Mrest = Zero;

    // A link's wall slot (direction q at node s beyond the wall): its
    // direction and the water node x it leaves
    auto linkNode = [&](const label ghost, label& q)
    {
        q = ghost/nBox;
        const label s = ghost - q*nBox;
        const labelVector& cq = c[q];
        return s + cq.x()*stride.x() + cq.y()*stride.y() + cq.z()*stride.z();
    };

    // One link: the wall slot (direction q, node s beyond the wall), the
    // population fIn it holds, the patch of the face it crosses. A link
    // across an edge or a corner crosses a face in each axis it leaves
    // the water by: each such component of its momentum goes to the patch
    // of that face (the bottom of a tank gets the vertical share of the
    // corner's diagonal links, the side wall their horizontal one); the
    // components along the wall go to the face the link was classified by
    // (the shear on it)
    auto add = [&](const label ghost, const scalar fIn, const label patchi)
    {
        label q;
        const label x = linkNode(ghost, q);
        const labelVector& cq = c[q];
        if (freeSurface && freeSurface->gas(x))
        {
            return;
        }
        vector dP(Zero);
        vector dPrest(Zero);
        bool any = false;
        for (direction a = 0; a < 3; ++a)
        {
            const label out = -cq[a];
            if (out == 0)
            {
                continue;
            }
            label patcha = patchi;
            if (kind[x + out*stride[a]] == latticeMesh::WALL)
            {
                const label facei =
                    cellFace[nodeCell[x]][2*a + (out > 0 ? 1 : 0)];
                if (facei >= 0)
                {
                    patcha = patches.whichPatch(facei);
                }
            }
            if (patcha >= 0 && selected[patcha])
            {
                // (at rest, density 1: both populations are w_q)
                dP[a] = (f[layout.at(opp[q], x)] + fIn)*out;
                dPrest[a] = 2.0*w[q]*out;
                any = true;
            }
        }
        if (any)
        {
            const point r = C[nodeCell[x]] - 0.5*dx*vector(cq);
            // (the hydrostatic pressure the lattice does not carry, at its
            // value where the link meets the wall, on the pore water's
            // share of it as the lattice's own pressure: zero unless set)
            dP +=
                (porosity ? porosity[x] : 1.0)
               *(hydroRhoGrad_ & (r - hydroRef_))*dPrest;
            P += dP;
            M += (r - CofR) ^ dP;
            Prest += dPrest;
            Mrest += (r - CofR) ^ dPrest;
        }
    };

    // With a free surface f is filled (the wall slots hold what the next
    // step pulls: the gas's rebuilt populations, the surface's pressure
    // links and slip links): read there. (Recomputed from the gas nodes'
    // populations, a slip wall's links beside the surface read the
    // populations the gas node had when it was last water.)
    const linkSlots& sl = slots(layout);
    forAll(copyGhost_, i)
    {
        add
        (
            copyGhost_[i],
            freeSurface
          ? f[sl.copyGhost[i]]
          : f[sl.copySource[i]] + copyValue_[i],
            copyPatch_[i]
        );
    }
    forAll(abbGhost_, i)
    {
        add
        (
            abbGhost_[i],
            freeSurface
          ? f[sl.abbGhost[i]]
          : pressureLinkValue(f, layout, porosity, i),
            abbPatch_[i]
        );
    }

    // Into bodies: F = sum c_i [f*_i(x) + f_-i(x, t + 1)] (Ladd 1994; Mei
    // et al. 2002; with interpolated bounce-back as Caiazzo & Junk 2008
    // do), at the point where the link meets the surface
    forAll(bodyGhost_, k)
    {
        if (!selectedBodies.size() || !selectedBodies[bodyOf_[k]])
        {
            continue;
        }
        label q;
        const label x = linkNode(bodyGhost_[k], q);
        const labelVector& cq = c[q];
        if (freeSurface && freeSurface->gas(x))
        {
            continue;
        }
        const vector cOut(-vector(cq));
        const scalar fIn =
            freeSurface
          ? f[sl.bodyGhost[k]]
          : bodyLinkValue(f, layout, sl, k, porosity, g, nullptr);
        const vector dPrest = 2.0*w[q]*cOut;
        const point r = C[nodeCell[x]] + bodyFraction_[k]*dx*cOut;
        const vector dP =
            (f[sl.bodyA[k]] + fIn)*cOut
          + (porosity ? porosity[x] : 1.0)
           *(hydroRhoGrad_ & (r - hydroRef_))*dPrest;
        P += dP;
        M += (r - CofR) ^ dP;
        Prest += dPrest;
        Mrest += (r - CofR) ^ dPrest;
    }
}


// ************************************************************************* //
