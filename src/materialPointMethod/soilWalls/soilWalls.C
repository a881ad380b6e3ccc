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

#include "soilWalls.H"
#include "selectEntry.H"
#include "emptyPolyPatch.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::soilWalls::wallType>
Foam::soilWalls::wallTypeNames
({
    { wallType::slip, "slip" },
    { wallType::noSlip, "noSlip" },
    { wallType::friction, "friction" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A node this processor holds (owned or in the halo)
inline bool isLocal(const Foam::label k)
{
    return k == Foam::latticeMesh::OWNED || k == Foam::latticeMesh::HALO;
}

// The patches the soil can meet (neither coupled nor empty)
Foam::wordList wallPatchNames(const Foam::polyBoundaryMesh& patches)
{
    Foam::wordList names;
    for (const Foam::polyPatch& pp : patches)
    {
        if (!pp.coupled() && !Foam::isA<Foam::emptyPolyPatch>(pp))
        {
            names.append(pp.name());
        }
    }
    return names;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::soilWalls::readWalls(const dictionary& walls)
{
    const polyBoundaryMesh& patches = lattice_.mesh().boundaryMesh();

    patchWall_.setSize(patches.size(), wallType::slip);
    patchFriction_.setSize(patches.size(), 0.0);

    for (const entry& e : walls)
    {
        if (e.keyword().isPattern())
        {
            continue;
        }
        const word& name = e.keyword();
        const label patchi = patches.findPatchID(name);
        if (patchi < 0)
        {
            FatalIOErrorInFunction(walls)
                << "walls: " << name << " is not a patch of the mesh: the"
                << " patches the soil can meet are "
                << wallPatchNames(patches) << exit(FatalIOError);
        }
    }

    wordList missing;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (pp.coupled() || isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        if (!walls.found(pp.name()))
        {
            missing.append(pp.name());
            continue;
        }
        const dictionary& wd = walls.subDict(pp.name());
        patchWall_[patchi] = selectEntry(wallTypeNames, "type", wd);
        if (patchWall_[patchi] == wallType::friction)
        {
            const scalar mu = wd.get<scalar>("coefficient");
            if (!(mu >= 0))
            {
                FatalIOErrorInFunction(wd)
                    << "coefficient " << mu << " is not allowed: the Coulomb"
                    << " friction coefficient must be >= 0" << exit(FatalIOError);
            }
            patchFriction_[patchi] = mu;
        }
    }
    if (missing.size())
    {
        FatalIOErrorInFunction(walls)
            << "No soil wall condition for patches " << missing << nl
            << "    Give each wall patch an entry, e.g." << nl
            << "        " << missing[0] << " { type slip; }" << nl
            << "    Allowed types: " << wallTypeNames.sortedToc()
            << " (friction needs coefficient)" << exit(FatalIOError);
    }
}


Foam::List<Foam::labelList> Foam::soilWalls::sidePatches() const
{
    // In parallel also at the halo nodes: a node beyond a wall near a
    // processor boundary mirrors a node of the neighbour. (The patches a
    // decomposition keeps have the same index on every processor.)
    const List<FixedList<label, 6>>& cellFace = lattice_.cellBoundaryFace();
    const polyBoundaryMesh& patches = lattice_.mesh().boundaryMesh();

    List<labelList> sidePatch(6, labelList(lattice_.nBox(), -1));
    forAll(cellFace, celli)
    {
        for (label dir = 0; dir < 6; ++dir)
        {
            if (cellFace[celli][dir] >= 0)
            {
                sidePatch[dir][lattice_.cellNode()[celli]] =
                    patches.whichPatch(cellFace[celli][dir]);
            }
        }
    }
    if (Pstream::parRun())
    {
        for (labelList& sp : sidePatch)
        {
            lattice_.halo().exchange(sp);
        }
    }
    return sidePatch;
}


void Foam::soilWalls::mirrorSign
(
    const label patchi,
    const direction d,
    vector& s
) const
{
    // A slip wall reverses the normal component, a noSlip wall every
    // component. Beyond a friction wall the node copies the node inside,
    // which thereby carries the whole load on the wall and meets it through
    // the Coulomb contact
    const wallType wt = patchi >= 0 ? patchWall_[patchi] : wallType::noSlip;
    if (wt == wallType::noSlip)
    {
        s = -s;
    }
    else if (wt == wallType::slip)
    {
        s[d] = -s[d];
    }
}


Foam::label Foam::soilWalls::boxKind(const labelVector& c, label& m) const
{
    const labelVector b = c - lattice_.boxStart();
    const labelVector& bn = lattice_.boxN();
    for (direction d = 0; d < 3; ++d)
    {
        if (b[d] < 0 || b[d] >= bn[d])
        {
            return -1;
        }
    }
    m = lattice_.node(b.x(), b.y(), b.z());
    return lattice_.kind()[m];
}


Foam::label Foam::soilWalls::missingCellImage
(
    const labelVector& g,
    const List<labelList>& sidePatch,
    vector& s
) const
{
    // Across the face of the nearest cell of the mesh along an axis, within
    // the shape function's reach, with that face's wall condition (sign s
    // as at the box's walls). None (-1) where two faces are equally near
    // (the corner of a step) or the mesh beyond the face is too thin for
    // the image. Undetermined here (-2) where the nearest face or the image
    // lies beyond this processor's box or halo (a cell another processor
    // owns, not in the halo: UNUSED).
    const labelVector& N = lattice_.globalN();
    label nearest = reach_ + 1, image = -1, unknownFrom = reach_ + 1;
    bool tie = false;
    for (direction d = 0; d < (lattice_.twoD() ? 2 : 3); ++d)
    for (label side = 0; side < 2; ++side)
    {
        const label step = side ? 1 : -1;
        for (label k = 1; k <= min(reach_, nearest); ++k)
        {
            labelVector c(g);
            c[d] += step*k;
            if (c[d] < 0 || c[d] >= N[d])
            {
                break;
            }
            label cn = -1;
            const label ck = boxKind(c, cn);
            if (ck < 0)
            {
                unknownFrom = min(unknownFrom, k);
                break;
            }
            if (ck == latticeMesh::WALL)
            {
                continue;
            }
            // c is the first cell of the mesh: the face is on its side
            // towards the node; the image lies as far inside
            if (k == nearest)
            {
                tie = true;
                break;
            }
            nearest = k;
            tie = false;
            labelVector m(g);
            m[d] += step*(2*k - 1);
            label mn = -1;
            const label mk =
                (m[d] >= 0 && m[d] < N[d])
              ? boxKind(m, mn) : label(latticeMesh::WALL);
            if (!isLocal(ck) || (mk != latticeMesh::WALL && !isLocal(mk)))
            {
                image = -2;
                break;
            }
            image = isLocal(mk) ? mn : -1;
            s = vector::one;
            mirrorSign(sidePatch[2*d + (side ? 0 : 1)][cn], d, s);
            break;
        }
    }
    if (unknownFrom <= nearest)
    {
        return -2;
    }
    return tie ? -1 : image;
}


bool Foam::soilWalls::inReach(const labelVector& g) const
{
    const label rz = lattice_.twoD() ? 0 : reach_;
    for (label i = -reach_; i <= reach_; ++i)
    for (label j = -reach_; j <= reach_; ++j)
    for (label k = -rz; k <= rz; ++k)
    {
        label m = -1;
        if (boxKind(g + labelVector(i, j, k), m) == latticeMesh::OWNED)
        {
            return true;
        }
    }
    return false;
}


bool Foam::soilWalls::beyondBox(const labelVector& g) const
{
    // (not across a periodic direction: the halo wraps there)
    const labelVector& N = lattice_.globalN();
    for (direction d = 0; d < 3; ++d)
    {
        if (!lattice_.periodic()[d] && (g[d] < 0 || g[d] >= N[d]))
        {
            return true;
        }
    }
    return false;
}


Foam::label Foam::soilWalls::boxImage
(
    const labelVector& g,
    const List<labelList>& sidePatch,
    vector& s
) const
{
    // Reflect across every boundary plane the node lies beyond, again while
    // the image lies beyond the opposite plane (a domain thinner than the
    // shape function's reach: cubic B-splines reach two nodes beyond a
    // wall, across a domain one cell thick); not across a periodic
    // direction. reflections[d][side]: how often across the low (0) and
    // high (1) wall of axis d
    const labelVector& N = lattice_.globalN();
    labelVector r(g);
    label reflections[3][2] = {{0, 0}, {0, 0}, {0, 0}};
    for (direction d = 0; d < 3; ++d)
    {
        if (lattice_.periodic()[d])
        {
            continue;
        }
        while (r[d] < 0 || r[d] >= N[d])
        {
            if (r[d] < 0)
            {
                r[d] = -1 - r[d];
                ++reflections[d][0];
            }
            else
            {
                r[d] = 2*N[d] - 1 - r[d];
                ++reflections[d][1];
            }
        }
    }

    // (a halo node in parallel: what is folded onto it is then added to
    // its owner's, and it holds the owner's velocity)
    label src = -1;
    if (!isLocal(boxKind(r, src)))
    {
        return -1;
    }

    // The wall type of each reflection: from the boundary face of the cell
    // next to that wall on that axis
    const labelVector& bs = lattice_.boxStart();
    for (direction d = 0; d < 3; ++d)
    for (label side = 0; side < 2; ++side)
    for (label k = 0; k < reflections[d][side]; ++k)
    {
        labelVector c(r);
        c[d] = (side == 0 ? 0 : N[d] - 1);
        const labelVector cb = c - bs;
        const label cn = lattice_.node(cb.x(), cb.y(), cb.z());
        mirrorSign(sidePatch[2*d + side][cn], d, s);
    }
    return src;
}


Foam::label Foam::soilWalls::missingCellGhost
(
    const labelVector& g,
    const List<labelList>& sidePatch,
    vector& s
) const
{
    const label src = missingCellImage(g, sidePatch, s);
    if (src == -2 && inReach(g))
    {
        FatalErrorInFunction
            << "The node of missing cell " << g << " (global cell"
            << " indices) is within reach of this processor's points"
            << " but the mesh face it mirrors across, or its image,"
            << " lies beyond processor " << Pstream::myProcNo()
            << "'s halo (" << lattice_.haloWidth() << " cells) for "
            << shapeName_ << " (reach " << reach_ << ")." << nl
            << "    Use a shape function of reach 1 (linear, GIMP,"
            << " quadraticBSpline) on this mesh with missing cells,"
            << " or decompose it so that no processor boundary runs"
            << " within " << 3*reach_ << " cells of a missing cell."
            << exit(FatalError);
    }
    return src;
}


void Foam::soilWalls::buildGhosts()
{
    const List<labelList> sidePatch(sidePatches());
    const List<unsigned char>& kind = lattice_.kind();

    DynamicList<label> ghost, source;
    DynamicList<vector> sign;
    for (label n = 0; n < lattice_.nBox(); ++n)
    {
        if (kind[n] != latticeMesh::WALL)
        {
            continue;
        }
        const labelVector g = lattice_.globalIjk(n);
        vector s(vector::one);
        label src =
            beyondBox(g)
          ? boxImage(g, sidePatch, s)
          : missingCellGhost(g, sidePatch, s);    // (a stepped mesh)
        if (src < 0)
        {
            // No image (beyond a missing cell, or a corner of missing cells
            // with two faces equally near): at rest
            s = Zero;
            src = n;
        }
        ghost.append(n);
        source.append(src);
        sign.append(s);
    }
    ghostNode_.transfer(ghost);
    ghostSource_.transfer(source);
    ghostSign_.transfer(sign);
    ghostIjk_.setSize(ghostNode_.size());
    ghostReach_ = 0;
    forAll(ghostNode_, i)
    {
        ghostIjk_[i] = lattice_.boxIjk(ghostNode_[i]);
        const labelVector d = lattice_.boxIjk(ghostSource_[i]) - ghostIjk_[i];
        ghostReach_ = max(ghostReach_, cmptMax(cmptMag(d)));
    }

    // Box lookup: the node inside that each node beyond a wall folds into
    ghostImage_ = identity(lattice_.nBox());
    forAll(ghostNode_, i)
    {
        ghostImage_[ghostNode_[i]] = ghostSource_[i];
    }
}


void Foam::soilWalls::buildContacts()
{
    const List<FixedList<label, 6>>& cellFace = lattice_.cellBoundaryFace();
    const polyBoundaryMesh& patches = lattice_.mesh().boundaryMesh();

    DynamicList<label> cn;
    DynamicList<vector> cnormal;
    DynamicList<scalar> cmu;
    forAll(cellFace, celli)
    {
        for (label dir = 0; dir < 6; ++dir)
        {
            const label facei = cellFace[celli][dir];
            if (facei < 0)
            {
                continue;
            }
            const label patchi = patches.whichPatch(facei);
            if (patchWall_[patchi] != wallType::friction)
            {
                continue;
            }
            vector normal(Zero);
            normal[dir/2] = (dir % 2) ? 1 : -1;
            cn.append(lattice_.cellNode()[celli]);
            cnormal.append(normal);
            cmu.append(patchFriction_[patchi]);
        }
    }
    contactNode_.transfer(cn);
    contactIjk_.setSize(contactNode_.size());
    forAll(contactNode_, i)
    {
        contactIjk_[i] = lattice_.boxIjk(contactNode_[i]);
    }
    contactNormal_.transfer(cnormal);
    contactFriction_.transfer(cmu);
}


void Foam::soilWalls::cacheBox(const nodeBox& box) const
{
    if (cacheSet_ && box == cachedBox_)
    {
        return;
    }
    // (in the order of the whole lists: the folds add in the same order
    // whatever the box)
    auto select = [&](const List<labelVector>& ijk, labelList& out)
    {
        DynamicList<label> in(ijk.size());
        forAll(ijk, i)
        {
            if (box.contains(ijk[i]))
            {
                in.append(i);
            }
        }
        out.transfer(in);
    };
    select(ghostIjk_, cachedGhosts_);
    select(contactIjk_, cachedContacts_);
    cachedBox_ = box;
    cacheSet_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::soilWalls::soilWalls
(
    const latticeMesh& lattice,
    const dictionary& walls,
    const label reach,
    const word& shapeName
)
:
    lattice_(lattice),
    reach_(reach),
    shapeName_(shapeName),
    ghostReach_(0),
    cacheSet_(false),
    hasMissingCells_
    (
        returnReduce(lattice.mesh().nCells(), sumOp<label>())
      < lattice.globalN().x()*lattice.globalN().y()*lattice.globalN().z()
    )
{
    readWalls(walls);
    buildGhosts();
    buildContacts();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::soilWalls::fold(List<vector>& values, const nodeBox& box) const
{
    // The grid beyond a wall is the mirror image of the grid inside: what
    // the points gave to a node beyond the wall belongs, mirrored, to its
    // image inside (as if the points had mirror images beyond the wall).
    // Without this the nodes beyond a slip wall would carry part of the
    // weight of the points next to it: a spurious friction.
    for (const label i : ghostsIn(box))
    {
        const label w = ghostNode_[i];
        const label src = ghostSource_[i];
        if (src != w)
        {
            values[src] += cmptMultiply(ghostSign_[i], values[w]);
        }
        values[w] = Zero;
    }
}


void Foam::soilWalls::fold(scalarList& values, const nodeBox& box) const
{
    for (const label i : ghostsIn(box))
    {
        const label w = ghostNode_[i];
        const label src = ghostSource_[i];
        if (src != w)
        {
            values[src] += values[w];
        }
        values[w] = 0;
    }
}


void Foam::soilWalls::fold
(
    List<vector>& values,
    scalarList& mass,
    const nodeBox& box
) const
{
    // (an image is never itself beyond a wall: the two folds are
    // independent)
    fold(values, box);
    fold(mass, box);
}


void Foam::soilWalls::mirror(List<vector>& vel, const nodeBox& box) const
{
    for (const label i : ghostsIn(box))
    {
        vel[ghostNode_[i]] = cmptMultiply(ghostSign_[i], vel[ghostSource_[i]]);
    }
}


Foam::scalar Foam::soilWalls::maxFrictionCoefficient() const
{
    scalar mu = 0;
    forAll(patchWall_, patchi)
    {
        if (patchWall_[patchi] == wallType::friction)
        {
            mu = max(mu, patchFriction_[patchi]);
        }
    }
    return mu;
}


void Foam::soilWalls::applyContact
(
    List<vector>& vel,
    const scalarList& mass,
    const nodeBox& box
) const
{
    // Coulomb friction at the last node before a friction wall
    // (Bardenhagen, Brackbill & Sulsky 2000, CMAME 187, 529)
    for (const label i : contactsIn(box))
    {
        const label n = contactNode_[i];
        if (mass[n] <= VSMALL)
        {
            continue;
        }
        const vector& nw = contactNormal_[i];
        vector& v = vel[n];
        const scalar vn = v & nw;
        if (vn <= 0)
        {
            continue;
        }
        vector vt = v - vn*nw;
        const scalar magVt = mag(vt);
        const scalar reduce =
            magVt > VSMALL ? max(0.0, 1.0 - contactFriction_[i]*vn/magVt) : 0;
        v = reduce*vt;
    }
}


bool Foam::soilWalls::clamp(vector& x, const vector& xOld) const
{
    const scalar dx = lattice_.dx();
    const vector& o = lattice_.origin();
    const labelVector& N = lattice_.globalN();
    const direction nDir = lattice_.twoD() ? 2 : 3;
    const scalar eps = 1e-6*dx;
    bool moved = false;
    for (direction d = 0; d < nDir; ++d)
    {
        const scalar lo = o[d] + eps;
        const scalar hi = o[d] + N[d]*dx - eps;
        if (x[d] < lo)
        {
            x[d] = lo;
            moved = true;
        }
        else if (x[d] > hi)
        {
            x[d] = hi;
            moved = true;
        }
    }
    if (!hasMissingCells_)
    {
        return moved;
    }

    // A missing cell of the box (a stepped or L-shaped mesh): stop the
    // point at the face it crossed into it. It moves less than a cell per
    // sub-step, so it crossed at most one face per axis: first the faces
    // whose neighbour across is missing, then as below.
    if (isDomainCell(x))
    {
        return moved;
    }
    labelVector cOld(Zero), cNew(Zero);
    for (direction d = 0; d < nDir; ++d)
    {
        cOld[d] = label(std::floor((xOld[d] - o[d])/dx));
        cNew[d] = label(std::floor((x[d] - o[d])/dx));
    }
    auto stopAt = [&](const direction d)
    {
        // The face between the old and the new cell along d
        const scalar face = o[d] + max(cOld[d], cNew[d])*dx;
        x[d] = (cNew[d] > cOld[d]) ? face - eps : face + eps;
        cNew[d] = cOld[d];
    };
    for (direction d = 0; d < nDir; ++d)
    {
        if (cNew[d] != cOld[d])
        {
            vector across(xOld);
            across[d] = x[d];
            if (!isDomainCell(across))
            {
                stopAt(d);
            }
        }
    }
    // Only a diagonal cell missing (a convex corner of the missing cells):
    // stop the crossing it overshot least, then the next, until the point
    // is in a cell of the mesh (at the latest in its old cell)
    while (!isDomainCell(x))
    {
        direction best = 0;
        scalar least = GREAT;
        for (direction d = 0; d < nDir; ++d)
        {
            if (cNew[d] != cOld[d])
            {
                const scalar face = o[d] + max(cOld[d], cNew[d])*dx;
                if (mag(x[d] - face) < least)
                {
                    least = mag(x[d] - face);
                    best = d;
                }
            }
        }
        if (least == GREAT)
        {
            // (the old cell itself is missing: cannot happen for points
            // seeded in the mesh and kept out since)
            break;
        }
        stopAt(best);
    }
    return true;
}


bool Foam::soilWalls::isDomainCell(const vector& x) const
{
    const label n = cellNodeOf(x);
    // (beyond this processor's box: its owner judges it; the migration
    // check stops a point that jumps that far)
    if (n < 0)
    {
        return true;
    }
    return isLocal(lattice_.kind()[n]);
}


Foam::label Foam::soilWalls::cellNodeOf(const vector& x) const
{
    const scalar dx = lattice_.dx();
    const vector& o = lattice_.origin();
    const labelVector& bs = lattice_.boxStart();
    const labelVector& bn = lattice_.boxN();
    labelVector b(Zero);
    for (direction d = 0; d < (lattice_.twoD() ? 2 : 3); ++d)
    {
        b[d] = label(std::floor((x[d] - o[d])/dx)) - bs[d];
        if (b[d] < 0 || b[d] >= bn[d])
        {
            return -1;
        }
    }
    return lattice_.node(b.x(), b.y(), b.z());
}


// ************************************************************************* //
