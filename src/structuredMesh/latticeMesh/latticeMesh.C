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

#include "latticeMesh.H"
#include "boundBox.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "emptyPolyPatch.H"
#include "coupledPolyPatch.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(latticeMesh, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::latticeMesh::checkUniform()
{
    const pointField& points = mesh_.points();
    const cellList& cells = mesh_.cells();
    const faceList& faces = mesh_.faces();

    // 2D: one cell thick in z with empty patches
    const Vector<label>& solD = mesh_.solutionD();
    nDim_ = mesh_.nSolutionD();
    if (nDim_ == 1)
    {
        FatalErrorInFunction
            << "The mesh of " << mesh_.time().path() << " is one-dimensional"
            << " (two empty directions). mpmLbmFoam needs a 2D mesh (one cell"
            << " thick in z with empty front and back patches) or a 3D mesh."
            << exit(FatalError);
    }
    if (nDim_ == 2 && solD.z() != -1)
    {
        // (solutionD: -1 marks the empty direction)
        const char* axis = (solD.x() == -1 ? "x" : "y");
        FatalErrorInFunction
            << "The mesh of " << mesh_.time().path() << " is 2D with its"
            << " empty direction along " << axis << ", not z. A 2D scene"
            << " must be one cell thick in z with empty patches on the z"
            << " faces (blockMesh: the plane in x and y, one cell in z)."
            << exit(FatalError);
    }

    const boundBox globalBb(points, true);
    origin_ = globalBb.min();

    // Expected cell size: the smallest x extent of any cell
    scalar minExtent = GREAT;
    List<boundBox> cellBb(cells.size());
    forAll(cells, celli)
    {
        const labelList cellPts(cells[celli].labels(faces));
        cellBb[celli] = boundBox(pointField(points, cellPts), false);
        minExtent = min(minExtent, cellBb[celli].span().x());
    }
    dx_ = returnReduce(minExtent, minOp<scalar>());
    thickness_ = (nDim_ == 2 ? globalBb.span().z() : dx_);

    const scalar tol = 1e-6*dx_;
    const vector expected(dx_, dx_, thickness_);

    forAll(cells, celli)
    {
        const boundBox& bb = cellBb[celli];
        const labelList cellPts(cells[celli].labels(faces));

        bool ok = (cells[celli].size() == 6 && cellPts.size() == 8);
        ok = ok && mag(bb.span().x() - dx_) < tol
                && mag(bb.span().y() - dx_) < tol
                && mag(bb.span().z() - thickness_) < tol;

        // Every vertex at a corner of the cell's box: axis-aligned
        if (ok)
        {
            for (const label pti : cellPts)
            {
                const point& p = points[pti];
                for (direction d = 0; d < 3; ++d)
                {
                    if
                    (
                        mag(p[d] - bb.min()[d]) > tol
                     && mag(p[d] - bb.max()[d]) > tol
                    )
                    {
                        ok = false;
                    }
                }
            }
        }

        if (!ok)
        {
            FatalErrorInFunction
                << "The mesh is not a uniform axis-aligned hex mesh." << nl
                << "    Cell " << celli << " at " << mesh_.cellCentres()[celli]
                << " has " << cells[celli].size() << " faces, "
                << cellPts.size() << " points and size " << bb.span()
                << nl << "    expected: a hexahedron of size " << expected
                << " (the smallest cell width dx = " << dx_ << ")" << nl
                << "    mpmLbmFoam shares one lattice between the water and"
                << " the soil: use blockMesh with simpleGrading (1 1 1) and the"
                << " same cell size dx in every block and direction."
                << exit(FatalError);
        }
    }

    // Global node counts
    const vector span = globalBb.span();
    for (direction d = 0; d < 3; ++d)
    {
        const scalar n = (d == 2 && nDim_ == 2) ? 1 : span[d]/dx_;
        globalN_[d] = label(n + 0.5);
        if (mag(n - globalN_[d]) > 1e-6*max(n, 1.0))
        {
            FatalErrorInFunction
                << "The bounding box " << span << " of the mesh is not a"
                << " whole number of cells of size " << dx_ << " in direction "
                << d << exit(FatalError);
        }
    }
}


void Foam::latticeMesh::findPeriodic()
{
    periodic_ = false;
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const vectorField& Sf = mesh_.faceAreas();

    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (isA<cyclicPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp))
        {
            forAll(pp, i)
            {
                const vector n = Sf[pp.start() + i]/mag(Sf[pp.start() + i]);
                for (direction d = 0; d < 3; ++d)
                {
                    if (mag(n[d]) > 0.99)
                    {
                        periodic_[d] = true;
                    }
                }
            }
        }
    }
    for (direction d = 0; d < 3; ++d)
    {
        reduce(periodic_[d], orOp<bool>());
    }
    if (nDim_ == 2)
    {
        periodic_[2] = false;
    }
}


Foam::List<Foam::labelVector> Foam::latticeMesh::cellLatticeIjk
(
    labelVector& lo,
    labelVector& hi
) const
{
    const vectorField& C = mesh_.cellCentres();

    List<labelVector> cellIjk(mesh_.nCells());
    lo = labelVector(labelMax, labelMax, labelMax);
    hi = labelVector(labelMin, labelMin, labelMin);
    const scalar tol = 1e-3;
    forAll(C, celli)
    {
        labelVector ijk;
        for (direction d = 0; d < 3; ++d)
        {
            if (d == 2 && nDim_ == 2)
            {
                ijk[d] = 0;
                continue;
            }
            const scalar s = (C[celli][d] - origin_[d])/dx_ - 0.5;
            ijk[d] = label(std::floor(s + 0.5));
            if (mag(s - ijk[d]) > tol)
            {
                FatalErrorInFunction
                    << "Cell " << celli << " centre " << C[celli]
                    << " is not on the lattice of spacing " << dx_
                    << " from " << origin_ << exit(FatalError);
            }
        }
        cellIjk[celli] = ijk;
        lo = min(lo, ijk);
        hi = max(hi, ijk);
    }
    return cellIjk;
}


void Foam::latticeMesh::sizeBox(const labelVector& lo, const labelVector& hi)
{
    const label h = haloWidth_;
    for (direction d = 0; d < 3; ++d)
    {
        if (d == 2 && nDim_ == 2)
        {
            boxStart_[d] = 0;
            boxN_[d] = 1;
        }
        else if (mesh_.nCells())
        {
            boxStart_[d] = lo[d] - h;
            boxN_[d] = hi[d] - lo[d] + 1 + 2*h;
        }
        else
        {
            boxStart_[d] = 0;
            boxN_[d] = 0;
        }
    }
    stride_ = labelVector(1, boxN_.x(), boxN_.x()*boxN_.y());
}


Foam::List<bool> Foam::latticeMesh::nodesWithinReach() const
{
    // Separable dilation of the owned mask
    const label h = haloWidth_;
    const label nBox = this->nBox();
    List<bool> reach(nBox, false);
    forAll(cellNode_, celli)
    {
        reach[cellNode_[celli]] = true;
    }
    for (direction d = 0; d < 3; ++d)
    {
        if (boxN_[d] <= 1)
        {
            continue;
        }
        List<bool> dilated(reach);
        const label s = stride_[d];
        for (label n = 0; n < nBox; ++n)
        {
            if (!reach[n])
            {
                continue;
            }
            const label c = boxIjk(n)[d];
            for (label o = -h; o <= h; ++o)
            {
                if (c + o >= 0 && c + o < boxN_[d])
                {
                    dilated[n + o*s] = true;
                }
            }
        }
        reach.transfer(dilated);
    }
    return reach;
}


void Foam::latticeMesh::classifyNodes(const List<labelVector>& cellIjk)
{
    const label myProc = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();

    // Owner of every global node (-1: missing cell)
    const labelVector& N = globalN_;
    auto globalIndex = [&N](const labelVector& g)
    {
        return g.x() + N.x()*(g.y() + N.y()*g.z());
    };

    labelList globalOwner(nGlobalBox(), -1);
    forAll(cellIjk, celli)
    {
        globalOwner[globalIndex(cellIjk[celli])] = myProc;
    }
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(globalOwner, maxEqOp<label>());
        Pstream::listCombineScatter(globalOwner);
    }

    // Every processor's box, to address nodes in the owner's box
    List<labelVector> procBoxStart(nProcs), procBoxN(nProcs);
    procBoxStart[myProc] = boxStart_;
    procBoxN[myProc] = boxN_;
    Pstream::gatherList(procBoxStart);
    Pstream::scatterList(procBoxStart);
    Pstream::gatherList(procBoxN);
    Pstream::scatterList(procBoxN);

    const List<bool> reach(nodesWithinReach());

    DynamicList<label> haloNodes, haloProc, haloOwnerNode;
    for (label n = 0; n < nBox(); ++n)
    {
        if (kind_[n] == OWNED)
        {
            continue;
        }
        labelVector g = globalIjk(n);
        bool inside = true;
        for (direction d = 0; d < 3; ++d)
        {
            if (periodic_[d])
            {
                g[d] = ((g[d] % N[d]) + N[d]) % N[d];
            }
            else if (g[d] < 0 || g[d] >= N[d])
            {
                inside = false;
            }
        }
        const label owner = inside ? globalOwner[globalIndex(g)] : -1;
        if (owner < 0)
        {
            kind_[n] = WALL;
        }
        else if (!reach[n])
        {
            kind_[n] = UNUSED;
        }
        else
        {
            kind_[n] = HALO;
            const labelVector b = g - procBoxStart[owner];
            const labelVector& bn = procBoxN[owner];
            haloNodes.append(n);
            haloProc.append(owner);
            haloOwnerNode.append(b.x() + bn.x()*(b.y() + bn.y()*b.z()));
        }
    }

    halo_ = haloExchange(haloNodes, haloProc, haloOwnerNode);
}


void Foam::latticeMesh::findRuns()
{
    DynamicList<nodeRun> runs;
    for (label k = 0; k < boxN_.z(); ++k)
    {
        for (label j = 0; j < boxN_.y(); ++j)
        {
            label i = 0;
            while (i < boxN_.x())
            {
                if (kind_[node(i, j, k)] != OWNED)
                {
                    ++i;
                    continue;
                }
                nodeRun r;
                r[0] = node(i, j, k);
                while (i < boxN_.x() && kind_[node(i, j, k)] == OWNED)
                {
                    ++i;
                }
                r[1] = node(i - 1, j, k) + 1;
                runs.append(r);
            }
        }
    }
    runs_.transfer(runs);
}


void Foam::latticeMesh::buildBox()
{
    labelVector lo, hi;
    const List<labelVector> cellIjk(cellLatticeIjk(lo, hi));
    sizeBox(lo, hi);

    // Maps cell <-> node
    const label nBox = boxN_.x()*boxN_.y()*boxN_.z();
    kind_.setSize(nBox, WALL);
    nodeCell_.setSize(nBox, -1);
    cellNode_.setSize(cellIjk.size());
    forAll(cellIjk, celli)
    {
        const labelVector b = cellIjk[celli] - boxStart_;
        const label n = node(b.x(), b.y(), b.z());
        cellNode_[celli] = n;
        nodeCell_[n] = celli;
        kind_[n] = OWNED;
    }

    classifyNodes(cellIjk);
    findRuns();
}


void Foam::latticeMesh::buildBoundaryFaces()
{
    FixedList<label, 6> none(-1);
    cellBoundaryFace_.setSize(mesh_.nCells(), none);

    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const vectorField& Sf = mesh_.faceAreas();
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        if (pp.coupled() || isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        const labelUList& faceCells = pp.faceCells();
        forAll(pp, i)
        {
            const vector& a = Sf[pp.start() + i];
            direction d = 0;
            for (direction e = 1; e < 3; ++e)
            {
                if (mag(a[e]) > mag(a[d]))
                {
                    d = e;
                }
            }
            const label dir = 2*d + (a[d] > 0 ? 1 : 0);
            cellBoundaryFace_[faceCells[i]][dir] = pp.start() + i;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::latticeMesh::latticeMesh(const fvMesh& mesh, const label haloWidth)
:
    mesh_(mesh),
    dx_(0),
    origin_(Zero),
    globalN_(Zero),
    nDim_(3),
    thickness_(0),
    periodic_(false),
    haloWidth_(max(haloWidth, label(1))),
    boxStart_(Zero),
    boxN_(Zero),
    stride_(Zero)
{
    checkUniform();
    findPeriodic();
    buildBox();
    buildBoundaryFaces();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelVector Foam::latticeMesh::boxIjk(const label n) const
{
    const label k = n/stride_.z();
    const label r = n - k*stride_.z();
    const label j = r/stride_.y();
    return labelVector(r - j*stride_.y(), j, k);
}


Foam::point Foam::latticeMesh::position(const label n) const
{
    const labelVector g = globalIjk(n);
    point p;
    for (direction d = 0; d < 3; ++d)
    {
        p[d] = origin_[d]
             + (d == 2 && nDim_ == 2 ? 0.5*thickness_ : (g[d] + 0.5)*dx_);
    }
    return p;
}


void Foam::latticeMesh::report(Ostream& os) const
{
    const label nCells = returnReduce(mesh_.nCells(), sumOp<label>());
    const label nHalo = returnReduce(halo_.nRecv(), sumOp<label>());
    os  << "Lattice" << nl
        << "    dimensions   " << nDim_ << "D" << nl
        << "    dx           " << dx_ << " m" << nl
        << "    nodes        " << globalN_ << " box, " << nCells
        << " in the domain" << nl
        << "    periodic     " << periodic_ << nl
        << "    halo width   " << haloWidth_ << " (" << nHalo
        << " halo nodes)" << nl << endl;
}


// ************************************************************************* //
