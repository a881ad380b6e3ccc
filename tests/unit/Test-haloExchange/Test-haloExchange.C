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
    Test-haloExchange

Description
    Checks the shared lattice and its halo exchange on the case's mesh, in
    serial or parallel (any decomposition), for halo widths 1 and 2:
    - every owned node carries its global index; after the exchange every
      halo node holds the global index of the node it copies (wrapped in
      periodic directions), including nodes across edges and corners of
      the sub-domain;
    - every node within the halo width of an owned node is owned, halo or
      wall (none is missing), and wall nodes are exactly those outside the
      domain;
    - the owned nodes of all processors cover the global lattice once;
    - copyToHalo of node-major lists (a scalarList and a List<vector> in
      one message) gives the halo nodes the owners' values;
    - addToOwners adds every halo image's value to its owner node: with 1
      at every halo node, each owned node receives exactly the number of
      its images on all processors (periodic ones included).
    Prints PASS:/FAIL: lines (from the master); exits 1 on any failure.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "latticeMesh.H"
#include "unitTest.H"

using namespace unitTest;

//- The global index of a node of the box, wrapped across periodic
//  directions; inside is false for a node outside a non-periodic side
static label wrappedGlobal(const latticeMesh& lat, const label n, bool& inside)
{
    const labelVector& N = lat.globalN();
    labelVector g = lat.globalIjk(n);
    inside = true;
    for (direction d = 0; d < 3; ++d)
    {
        if (lat.periodic()[d])
        {
            g[d] = ((g[d] % N[d]) + N[d]) % N[d];
        }
        else if (g[d] < 0 || g[d] >= N[d])
        {
            inside = false;
        }
    }
    return g.x() + N.x()*(g.y() + N.y()*g.z());
}


static label wrappedGlobal(const latticeMesh& lat, const label n)
{
    bool inside;
    return wrappedGlobal(lat, n, inside);
}


//- exchange(): owned nodes carry their global index; every halo node must
//  hold its owner's, and walls must be exactly the nodes outside the box
static void testExchange(const latticeMesh& lat, const word& w)
{
    const label nBox = lat.nBox();
    const List<unsigned char>& kind = lat.kind();

    scalarList value(nBox, -1.0);
    for (const label n : lat.cellNode())
    {
        value[n] = wrappedGlobal(lat, n);
    }
    lat.halo().exchange(value.data(), 1, nBox);

    label nHalo = 0, nBad = 0, nWrongWall = 0;
    for (label n = 0; n < nBox; ++n)
    {
        bool inside;
        const label g = wrappedGlobal(lat, n, inside);
        if (kind[n] == latticeMesh::HALO)
        {
            ++nHalo;
            if (value[n] != g) ++nBad;
        }
        if (kind[n] == latticeMesh::WALL && inside)
        {
            // A wall inside the global box must be a missing cell: this
            // mesh has none
            ++nWrongWall;
        }
    }
    checkAll
    (
        nBad == 0,
        "halo nodes hold the owner's value, " + w,
        Foam::name(returnReduce(nHalo, sumOp<label>())) + " halo nodes, "
      + Foam::name(returnReduce(nBad, sumOp<label>())) + " wrong"
    );
    checkAll
    (
        nWrongWall == 0,
        "wall nodes are exactly those outside the domain, " + w,
        Foam::name(returnReduce(nWrongWall, sumOp<label>())) + " wrong"
    );
}


//- Every node within the halo width of an owned node is in the box and used
static void testNeighbourhood
(
    const latticeMesh& lat,
    const label width,
    const word& w
)
{
    const List<unsigned char>& kind = lat.kind();
    const labelVector& bn = lat.boxN();
    label nMissing = 0;
    for (const label n : lat.cellNode())
    {
        const labelVector b = lat.boxIjk(n);
        for (label k = -width; k <= width; ++k)
        for (label j = -width; j <= width; ++j)
        for (label i = -width; i <= width; ++i)
        {
            if (lat.twoD() && k != 0) continue;
            const labelVector o(b.x() + i, b.y() + j, b.z() + k);
            if
            (
                o.x() < 0 || o.y() < 0 || o.z() < 0
             || o.x() >= bn.x() || o.y() >= bn.y() || o.z() >= bn.z()
            )
            {
                ++nMissing;
                continue;
            }
            if (kind[lat.node(o.x(), o.y(), o.z())] == latticeMesh::UNUSED)
            {
                ++nMissing;
            }
        }
    }
    checkAll
    (
        nMissing == 0,
        "every node within reach of an owned node is present, " + w,
        Foam::name(returnReduce(nMissing, sumOp<label>())) + " missing"
    );
}


//- copyToHalo of node-major lists: a scalar and a vector list in one message
static void testCopyToHalo(const latticeMesh& lat, const word& w)
{
    const label nBox = lat.nBox();
    const List<unsigned char>& kind = lat.kind();

    scalarList sv(nBox, -1.0);
    List<vector> vv(nBox, vector::one*(-1));
    for (const label n : lat.cellNode())
    {
        const scalar g = wrappedGlobal(lat, n);
        sv[n] = g;
        vv[n] = vector(g, -g, 2*g);
    }
    lat.halo().copyToHalo
    ({
        haloExchange::field(sv), haloExchange::field(vv)
    });
    label nBadCopy = 0;
    for (label n = 0; n < nBox; ++n)
    {
        if (kind[n] != latticeMesh::HALO) continue;
        const scalar g = wrappedGlobal(lat, n);
        if (sv[n] != g || vv[n] != vector(g, -g, 2*g)) ++nBadCopy;
    }
    checkAll
    (
        nBadCopy == 0,
        "copyToHalo of node-major lists, " + w,
        Foam::name(returnReduce(nBadCopy, sumOp<label>())) + " wrong"
    );
}


//- addToOwners: 1 at every halo node, 0 at owned nodes; the owners must
//  receive the number of their images on all processors
static void testAddToOwners(const latticeMesh& lat, const word& w)
{
    const label nBox = lat.nBox();
    const List<unsigned char>& kind = lat.kind();

    scalarList count(nBox, 0.0);
    labelList images(lat.nGlobalBox(), 0);
    for (label n = 0; n < nBox; ++n)
    {
        if (kind[n] == latticeMesh::HALO)
        {
            count[n] = 1;
            ++images[wrappedGlobal(lat, n)];
        }
    }
    Pstream::listCombineGather(images, plusEqOp<label>());
    Pstream::listCombineScatter(images);
    lat.halo().addToOwners({haloExchange::field(count)});
    label nBadSum = 0;
    for (const label n : lat.cellNode())
    {
        if (count[n] != images[wrappedGlobal(lat, n)])
        {
            ++nBadSum;
        }
    }
    checkAll
    (
        nBadSum == 0,
        "addToOwners: every owner receives its images' values, " + w,
        Foam::name(returnReduce(nBadSum, sumOp<label>())) + " wrong"
    );
}


int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const word decomp =
        Pstream::parRun()
      ? Foam::name(Pstream::nProcs()) + " processors"
      : word("serial");

    for (label width = 1; width <= 2; ++width)
    {
        const latticeMesh lat(mesh, width);
        const word w = "width " + Foam::name(width) + ", " + decomp;

        testExchange(lat, w);
        testNeighbourhood(lat, width, w);
        testCopyToHalo(lat, w);
        testAddToOwners(lat, w);

        const label nOwned = returnReduce(lat.nOwned(), sumOp<label>());
        checkAll
        (
            nOwned == lat.nGlobalBox(),
            "owned nodes cover the lattice once, " + w,
            Foam::name(nOwned) + " of " + Foam::name(lat.nGlobalBox())
        );
    }

    return unitTest::finish();
}


// ************************************************************************* //
