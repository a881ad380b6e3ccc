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

#include "materialPointSoil.H"
#include "volFields.H"
#include "emptyPolyPatch.H"
#include "DynamicList.H"
#include "packedDouble4.H"
#include "linearShapeFunction.H"
#include "GIMP.H"
#include "quadraticBSpline.H"
#include "cubicBSpline.H"

#include <type_traits>
#include <cstdint>
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(materialPointSoil, 0);
}

const Foam::Enum<Foam::materialPointSoil::transferType>
Foam::materialPointSoil::transferTypeNames
({
    { transferType::PIC, "PIC" },
    { transferType::FLIP, "FLIP" },
    { transferType::APIC, "APIC" },
});

const Foam::Enum<Foam::materialPointSoil::updateType>
Foam::materialPointSoil::updateTypeNames
({
    { updateType::USL, "USL" },
    { updateType::USF, "USF" },
    { updateType::MUSL, "MUSL" },
});

const Foam::Enum<Foam::materialPointSoil::wallType>
Foam::materialPointSoil::wallTypeNames
({
    { wallType::slip, "slip" },
    { wallType::noSlip, "noSlip" },
    { wallType::friction, "friction" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// An enumerated entry, refused with the keyword, the value and the choices
template<class EnumType>
EnumType selectEntry
(
    const Foam::Enum<EnumType>& names,
    const Foam::word& key,
    const Foam::dictionary& dict,
    const bool optional = false,
    const EnumType deflt = EnumType(0)
)
{
    if (optional && !dict.found(key))
    {
        return deflt;
    }
    const Foam::word value(dict.get<Foam::word>(key));
    if (!names.found(value))
    {
        FatalIOErrorInFunction(dict)
            << key << " " << value << " is not allowed: choose one of "
            << names.sortedToc() << Foam::exit(Foam::FatalIOError);
    }
    return names[value];
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::materialPointSoil::readMaterials()
{
    const dictionary& mats = dict_.subDict("materials");
    materialNames_ = mats.toc();
    if (materialNames_.empty())
    {
        FatalIOErrorInFunction(mats)
            << "materials is empty: the soil needs at least one material"
            << exit(FatalIOError);
    }
    materials_.setSize(materialNames_.size());
    forAll(materialNames_, i)
    {
        materials_.set
        (
            i,
            constitutiveModel::New
            (
                materialNames_[i],
                mats.subDict(materialNames_[i])
            )
        );
    }
}


void Foam::materialPointSoil::readWalls()
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const dictionary& walls = dict_.subDict("walls");

    patchWall_.setSize(patches.size(), wallType::slip);
    patchFriction_.setSize(patches.size(), 0.0);

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


void Foam::materialPointSoil::buildGhosts()
{
    const List<unsigned char>& kind = lattice_.kind();
    const labelVector& N = lattice_.globalN();
    const labelVector& bs = lattice_.boxStart();
    const labelVector& bn = lattice_.boxN();
    const List<FixedList<label, 6>>& cellFace = lattice_.cellBoundaryFace();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const FixedList<bool, 3>& periodic = lattice_.periodic();

    // The patch of the boundary face on each side (-x, +x, -y, +y, -z, +z)
    // of the cell of every node, -1 where there is none. In parallel also
    // at the halo nodes: a node beyond a wall near a processor boundary
    // mirrors a node of the neighbour. (The patches a decomposition keeps
    // have the same index on every processor.)
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

    // Compose into s the mirror across a wall normal to axis d of patch
    // patchi (-1: no face known, taken as noSlip): a slip wall reverses the
    // normal component, a noSlip wall every component. Beyond a friction
    // wall the node copies the node inside, which thereby carries the whole
    // load on the wall and meets it through the Coulomb contact
    auto mirror = [&](const label patchi, const direction d, vector& s)
    {
        const wallType wt =
            patchi >= 0 ? patchWall_[patchi] : wallType::noSlip;
        if (wt == wallType::noSlip)
        {
            s = -s;
        }
        else if (wt == wallType::slip)
        {
            s[d] = -s[d];
        }
    };

    // The kind of the node at global cell indices c of this box (-1 beyond
    // the box) and the node itself
    auto boxKind = [&](const labelVector& c, label& m) -> label
    {
        const labelVector b = c - bs;
        for (direction d = 0; d < 3; ++d)
        {
            if (b[d] < 0 || b[d] >= bn[d])
            {
                return -1;
            }
        }
        m = lattice_.node(b.x(), b.y(), b.z());
        return kind[m];
    };
    auto isLocal = [](const label k)
    {
        return k == latticeMesh::OWNED || k == latticeMesh::HALO;
    };

    // The image of the node (global indices g) of a missing cell: across
    // the face of the nearest cell of the mesh along an axis, within the
    // shape function's reach, with that face's wall condition (sign s as at
    // the box's walls). None (-1) where two faces are equally near (the
    // corner of a step) or the mesh beyond the face is too thin for the
    // image. Undetermined here (-2) where the nearest face or the image
    // lies beyond this processor's box or halo (a cell another processor
    // owns, not in the halo: UNUSED).
    const label reach = shape_->reach();
    auto missingCellImage = [&](const labelVector& g, vector& s) -> label
    {
        label nearest = reach + 1, image = -1, unknownFrom = reach + 1;
        bool tie = false;
        for (direction d = 0; d < (lattice_.twoD() ? 2 : 3); ++d)
        for (label side = 0; side < 2; ++side)
        {
            const label step = side ? 1 : -1;
            for (label k = 1; k <= min(reach, nearest); ++k)
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
                mirror(sidePatch[2*d + (side ? 0 : 1)][cn], d, s);
                break;
            }
        }
        if (unknownFrom <= nearest)
        {
            return -2;
        }
        return tie ? -1 : image;
    };

    // Could a point of this processor reach the node (global indices g)?
    auto inReach = [&](const labelVector& g)
    {
        const label rz = lattice_.twoD() ? 0 : reach;
        for (label i = -reach; i <= reach; ++i)
        for (label j = -reach; j <= reach; ++j)
        for (label k = -rz; k <= rz; ++k)
        {
            label m = -1;
            if (boxKind(g + labelVector(i, j, k), m) == latticeMesh::OWNED)
            {
                return true;
            }
        }
        return false;
    };

    DynamicList<label> ghost, source;
    DynamicList<vector> sign;

    for (label n = 0; n < lattice_.nBox(); ++n)
    {
        if (kind[n] != latticeMesh::WALL)
        {
            continue;
        }
        const labelVector g = lattice_.globalIjk(n);
        labelVector r(g);
        vector s(vector::one);
        bool reflected = false;

        // Reflect across every boundary plane the node lies beyond, again
        // while the image lies beyond the opposite plane (a domain thinner
        // than the shape function's reach: cubic B-splines reach two nodes
        // beyond a wall, across a domain one cell thick); not across a
        // periodic direction: the halo wraps there
        // reflections[d][side]: how often across the low (0) and high (1)
        // wall of axis d
        label reflections[3][2] = {{0, 0}, {0, 0}, {0, 0}};
        for (direction d = 0; d < 3; ++d)
        {
            if (periodic[d])
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
                reflected = true;
            }
        }

        label src = -1;
        if (reflected)
        {
            const labelVector b = r - bs;
            if
            (
                b.x() >= 0 && b.y() >= 0 && b.z() >= 0
             && b.x() < bn.x() && b.y() < bn.y() && b.z() < bn.z()
            )
            {
                // (a halo node in parallel: what is folded onto it is then
                // added to its owner's, and it holds the owner's velocity)
                src = lattice_.node(b.x(), b.y(), b.z());
                if
                (
                    kind[src] != latticeMesh::OWNED
                 && kind[src] != latticeMesh::HALO
                )
                {
                    src = -1;
                }
            }
        }

        if (!reflected)
        {
            // A node of a missing cell inside the box (a stepped mesh)
            src = missingCellImage(g, s);
            if (src == -2 && inReach(g))
            {
                FatalErrorInFunction
                    << "The node of missing cell " << g << " (global cell"
                    << " indices) is within reach of this processor's points"
                    << " but the mesh face it mirrors across, or its image,"
                    << " lies beyond processor " << Pstream::myProcNo()
                    << "'s halo (" << lattice_.haloWidth() << " cells) for "
                    << shape_->type() << " (reach " << reach << ")." << nl
                    << "    Use a shape function of reach 1 (linear, GIMP,"
                    << " quadraticBSpline) on this mesh with missing cells,"
                    << " or decompose it so that no processor boundary runs"
                    << " within " << 3*reach << " cells of a missing cell."
                    << exit(FatalError);
            }
        }
        else if (src >= 0)
        {
            // The wall type of each reflection: from the boundary face of
            // the cell next to that wall on that axis
            for (direction d = 0; d < 3; ++d)
            for (label side = 0; side < 2; ++side)
            for (label k = 0; k < reflections[d][side]; ++k)
            {
                labelVector c(r);
                c[d] = (side == 0 ? 0 : N[d] - 1);
                const labelVector cb = c - bs;
                const label cn = lattice_.node(cb.x(), cb.y(), cb.z());
                const label dir = 2*d + side;
                mirror(sidePatch[dir][cn], d, s);
            }
        }
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

    // Box lookup: the node inside that each node beyond a wall folds into
    ghostImage_.setSize(lattice_.nBox());
    forAll(ghostImage_, n)
    {
        ghostImage_[n] = n;
    }
    forAll(ghostNode_, i)
    {
        ghostImage_[ghostNode_[i]] = ghostSource_[i];
    }
    ghostSign_.transfer(sign);

    // Friction contact nodes
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
    contactNormal_.transfer(cnormal);
    contactFriction_.transfer(cmu);
}


inline Foam::vector Foam::materialPointSoil::latticeCoordinates
(
    const vector& x
) const
{
    const scalar dx = lattice_.dx();
    const vector& o = lattice_.origin();
    const labelVector& bs = lattice_.boxStart();
    return vector
    (
        (x.x() - o.x())/dx - 0.5 - bs.x(),
        (x.y() - o.y())/dx - 0.5 - bs.y(),
        lattice_.twoD() ? 0 : (x.z() - o.z())/dx - 0.5 - bs.z()
    );
}


Foam::scalar Foam::materialPointSoil::pWaveSpeed() const
{
    // (with an added modulus, e.g. the pore water's when the soil is
    // undrained: Biot's undrained modulus M + K_f/n)
    scalar cp = 0;
    forAll(materials_, i)
    {
        cp = max
        (
            cp,
            std::sqrt
            (
                sqr(materials_[i].pWaveSpeed())
              + addedModulus_/materials_[i].rho()
            )
        );
    }
    return cp;
}


Foam::scalar Foam::materialPointSoil::stableDt() const
{
    const scalar cp = pWaveSpeed();
    scalar vmax = 0;
    label fastest = -1;
    forAll(points_.v, p)
    {
        const scalar v2 = magSqr(points_.v[p]);
        if (!(v2 <= vmax))
        {
            vmax = v2;
            fastest = p;
        }
    }
    // A point ten times faster than the fastest p-wave has left the range
    // an explicit MPM step resolves (or is not finite): stop before
    // anything non-finite is written
    if (fastest >= 0 && !(std::sqrt(vmax) < maxSpeed_))
    {
        FatalErrorInFunction
            << "The soil went unstable at time " << mesh_.time().timeName()
            << " s: material point " << points_.id[fastest]
            << " (origId) at "
            << points_.x[fastest] << " moves at " << std::sqrt(vmax)
            << " m/s, above " << maxSpeed_ << " m/s (ten times the largest"
            << " p-wave speed of the materials)." << nl
            << "    Lower soilCFL in system/controlDict (now " << CFL_
            << "), or check the loads the couplings put on the soil."
            << " Nothing of this step was written." << exit(FatalError);
    }
    // (every processor takes the same sub-steps)
    reduce(vmax, maxOp<scalar>());
    return CFL_*lattice_.dx()/(cp + std::sqrt(vmax));
}


void Foam::materialPointSoil::checkPeriodicReach() const
{
    // The soil's grid does not wrap around cyclic patches: a point whose
    // shape function would reach across one is refused (the water may be
    // periodic around a soil body that stays clear of the seam)
    const labelVector& N = lattice_.globalN();
    const vector& o = lattice_.origin();
    const scalar dx = lattice_.dx();
    const scalar clear = (shape_->reach() + 1)*dx;
    for (direction d = 0; d < 3; ++d)
    {
        if (!lattice_.periodic()[d])
        {
            continue;
        }
        forAll(points_.x, p)
        {
            const scalar x = points_.x[p][d];
            if (x < o[d] + clear || x > o[d] + N[d]*dx - clear)
            {
                FatalErrorInFunction
                    << "Material point " << p << " at " << points_.x[p]
                    << " is within " << clear << " m of the cyclic patches"
                    << " normal to " << vector::componentNames[d]
                    << " at time " << mesh_.time().timeName() << " s" << nl
                    << "    The soil's grid does not wrap around cyclic"
                    << " patches: keep the soil " << shape_->reach() + 1
                    << " cells clear of them, or use walls"
                    << exit(FatalError);
            }
        }
    }
}


template<class Shape, Foam::label D>
inline void Foam::materialPointSoil::pointWeights
(
    const label p,
    const vector& xl,
    shapeWeights& sw
) const
{
    tensorProductWeights<Shape, D>
    (
        xl,
        Shape::usesHalfLength ? points_.halfLength[p] : vector::zero,
        sw
    );
}


inline void Foam::materialPointSoil::pointWeights
(
    const label p,
    shapeWeights& sw
) const
{
    shape_->weights
    (
        latticeCoordinates(points_.x[p]),
        points_.halfLength[p],
        lattice_.nDim(),
        sw
    );
}


namespace
{
//- Bounds of a point's volume over its initial volume (det F): beyond a
//  thousandfold squeeze or stretch (or inverted) a point is a run gone
//  unstable, not soil, and the run stops before its deformation gradient
//  overflows
constexpr Foam::scalar minVolumeRatio = 1e-3;
constexpr Foam::scalar maxVolumeRatio = 1e3;

} // End anonymous namespace


void Foam::materialPointSoil::volumeRunaway
(
    const label p,
    const scalar J
) const
{
    FatalErrorInFunction
        << "The soil went unstable at time " << mesh_.time().timeName()
        << " s: material point " << points_.id[p] << " (origId) at "
        << points_.x[p] << " has " << J << " times its initial volume"
        << " (det F; allowed: " << minVolumeRatio << " to " << maxVolumeRatio
        << "), moving at " << mag(points_.v[p]) << " m/s." << nl
        << "    Its deformation gradient runs away: lower soilCFL in"
        << " system/controlDict (now " << CFL_ << "), "
        << (
               shape_->type() == "linear"
             ? "use a smoother shapeFunction than linear (quadraticBSpline"
               " or GIMP: with linear shape functions a point crossing a"
               " cell face at speed makes its velocity gradient jump), "
             : ""
           )
        << "or check the loads the couplings put on the soil (an impact"
        << " this fast splashes the points apart). Nothing of this step was"
        << " written."
        << exit(FatalError);
}


inline void Foam::materialPointSoil::updateVolume(const label p)
{
    // The grains are incompressible: the solid volume (1 - n) V of a point
    // is kept as it dilates or compacts, so its porosity n changes (a
    // point never holds more grains than its volume)
    const scalar Vold = points_.V[p];
    const scalar J = det(points_.F[p]);
    if (!(J > minVolumeRatio && J < maxVolumeRatio))
    {
        volumeRunaway(p, J);
    }
    points_.V[p] = J*points_.V0[p];
    points_.porosity[p] =
        max(1 - (1 - points_.porosity[p])*Vold/points_.V[p], 0.0);
}


// * * * * * * * * * * * * * * * * Point loops * * * * * * * * * * * * * * * //

namespace
{

template<Foam::label N>
using labelConstant = std::integral_constant<Foam::label, N>;

//- A shape function model as a type, to pass to a generic lambda
template<class Shape>
struct shapeTag
{
    typedef Shape type;
};

//- Call k(shapeTag<Shape>, D) with the model of the shape function and the
//  dimension D as compile-time constants, so that the kernels' weights
//  inline and their node loops unroll
template<Foam::label D, class Kernel>
inline void withShapeIn(const Foam::shapeFunction& shape, Kernel&& k)
{
    using namespace Foam::shapeFunctions;
    if (Foam::isA<quadraticBSpline>(shape))
    {
        k(shapeTag<quadraticBSpline>(), labelConstant<D>());
    }
    else if (Foam::isA<cubicBSpline>(shape))
    {
        k(shapeTag<cubicBSpline>(), labelConstant<D>());
    }
    else if (Foam::isA<GIMP>(shape))
    {
        k(shapeTag<GIMP>(), labelConstant<D>());
    }
    else if (Foam::isA<linear>(shape))
    {
        k(shapeTag<linear>(), labelConstant<D>());
    }
    else
    {
        FatalErrorInFunction
            << "No transfer kernel for shape function " << shape.type()
            << " (linear, GIMP, quadraticBSpline and cubicBSpline are built)"
            << Foam::abort(Foam::FatalError);
    }
}

template<class Kernel>
inline void withShape
(
    const Foam::shapeFunction& shape,
    const Foam::label D,
    Kernel&& k
)
{
    if (D == 3)
    {
        withShapeIn<3>(shape, k);
    }
    else
    {
        withShapeIn<2>(shape, k);
    }
}

//- Points per block of the grid-to-point loop: the block's constitutive
//  update follows it while its stresses and strain increments are in the
//  cache (512 points: 24 kB of increments)
constexpr Foam::label pointBlock = 512;

//- Four and eight doubles as one SIMD value, loaded and stored in place
typedef Foam::packed::double4InPlace v4d;
typedef Foam::packed::double8InPlace v8d;

inline v4d v4(const double a, const double b, const double c, const double d)
{
    return v4d{a, b, c, d};
}

inline v8d v8(const v4d lo, const v4d hi)
{
    return v8d{lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]};
}

//- The first address at or after p on a 64-byte boundary (a cache line):
//  the node records and padded velocities start there, so that no record
//  or velocity straddles two lines
inline double* cacheLineAligned(double* p)
{
    const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
    return reinterpret_cast<double*>((a + 63) & ~std::uintptr_t(63));
}

//- The sums of one point over its support nodes: vPic = sum N v_n,
//  Lx, Ly, Lz = the columns of sum v_n gradN (lattice units) and, for FLIP,
//  dv = sum N (v_n - v_n,old). Along a row of nodes the sums of w_x v_n
//  and w'_x v_n serve every term: six multiply-adds per node, each one
//  SIMD operation on a node velocity padded to four doubles (vel4)
template<Foam::label S, Foam::label D, bool Flip>
inline void supportSums
(
    const Foam::shapeWeights& sw,
    const Foam::label base,
    const Foam::label sy,
    const Foam::label sz,
    const double* __restrict__ vel4,
    const double* __restrict__ velOld4,
    Foam::vector& vPic,
    Foam::vector& dv,
    Foam::vector& Lx,
    Foam::vector& Ly,
    Foam::vector& Lz
)
{
    using namespace Foam;
    constexpr label SZ = (D == 3 ? S : 1);
    const scalar* wx = sw.w[0];
    const scalar* dwx = sw.dw[0];
    v4d sPic = v4(0, 0, 0, 0), sDv = sPic, sLx = sPic, sLy = sPic, sLz = sPic;
    for (label c = 0; c < SZ; ++c)
    {
        const scalar wz = sw.w[2][c];
        const scalar dwz = sw.dw[2][c];
        for (label b = 0; b < S; ++b)
        {
            const scalar wy = sw.w[1][b];
            const label row = base + b*sy + c*sz;
            v4d sumW = v4(0, 0, 0, 0), sumDw = sumW, sumDv = sumW;
            for (label a = 0; a < S; ++a)
            {
                const v4d vn = *reinterpret_cast<const v4d*>(vel4 + 4*(row + a));
                sumW += wx[a]*vn;
                sumDw += dwx[a]*vn;
                if constexpr (Flip)
                {
                    sumDv +=
                        wx[a]
                       *(vn - *reinterpret_cast<const v4d*>(velOld4 + 4*(row + a)));
                }
            }
            const scalar wyz = wy*wz;
            sPic += wyz*sumW;
            sLx += wyz*sumDw;
            sLy += (sw.dw[1][b]*wz)*sumW;
            if constexpr (D == 3)
            {
                sLz += (wy*dwz)*sumW;
            }
            if constexpr (Flip)
            {
                sDv += wyz*sumDv;
            }
        }
    }
    vPic = vector(sPic[0], sPic[1], sPic[2]);
    Lx = vector(sLx[0], sLx[1], sLx[2]);
    Ly = vector(sLy[0], sLy[1], sLy[2]);
    Lz = vector(sLz[0], sLz[1], sLz[2]);
    if constexpr (Flip)
    {
        dv = vector(sDv[0], sDv[1], sDv[2]);
    }
}

//- The velocity gradient L = sum v_n gradN/dx of a point with weights sw,
//  and its sums vPic and (FLIP) dv, from supportSums
template<Foam::label S, Foam::label D, bool Flip>
inline Foam::tensor velocityGradient
(
    const Foam::shapeWeights& sw,
    const Foam::latticeMesh& lattice,
    const Foam::scalar invDx,
    const double* __restrict__ vel4,
    const double* __restrict__ velOld4,
    Foam::vector& vPic,
    Foam::vector& dv
)
{
    Foam::vector Lx, Ly, Lz;
    supportSums<S, D, Flip>
    (
        sw,
        lattice.node(sw.first.x(), sw.first.y(), sw.first.z()),
        lattice.stride().y(), lattice.stride().z(),
        vel4, velOld4, vPic, dv, Lx, Ly, Lz
    );
    return Foam::tensor
    (
        invDx*Lx.x(), invDx*Ly.x(), invDx*Lz.x(),
        invDx*Lx.y(), invDx*Ly.y(), invDx*Lz.y(),
        invDx*Lx.z(), invDx*Ly.z(), invDx*Lz.z()
    );
}

//- Node velocities padded to four doubles per node, from the first cache
//  line boundary of vel4 on (returned)
inline const double* padVelocities
(
    const Foam::List<Foam::vector>& vel,
    Foam::scalarList& vel4
)
{
    const Foam::label n = vel.size();
    vel4.setSize(4*n + 8);
    double* __restrict__ out = cacheLineAligned(vel4.data());
    const Foam::vector* __restrict__ in = vel.cdata();
    for (Foam::label i = 0; i < n; ++i)
    {
        out[4*i] = in[i].x();
        out[4*i + 1] = in[i].y();
        out[4*i + 2] = in[i].z();
        out[4*i + 3] = 0;
    }
    return out;
}

//- Column j of a tensor
inline Foam::vector column(const Foam::tensor& T, const Foam::direction j)
{
    return Foam::vector(T(0, j), T(1, j), T(2, j));
}

} // End anonymous namespace




template<class Shape, Foam::label D, bool Apic, bool Forces>
void Foam::materialPointSoil::p2gPoints(const vector& g)
{
    // Per node of point p, weight N = wx wy wz, gradient (lattice units)
    // gradN = (w'x wy wz, wx w'y wz, wx wy w'z):
    //     mass     += N m
    //     momentum += N m (v + C r),  r = node - point  (APIC; else N m v)
    //     force    += N m g (+ N f_ext) - V sigma.gradN/dx
    // The point's factors are formed once per point (A_a, B_a for the S
    // nodes a of a row) and per row (R), so that each node takes one
    // contiguous update of its record (mass, momentum | force, 0):
    //     rec += wx_a (wyz A_a + R) + wyz B_a
    // A_a = (m, m v + C r_x(a) m dx | m g + f_ext, 0),
    // R   = (0, wyz m C (r_y, r_z) dx | -V sigma.(w'y wz, wy w'z)/dx, 0),
    // B_a = (0, 0 | -V sigma.e_x w'x_a/dx, 0).
    constexpr label S = Shape::supportSize;
    constexpr label SZ = (D == 3 ? S : 1);
    constexpr label W = (Forces ? 8 : 4);
    const scalar dx = lattice_.dx();
    const scalar invDx = 1.0/dx;
    const label sy = lattice_.stride().y();
    const label sz = lattice_.stride().z();
    const vector* fExt = pointForce_.size() ? pointForce_.cdata() : nullptr;
    const label nBox = gridMass_.size();

    // (sized once for 8 values per node, whatever W: MUSL maps with and
    // without forces in one sub-step)
    p2gScratch_.setSize(8*nBox + 8);
    scalar* __restrict__ rec = cacheLineAligned(p2gScratch_.data());
    std::fill(rec, rec + W*nBox, 0.0);

    const label nPoints = points_.size();
    for (label p = 0; p < nPoints; ++p)
    {
        const vector xl(latticeCoordinates(points_.x[p]));
        shapeWeights sw;
        pointWeights<Shape, D>(p, xl, sw);
        const scalar mp = points_.m[p];
        const vector mv(mp*points_.v[p]);
        const scalar* wx = sw.w[0];
        const scalar* dwx = sw.dw[0];

        v4d Alo[S];
        v8d A8[S], B8[S];
        tensor mCdx(Zero);
        scalar ry[S], rz[SZ];
        if constexpr (Apic)
        {
            mCdx = (mp*dx)*points_.C[p];
            const vector cx(column(mCdx, 0));
            for (label a = 0; a < S; ++a)
            {
                const vector momA(mv + cx*(sw.first.x() + a - xl.x()));
                Alo[a] = v4(mp, momA.x(), momA.y(), momA.z());
                ry[a] = sw.first.y() + a - xl.y();
            }
            for (label c = 0; c < SZ; ++c)
            {
                rz[c] = sw.first.z() + c - xl.z();
            }
        }
        else
        {
            for (label a = 0; a < S; ++a)
            {
                Alo[a] = v4(mp, mv.x(), mv.y(), mv.z());
            }
        }

        vector By(Zero), Bz(Zero);
        if constexpr (Forces)
        {
            const vector mg(fExt ? mp*g + fExt[p] : mp*g);
            const symmTensor Bs(-(points_.V[p]*invDx)*points_.sigma[p]);
            By = vector(Bs.xy(), Bs.yy(), Bs.yz());
            Bz = vector(Bs.xz(), Bs.yz(), Bs.zz());
            for (label a = 0; a < S; ++a)
            {
                A8[a] = v8(Alo[a], v4(mg.x(), mg.y(), mg.z(), 0));
                B8[a] = v8
                (
                    v4(0, 0, 0, 0),
                    v4(Bs.xx(), Bs.xy(), Bs.xz(), 0)*dwx[a]
                );
            }
        }

        const label base = lattice_.node(sw.first.x(), sw.first.y(), sw.first.z());
        for (label c = 0; c < SZ; ++c)
        {
            const scalar wz = sw.w[2][c];
            const scalar dwz = sw.dw[2][c];
            for (label b = 0; b < S; ++b)
            {
                const scalar wy = sw.w[1][b];
                const scalar wyz = wy*wz;
                const label row = base + b*sy + c*sz;

                v4d Rlo = v4(0, 0, 0, 0);
                if constexpr (Apic)
                {
                    const vector momRow
                    (
                        wyz
                       *(
                            column(mCdx, 1)*ry[b]
                          + (D == 3 ? column(mCdx, 2)*rz[c] : vector::zero)
                        )
                    );
                    Rlo = v4(0, momRow.x(), momRow.y(), momRow.z());
                }
                v4d Rhi = v4(0, 0, 0, 0);
                if constexpr (Forces)
                {
                    vector forceRow(By*(sw.dw[1][b]*wz));
                    if constexpr (D == 3)
                    {
                        forceRow += Bz*(wy*dwz);
                    }
                    Rhi = v4(forceRow.x(), forceRow.y(), forceRow.z(), 0);
                }

                scalar* __restrict__ r = rec + W*row;
                if constexpr (Forces)
                {
                    // The whole record at once: (A_a, B_a) as eight values
                    // (B_a's lower half zero)
                    const v8d R = v8(Rlo, Rhi);
                    for (label a = 0; a < S; ++a)
                    {
                        v8d* node = reinterpret_cast<v8d*>(r + W*a);
                        *node += wx[a]*(wyz*A8[a] + R) + wyz*B8[a];
                    }
                }
                else
                {
                    for (label a = 0; a < S; ++a)
                    {
                        v4d* lo = reinterpret_cast<v4d*>(r + W*a);
                        *lo += wx[a]*(wyz*Alo[a] + Rlo);
                    }
                }
            }
        }
    }

    // To the grid arrays, all three set (the force zero without forces:
    // USF adds it after the stress update)
    for (label n = 0; n < nBox; ++n)
    {
        const scalar* rn = rec + W*n;
        gridMass_[n] = rn[0];
        gridMomentum_[n] = vector(rn[1], rn[2], rn[3]);
        if constexpr (Forces)
        {
            gridForce_[n] = vector(rn[4], rn[5], rn[6]);
        }
        else
        {
            gridForce_[n] = Zero;
        }
    }
}


template<class Shape, Foam::label D>
void Foam::materialPointSoil::p2gForcePoints(const vector& g)
{
    // The force part of p2gPoints (USF: after the stress update)
    constexpr label S = Shape::supportSize;
    constexpr label SZ = (D == 3 ? S : 1);
    const scalar invDx = 1.0/lattice_.dx();
    const label sy = lattice_.stride().y();
    const label sz = lattice_.stride().z();
    const vector* fExt = pointForce_.size() ? pointForce_.cdata() : nullptr;
    vector* __restrict__ force = gridForce_.data();

    const label nPoints = points_.size();
    for (label p = 0; p < nPoints; ++p)
    {
        shapeWeights sw;
        pointWeights<Shape, D>(p, latticeCoordinates(points_.x[p]), sw);
        const scalar mp = points_.m[p];
        const vector mg(fExt ? mp*g + fExt[p] : mp*g);
        const symmTensor B(-(points_.V[p]*invDx)*points_.sigma[p]);
        const vector Bx(B.xx(), B.xy(), B.xz());
        const vector By(B.xy(), B.yy(), B.yz());
        const vector Bz(B.xz(), B.yz(), B.zz());
        const scalar* wx = sw.w[0];
        vector forceA[S];
        for (label a = 0; a < S; ++a)
        {
            forceA[a] = Bx*sw.dw[0][a];
        }
        const label base = lattice_.node(sw.first.x(), sw.first.y(), sw.first.z());
        for (label c = 0; c < SZ; ++c)
        {
            const scalar wz = sw.w[2][c];
            const scalar dwz = sw.dw[2][c];
            for (label b = 0; b < S; ++b)
            {
                const scalar wy = sw.w[1][b];
                const scalar wyz = wy*wz;
                vector forceRow(By*(sw.dw[1][b]*wz));
                if constexpr (D == 3)
                {
                    forceRow += Bz*(wy*dwz);
                }
                const label row = base + b*sy + c*sz;
                for (label a = 0; a < S; ++a)
                {
                    force[row + a] +=
                        (wx[a]*wyz)*mg + wyz*forceA[a] + wx[a]*forceRow;
                }
            }
        }
    }
}


template<class Shape, Foam::label D, bool Flip>
void Foam::materialPointSoil::g2pPoints(const scalar dt)
{
    // Per point: v = sum N v_n, L = sum v_n gradN/dx (and FLIP's
    // sum N (v_n - v_n,old)), from supportSums; in blocks of pointBlock
    // points, each followed by its constitutive update (USL)
    constexpr label S = Shape::supportSize;
    const scalar invDx = 1.0/lattice_.dx();
    const bool stressHere = (update_ == updateType::USL);
    const bool apic = (transfer_ == transferType::APIC);
    const bool parallel = Pstream::parRun();
    const scalar alpha = flipRatio_;
    const double* vel = padVelocities(gridVelocity_, velocity4_);
    const double* velOld =
        Flip ? padVelocities(gridVelocityOld_, velocityOld4_) : nullptr;
    symmTensor* dStrain = strainIncrement_.data();
    leavingPoint_.clear();
    leavingProc_.clear();

    const label nPoints = points_.size();
    for (label start = 0; start < nPoints; start += pointBlock)
    {
        const label end = min(start + pointBlock, nPoints);
        for (label p = start; p < end; ++p)
        {
            shapeWeights sw;
            pointWeights<Shape, D>(p, latticeCoordinates(points_.x[p]), sw);
            vector vPic, dv(Zero);
            const tensor L
            (
                velocityGradient<S, D, Flip>
                (
                    sw, lattice_, invDx, vel, velOld, vPic, dv
                )
            );

            if constexpr (Flip)
            {
                points_.v[p] = alpha*(points_.v[p] + dv) + (1 - alpha)*vPic;
            }
            else
            {
                points_.v[p] = vPic;
                if (apic)
                {
                    points_.C[p] = L;
                }
            }

            if (stressHere)
            {
                updatePointStress(p, L, dt, dStrain[p - start]);
            }

            const vector xOld(points_.x[p]);
            points_.x[p] += dt*vPic;
            if (clamp(points_.x[p], xOld))
            {
                if (nClamped_++ == 0)
                {
                    firstClamped_ = points_.id[p];
                    firstClampedAt_ = points_.x[p];
                    firstClampedSpeed_ = mag(vPic);
                }
            }
            if (parallel)
            {
                noteLeaving(p);
            }
        }

        if (stressHere)
        {
            updateConstitutive(start, end);
        }
    }
}


template<class Shape, Foam::label D>
void Foam::materialPointSoil::stressPoints
(
    const List<vector>& vel,
    const scalar dt
)
{
    constexpr label S = Shape::supportSize;
    const scalar invDx = 1.0/lattice_.dx();
    const double* vel4 = padVelocities(vel, velocity4_);
    symmTensor* dStrain = strainIncrement_.data();
    const label nPoints = points_.size();
    for (label start = 0; start < nPoints; start += pointBlock)
    {
        const label end = min(start + pointBlock, nPoints);
        for (label p = start; p < end; ++p)
        {
            shapeWeights sw;
            pointWeights<Shape, D>(p, latticeCoordinates(points_.x[p]), sw);
            vector vPic, dv(Zero);
            updatePointStress
            (
                p,
                velocityGradient<S, D, false>
                (
                    sw, lattice_, invDx, vel4, nullptr, vPic, dv
                ),
                dt,
                dStrain[p - start]
            );
        }
        updateConstitutive(start, end);
    }
}


inline void Foam::materialPointSoil::updatePointStress
(
    const label p,
    const tensor& L,
    const scalar dt,
    symmTensor& dStrain
)
{
    // Jaumann rotation now, the constitutive update after the block
    // (updateConstitutive: it needs nothing else of this point's update).
    // With the spin W = skew(L) = [0 a b; -a 0 c; -b -c 0] and M = W s,
    // W s - s W = M + M^T (s symmetric, W skew): six components from the
    // three of W
    symmTensor& s = points_.sigma[p];
    {
        const scalar a = 0.5*(L.xy() - L.yx());
        const scalar b = 0.5*(L.xz() - L.zx());
        const scalar c = 0.5*(L.yz() - L.zy());
        s += dt*symmTensor
        (
            2*(a*s.xy() + b*s.xz()),
            (a*s.yy() + b*s.yz()) + (c*s.xz() - a*s.xx()),
            (a*s.yz() + b*s.zz()) - (b*s.xx() + c*s.xy()),
            2*(c*s.yz() - a*s.xy()),
            (c*s.zz() - a*s.xz()) - (b*s.xy() + c*s.yy()),
            -2*(b*s.xz() + c*s.yz())
        );
    }
    dStrain = symm(L)*dt;
    points_.F[p] = (tensor::I + dt*L) & points_.F[p];
    updateVolume(p);
}


void Foam::materialPointSoil::updateConstitutive
(
    const label start,
    const label end
)
{
    const label* material = points_.material.cdata();
    label first = start;
    while (first < end)
    {
        const label m = material[first];
        label last = first + 1;
        while (last < end && material[last] == m)
        {
            ++last;
        }
        materials_[m].updateStresses
        (
            last - first,
            strainIncrement_.cdata() + (first - start),
            points_.sigma.data() + first,
            points_.plasticStrain.data() + first
        );
        first = last;
    }
}


void Foam::materialPointSoil::p2gMassMomentum(const bool withForces)
{
    const scalar ramp =
        (gravityRamp_ > 0 && time_ < gravityRamp_) ? time_/gravityRamp_ : 1;
    const vector g(ramp*gravity_);
    const bool apic = (transfer_ == transferType::APIC);

    withShape
    (
        shape_(), lattice_.nDim(),
        [&](auto shape, auto D)
        {
            typedef typename decltype(shape)::type Shape;
            constexpr label d = decltype(D)::value;
            if (apic && withForces) { p2gPoints<Shape, d, true, true>(g); }
            else if (apic)          { p2gPoints<Shape, d, true, false>(g); }
            else if (withForces)    { p2gPoints<Shape, d, false, true>(g); }
            else                    { p2gPoints<Shape, d, false, false>(g); }
        }
    );
}


void Foam::materialPointSoil::gridVelocityFromMomentum
(
    List<vector>& vel
) const
{
    forAll(vel, n)
    {
        vel[n] = gridMass_[n] > VSMALL ? gridMomentum_[n]/gridMass_[n] : Zero;
    }
}


void Foam::materialPointSoil::foldGhosts(List<vector>& values, const bool withMass)
{
    // The grid beyond a wall is the mirror image of the grid inside: what
    // the points gave to a node beyond the wall belongs, mirrored, to its
    // image inside (as if the points had mirror images beyond the wall).
    // Without this the nodes beyond a slip wall would carry part of the
    // weight of the points next to it: a spurious friction.
    forAll(ghostNode_, i)
    {
        const label w = ghostNode_[i];
        const label src = ghostSource_[i];
        if (src != w)
        {
            values[src] += cmptMultiply(ghostSign_[i], values[w]);
            if (withMass)
            {
                gridMass_[src] += gridMass_[w];
            }
        }
        values[w] = Zero;
        if (withMass)
        {
            gridMass_[w] = 0;
        }
    }
}


void Foam::materialPointSoil::mirrorGhosts(List<vector>& vel) const
{
    forAll(ghostNode_, i)
    {
        vel[ghostNode_[i]] = cmptMultiply(ghostSign_[i], vel[ghostSource_[i]]);
    }
}


void Foam::materialPointSoil::p2gForces()
{
    const scalar ramp =
        (gravityRamp_ > 0 && time_ < gravityRamp_) ? time_/gravityRamp_ : 1;
    const vector g(ramp*gravity_);
    withShape
    (
        shape_(), lattice_.nDim(),
        [&](auto shape, auto D)
        {
            p2gForcePoints
            <
                typename decltype(shape)::type, decltype(D)::value
            >(g);
        }
    );
}


void Foam::materialPointSoil::applyContact(List<vector>& vel) const
{
    // Coulomb friction at the last node before a friction wall
    // (Bardenhagen, Brackbill & Sulsky 2000, CMAME 187, 529)
    forAll(contactNode_, i)
    {
        const label n = contactNode_[i];
        if (gridMass_[n] <= VSMALL)
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


void Foam::materialPointSoil::g2p(const scalar dt)
{
    const bool flip = (transfer_ == transferType::FLIP);
    withShape
    (
        shape_(), lattice_.nDim(),
        [&](auto shape, auto D)
        {
            typedef typename decltype(shape)::type Shape;
            constexpr label d = decltype(D)::value;
            if (flip) { g2pPoints<Shape, d, true>(dt); }
            else      { g2pPoints<Shape, d, false>(dt); }
        }
    );
}


void Foam::materialPointSoil::updateStresses
(
    const List<vector>& vel,
    const scalar dt
)
{
    withShape
    (
        shape_(), lattice_.nDim(),
        [&](auto shape, auto D)
        {
            stressPoints
            <
                typename decltype(shape)::type, decltype(D)::value
            >(vel, dt);
        }
    );
}


bool Foam::materialPointSoil::clamp(vector& x, const vector& xOld) const
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


bool Foam::materialPointSoil::isDomainCell(const vector& x) const
{
    const label n = cellNodeOf(x);
    // (beyond this processor's box: its owner judges it; the migration
    // check stops a point that jumps that far)
    if (n < 0)
    {
        return true;
    }
    const unsigned char k = lattice_.kind()[n];
    return k == latticeMesh::OWNED || k == latticeMesh::HALO;
}


Foam::label Foam::materialPointSoil::cellNodeOf(const vector& x) const
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


inline void Foam::materialPointSoil::noteLeaving(const label p)
{
    // The owner of a point is the owner of the cell containing it (the
    // global cell index from the position: the same on every processor).
    // A point moves less than a cell per sub-step (CFL <= 1), so from an
    // owned cell it reaches an owned cell or a halo cell, whose owner is
    // known here.
    const label n = cellNodeOf(points_.x[p]);
    if (n < 0)
    {
        FatalErrorInFunction
            << "Material point " << points_.id[p] << " at "
            << points_.x[p] << " moved beyond the halo of processor "
            << Pstream::myProcNo() << " in one sub-step at time "
            << mesh_.time().timeName() << " s" << nl
            << "    A point must move less than a cell per sub-step:"
            << " lower soilCFL in system/controlDict"
            << exit(FatalError);
    }
    const label owner = nodeOwner_[n];
    if (owner >= 0 && owner != Pstream::myProcNo())
    {
        leavingPoint_.append(p);
        leavingProc_.append(owner);
    }
}


void Foam::materialPointSoil::migrate()
{
    points_.migrate
    (
        leavingPoint_,
        leavingProc_,
        hasPointForces_ ? &pointForce_ : nullptr
    );
    leavingPoint_.clear();
    leavingProc_.clear();
}


void Foam::materialPointSoil::subStep(const scalar dt)
{
    if (periodic_)
    {
        checkPeriodicReach();
    }

    const bool usf = (update_ == updateType::USF);
    const bool parallel = Pstream::parRun();
    const haloExchange& halo = lattice_.halo();
    p2gMassMomentum(!usf);
    foldGhosts(gridMomentum_, true);
    if (!usf)
    {
        foldGhosts(gridForce_, false);
    }
    if (parallel)
    {
        // What the points gave the halo nodes belongs to their owners
        if (usf)
        {
            halo.addToOwners
            ({
                haloExchange::field(gridMass_),
                haloExchange::field(gridMomentum_)
            });
        }
        else
        {
            halo.addToOwners
            ({
                haloExchange::field(gridMass_),
                haloExchange::field(gridMomentum_),
                haloExchange::field(gridForce_)
            });
        }
    }
    gridVelocityFromMomentum(gridVelocityOld_);
    if (parallel && (usf || transfer_ == transferType::FLIP))
    {
        // (read in the halo by USF's stress update and FLIP's G2P only)
        halo.copyToHalo({haloExchange::field(gridVelocityOld_)});
    }
    mirrorGhosts(gridVelocityOld_);

    if (usf)
    {
        updateStresses(gridVelocityOld_, dt);
        p2gForces();
        foldGhosts(gridForce_, false);
        if (parallel)
        {
            halo.addToOwners({haloExchange::field(gridForce_)});
        }
    }

    if (localDamping_ > 0)
    {
        forAll(gridForce_, n)
        {
            vector& f = gridForce_[n];
            const vector& v = gridVelocityOld_[n];
            for (direction d = 0; d < 3; ++d)
            {
                f[d] -= localDamping_*mag(f[d])*((v[d] > 0) - (v[d] < 0));
            }
        }
    }
    forAll(gridVelocity_, n)
    {
        gridVelocity_[n] =
            gridMass_[n] > VSMALL
          ? gridVelocityOld_[n] + dt*gridForce_[n]/gridMass_[n]
          : Zero;
    }
    applyContact(gridVelocity_);
    if (parallel)
    {
        halo.copyToHalo({haloExchange::field(gridVelocity_)});
    }
    mirrorGhosts(gridVelocity_);

    g2p(dt);

    if (parallel)
    {
        migrate();
    }

    if (update_ == updateType::MUSL)
    {
        // The points have moved (the second mapping's weights are those of
        // the new positions)
        if (periodic_)
        {
            checkPeriodicReach();
        }
        p2gMassMomentum(false);
        foldGhosts(gridMomentum_, true);
        if (parallel)
        {
            halo.addToOwners
            ({
                haloExchange::field(gridMass_),
                haloExchange::field(gridMomentum_)
            });
        }
        List<vector> vel(gridVelocity_.size());
        gridVelocityFromMomentum(vel);
        applyContact(vel);
        if (parallel)
        {
            halo.copyToHalo({haloExchange::field(vel)});
        }
        mirrorGhosts(vel);
        updateStresses(vel, dt);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::materialPointSoil::materialPointSoil(const latticeMesh& lattice)
:
    lattice_(lattice),
    mesh_(lattice.mesh()),
    dict_
    (
        IOobject
        (
            "soilProperties",
            mesh_.time().constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    shape_(shapeFunction::New(dict_)),
    transfer_(selectEntry(transferTypeNames, "transfer", dict_)),
    flipRatio_
    (
        dict_.optionalSubDict("FLIPCoeffs").getOrDefault<scalar>("ratio", 0.99)
    ),
    update_
    (
        selectEntry
        (
            updateTypeNames, "updateScheme", dict_, true, updateType::USL
        )
    ),
    CFL_(readCFL()),
    gravity_(Zero),
    gravityRamp_(dict_.getOrDefault<scalar>("gravityRamp", 0)),
    localDamping_(dict_.getOrDefault<scalar>("localDamping", 0)),
    time_(mesh_.time().value()),
    addedModulus_(0),
    maxSpeed_(GREAT),
    periodic_
    (
        lattice.periodic()[0] || lattice.periodic()[1] || lattice.periodic()[2]
    ),
    hasPointForces_(false),
    hasMissingCells_
    (
        returnReduce(mesh_.nCells(), sumOp<label>())
      < lattice.globalN().x()*lattice.globalN().y()*lattice.globalN().z()
    ),
    nClamped_(0),
    firstClamped_(-1),
    firstClampedAt_(Zero),
    firstClampedSpeed_(0),
    nSubSteps_(0),
    subDt_(0),
    nTotalSubSteps_(0),
    pointUpdates_(0)
{
    if (lattice_.haloWidth() < shape_->reach())
    {
        FatalErrorInFunction
            << "Lattice halo width " << lattice_.haloWidth() << " is below"
            << " the reach " << shape_->reach() << " of shape function "
            << shape_->type() << abort(FatalError);
    }
    if (dict_.found("CFL"))
    {
        // The time step is controlDict's business, with deltaT and maxCo:
        // a CFL left here would be silently ignored
        FatalIOErrorInFunction(dict_)
            << "CFL is not read from constant/soilProperties: the soil's"
            << " Courant number is soilCFL in system/controlDict (a value"
            << " in (0, 1], default 0.5)" << exit(FatalIOError);
    }
    if (dict_.found("gravity"))
    {
        // Gravity comes from constant/g, one way for every phase: the old
        // keyword would be silently ignored
        FatalIOErrorInFunction(dict_)
            << "gravity is not read from constant/soilProperties: it is the"
            << " gravity effect's, from constant/g (value (...);): add"
            << " gravity to effects in constant/physicsProperties (the"
            << " optional gravityRamp stays here)" << exit(FatalIOError);
    }
    if (!(gravityRamp_ >= 0))
    {
        FatalIOErrorInFunction(dict_)
            << "gravityRamp " << gravityRamp_ << " is not allowed: it must be"
            << " >= 0 [s]" << exit(FatalIOError);
    }
    if (!(localDamping_ >= 0 && localDamping_ < 1))
    {
        FatalIOErrorInFunction(dict_)
            << "localDamping " << localDamping_ << " is not allowed: it must"
            << " lie in [0, 1)" << exit(FatalIOError);
    }
    if (!(flipRatio_ >= 0 && flipRatio_ <= 1))
    {
        FatalIOErrorInFunction(dict_)
            << "FLIPCoeffs: ratio " << flipRatio_ << " is not allowed: it must"
            << " lie in [0, 1] (0: PIC, 1: pure FLIP)" << exit(FatalIOError);
    }

    readMaterials();
    maxSpeed_ = 0;
    forAll(materials_, i)
    {
        maxSpeed_ = max(maxSpeed_, 10*materials_[i].pWaveSpeed());
    }
    readWalls();

    // Grid
    const label nBox = lattice_.nBox();
    gridMass_.setSize(nBox, 0.0);
    gridMomentum_.setSize(nBox, Zero);
    gridForce_.setSize(nBox, Zero);
    gridVelocity_.setSize(nBox, Zero);
    gridVelocityOld_.setSize(nBox, Zero);
    strainIncrement_.setSize(pointBlock);
    buildGhosts();

    // The owner of every node a point can move into
    nodeOwner_.setSize(nBox, -1);
    for (const label n : lattice_.cellNode())
    {
        nodeOwner_[n] = Pstream::myProcNo();
    }
    forAll(lattice_.halo().recvNodes(), proci)
    {
        for (const label n : lattice_.halo().recvNodes()[proci])
        {
            nodeOwner_[n] = proci;
        }
    }

    // Points
    if (!points_.read(mesh_, mesh_.time().timeName()))
    {
        FatalErrorInFunction
            << "No material points in " << mesh_.time().timePath()
            << "/lagrangian/" << materialPoints::cloudName << nl
            << "    Make them with setMaterialPoints (system/"
            << "setMaterialPointsDict)" << exit(FatalError);
    }
    forAll(points_.material, p)
    {
        if (points_.material[p] < 0 || points_.material[p] >= materials_.size())
        {
            FatalErrorInFunction
                << "Material point " << p << " has material index "
                << points_.material[p] << " but soilProperties defines "
                << materials_.size() << " materials " << materialNames_
                << exit(FatalError);
        }
        shape_->checkHalfLength(points_.halfLength[p].x());
    }

    Info<< "Material point soil" << nl
        << "    points       " << nPoints() << " ("
        << materialPoints::memoryPerPoint() << " bytes per point)" << nl
        << "    shape function " << shape_->type() << ", transfer "
        << transferTypeNames[transfer_];
    if (transfer_ == transferType::FLIP)
    {
        Info<< " (ratio " << flipRatio_ << ")";
    }
    Info<< ", update " << updateTypeNames[update_] << nl;
    if (gravityRamp_ > 0)
    {
        Info<< "    gravity (constant/g) ramped over " << gravityRamp_ << " s"
            << nl;
    }
    if (localDamping_ > 0)
    {
        Info<< "    local damping " << localDamping_ << nl;
    }
    forAll(materials_, i)
    {
        Info<< "  ";
        materials_[i].report(Info);
        Info<< "        p-wave speed " << materials_[i].pWaveSpeed()
            << " m/s" << nl;
    }
    Info<< "    stable time step " << stableDt() << " s (CFL " << CFL_
        << "); controlDict deltaT " << mesh_.time().deltaTValue() << " s"
        << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::materialPointSoil::haloWidth(const fvMesh& mesh)
{
    const IOdictionary dict
    (
        IOobject
        (
            "soilProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const label reach = shapeFunction::New(dict)->reach();

    // Missing cells: fewer cells than the bounding box holds (the mesh is
    // uniform; latticeMesh checks that)
    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    const scalar cellVolume =
        returnReduce(mesh.nCells() ? mesh.V()[0] : scalar(0), maxOp<scalar>());
    const boundBox bb(mesh.points(), true);
    const bool missing =
        cellVolume > 0 && nCells + 0.5 < bb.volume()/cellVolume;

    return max(label(2), missing ? 3*reach - 1 : reach);
}


Foam::scalar Foam::materialPointSoil::readCFL() const
{
    // Read at every outer step, so an edit of a running case's controlDict
    // (runTimeModifiable) takes effect, as maxCo does for OpenFOAM's solvers
    const dictionary& control = mesh_.time().controlDict();
    const scalar CFL = control.getOrDefault<scalar>("soilCFL", 0.5);
    if (!(CFL > 0 && CFL <= 1))
    {
        FatalIOErrorInFunction(control)
            << "soilCFL " << CFL << " is not allowed: it must lie in (0, 1]"
            << " (the soil's sub-step over dx/(c_p + |v|))"
            << exit(FatalIOError);
    }
    return CFL;
}


void Foam::materialPointSoil::advance(const scalar deltaT)
{
    CFL_ = readCFL();
    const scalar dtStable = stableDt();
    nSubSteps_ = max(label(std::ceil(deltaT/dtStable - 1e-9)), label(1));
    subDt_ = deltaT/nSubSteps_;
    for (label s = 0; s < nSubSteps_; ++s)
    {
        time_ += subDt_;
        subStep(subDt_);
    }
    nTotalSubSteps_ += nSubSteps_;
    pointUpdates_ += scalar(nSubSteps_)*nPoints();

    const label nClamped = returnReduce(nClamped_, sumOp<label>());
    if (nClamped)
    {
        // The first point held, of the lowest processor that held any
        const label proc = returnReduce
        (
            nClamped_ ? Pstream::myProcNo() : Pstream::nProcs(),
            minOp<label>()
        );
        const bool mine = (proc == Pstream::myProcNo());
        const label id =
            returnReduce(mine ? firstClamped_ : label(0), sumOp<label>());
        const vector at =
            returnReduce(mine ? firstClampedAt_ : vector::zero, sumOp<vector>());
        const scalar speed =
            returnReduce(mine ? firstClampedSpeed_ : scalar(0), sumOp<scalar>());
        WarningInFunction
            << nClamped << " material point moves out of the domain were"
            << " stopped at its boundary (a wall or the face of a missing"
            << " cell) at time " << mesh_.time().timeName() << " s, the"
            << " first by point " << id << " (origId) at " << at
            << ", moving at " << speed << " m/s" << nl
            << "    The points hit the boundary faster than the grid stops"
            << " them: lower soilCFL in system/controlDict (now " << CFL_
            << ") or check the loads on the soil" << endl;
    }
    nClamped_ = 0;
}


Foam::label Foam::materialPointSoil::nPoints() const
{
    return returnReduce(points_.size(), sumOp<label>());
}


Foam::scalar Foam::materialPointSoil::memoryBytes() const
{
    // Per point the stored arrays only: the weights are evaluated where
    // they are used, the strain increments kept for one block of points.
    // Per box node: mass, momentum, force, velocity and old velocity, the
    // particle-to-grid records (8 doubles) and the velocities padded to 4
    // doubles (FLIP's old ones too)
    const label nPadded = (transfer_ == transferType::FLIP ? 8 : 4);
    return returnReduce
    (
        scalar(points_.size())*materialPoints::memoryPerPoint()
      + scalar(pointBlock)*sizeof(symmTensor)
      + scalar(lattice_.nBox())
       *(sizeof(scalar) + 4*sizeof(vector) + (8 + nPadded)*sizeof(scalar)),
        sumOp<scalar>()
    );
}


void Foam::materialPointSoil::nodalFields
(
    scalarList& phi,
    List<vector>& velocity
)
{
    const label nBox = lattice_.nBox();
    phi.setSize(nBox);
    velocity.setSize(nBox);
    phi = 0;
    velocity = Zero;
    scalarList& mass = nodeMass_;
    mass.setSize(nBox);
    mass = 0;

    if (periodic_)
    {
        checkPeriodicReach();
    }
    forAll(points_.x, p)
    {
        const scalar Vs = points_.V[p]*(1 - points_.porosity[p]);
        const scalar mp = points_.m[p];
        const vector& vp = points_.v[p];
        shapeWeights sw;
        pointWeights(p, sw);
        sw.forEachNode
        (
            [&](label i, label j, label k, scalar N, const vector&)
            {
                const label n = lattice_.node(i, j, k);
                phi[n] += N*Vs;
                mass[n] += N*mp;
                velocity[n] += N*mp*vp;
            }
        );
    }
    // What the points gave the nodes beyond walls belongs, mirrored, to the
    // nodes inside (as in the soil's own transfers): without this the
    // solid fraction would dip at every wall
    forAll(ghostNode_, i)
    {
        const label w = ghostNode_[i];
        const label src = ghostSource_[i];
        if (src != w)
        {
            phi[src] += phi[w];
            mass[src] += mass[w];
            velocity[src] += cmptMultiply(ghostSign_[i], velocity[w]);
        }
        phi[w] = 0;
        mass[w] = 0;
        velocity[w] = Zero;
    }

    // Parallel: the halo nodes' shares to their owners
    const bool parallel = Pstream::parRun();
    if (parallel)
    {
        lattice_.halo().addToOwners
        ({
            haloExchange::field(phi),
            haloExchange::field(mass),
            haloExchange::field(velocity)
        });
    }

    const scalar invV = 1.0/lattice_.cellVolume();
    forAll(phi, n)
    {
        phi[n] = min(phi[n]*invV, 0.99);
        velocity[n] = mass[n] > VSMALL ? velocity[n]/mass[n] : Zero;
    }

    // ... and the totals back into the halo: addNodeForces shares a halo
    // node's force by its total mass
    if (parallel)
    {
        lattice_.halo().copyToHalo
        ({
            haloExchange::field(phi),
            haloExchange::field(mass),
            haloExchange::field(velocity)
        });
    }
}


void Foam::materialPointSoil::addNodeForces(const List<vector>& nodeForce)
{
    // Each node's force goes to the points in proportion to the mass they
    // gave it, N m_p/m_n, with the weights of nodalFields (the points have
    // not moved since): the shares of a node sum to one, so the points
    // receive exactly the total force, and through P2G, the grid update
    // and G2P the impulse dt sum(f) reaches the points' momentum exactly
    // (partition of unity)
    if (!hasPointForces_ || pointForce_.size() != points_.size())
    {
        pointForce_.setSize(points_.size());
        pointForce_ = Zero;
    }
    hasPointForces_ = true;

    // Parallel: the points near a processor boundary take shares of the
    // neighbour's nodes, whose forces are copied into the halo
    List<vector> haloForce;
    if (Pstream::parRun())
    {
        haloForce = nodeForce;
        lattice_.halo().copyToHalo({haloExchange::field(haloForce)});
    }
    const List<vector>& force = Pstream::parRun() ? haloForce : nodeForce;

    // (a point's weight on a node beyond a wall was folded into the node
    // inside: it takes its share of that node's force through it; in
    // parallel that node may be a halo node)
    forAll(points_.x, p)
    {
        const scalar mp = points_.m[p];
        vector f(Zero);
        shapeWeights sw;
        pointWeights(p, sw);
        sw.forEachNode
        (
            [&](label i, label j, label k, scalar N, const vector&)
            {
                const label n = ghostImage_[lattice_.node(i, j, k)];
                if (nodeMass_[n] > 0)
                {
                    f += (N*mp/nodeMass_[n])*force[n];
                }
            }
        );
        pointForce_[p] += f;
    }
}


void Foam::materialPointSoil::clearPointForces()
{
    pointForce_ = Zero;
}


void Foam::materialPointSoil::addModulus(const scalar K, const word& why)
{
    addedModulus_ += K;
    Info<< "    soil stable time step with " << why << ": "
        << stableDt() << " s (added modulus " << K << " Pa)" << nl;
}


Foam::scalar Foam::materialPointSoil::minPorosity() const
{
    scalar n = 1;
    for (const scalar np : points_.porosity)
    {
        n = min(n, np);
    }
    return returnReduce(n, minOp<scalar>());
}


Foam::vector Foam::materialPointSoil::momentum() const
{
    vector sum(Zero);
    forAll(points_.v, p)
    {
        sum += points_.m[p]*points_.v[p];
    }
    if (Pstream::parRun())
    {
        reduce(sum, sumOp<vector>());
    }
    return sum;
}


Foam::scalar Foam::materialPointSoil::kineticEnergy() const
{
    scalar e = 0;
    forAll(points_.v, p)
    {
        e += 0.5*points_.m[p]*magSqr(points_.v[p]);
    }
    // (reduced only in parallel: the serial sum stays as it was, to the
    // bit, whatever the compiler makes of the loop)
    if (Pstream::parRun())
    {
        reduce(e, sumOp<scalar>());
    }
    return e;
}


void Foam::materialPointSoil::write()
{
    points_.write(mesh_, lattice_);

    // Nodal fields, as the couplings see them: the solid volume fraction
    // phi and the soil's velocity
    scalarList phi;
    List<vector> vel;
    nodalFields(phi, vel);

    volScalarField alpha
    (
        IOobject
        (
            "soilFraction",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh_,
        dimensionedScalar(dimless, Zero)
    );
    volVectorField Us
    (
        IOobject
        (
            "Usoil",
            mesh_.time().timeName(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh_,
        dimensionedVector(dimVelocity, Zero)
    );
    forAll(lattice_.cellNode(), celli)
    {
        const label n = lattice_.cellNode()[celli];
        alpha[celli] = phi[n];
        Us[celli] = vel[n];
    }
    alpha.write();
    Us.write();
}


// ************************************************************************* //
