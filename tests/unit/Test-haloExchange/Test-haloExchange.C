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

int main(int argc, char *argv[])
{
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    using namespace unitTest;

    const word decomp =
        Pstream::parRun()
      ? Foam::name(Pstream::nProcs()) + " processors"
      : word("serial");

    for (label width = 1; width <= 2; ++width)
    {
        const latticeMesh lat(mesh, width);
        const labelVector& N = lat.globalN();
        const FixedList<bool, 3>& periodic = lat.periodic();
        const label nBox = lat.nBox();
        const List<unsigned char>& kind = lat.kind();

        auto wrapped = [&](labelVector g, bool& inside)
        {
            inside = true;
            for (direction d = 0; d < 3; ++d)
            {
                if (periodic[d])
                {
                    g[d] = ((g[d] % N[d]) + N[d]) % N[d];
                }
                else if (g[d] < 0 || g[d] >= N[d])
                {
                    inside = false;
                }
            }
            return g.x() + N.x()*(g.y() + N.y()*g.z());
        };

        // Values: owned nodes carry their global index
        scalarList value(nBox, -1.0);
        for (const label n : lat.cellNode())
        {
            bool inside;
            value[n] = wrapped(lat.globalIjk(n), inside);
        }
        lat.halo().exchange(value.data(), 1, nBox);

        label nHalo = 0, nBad = 0, nMissing = 0, nWrongWall = 0;
        for (label n = 0; n < nBox; ++n)
        {
            bool inside;
            const label g = wrapped(lat.globalIjk(n), inside);
            if (kind[n] == latticeMesh::HALO)
            {
                ++nHalo;
                if (value[n] != g) ++nBad;
            }
            if (kind[n] == latticeMesh::WALL && inside)
            {
                // A wall inside the global box must be a missing cell:
                // this mesh has none
                ++nWrongWall;
            }
        }

        // Neighbourhood of owned nodes within the width: never unused
        const labelVector& bn = lat.boxN();
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

        // Node-major lists: a scalar and a vector list in one message
        scalarList sv(nBox, -1.0);
        List<vector> vv(nBox, vector::one*(-1));
        for (const label n : lat.cellNode())
        {
            bool inside;
            const scalar g = wrapped(lat.globalIjk(n), inside);
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
            bool inside;
            const scalar g = wrapped(lat.globalIjk(n), inside);
            if (sv[n] != g || vv[n] != vector(g, -g, 2*g)) ++nBadCopy;
        }

        // Reverse: 1 at every halo node, 0 at owned nodes; the owners
        // must receive the number of their images on all processors
        scalarList count(nBox, 0.0);
        labelList images(lat.nGlobalBox(), 0);
        for (label n = 0; n < nBox; ++n)
        {
            if (kind[n] == latticeMesh::HALO)
            {
                count[n] = 1;
                bool inside;
                ++images[wrapped(lat.globalIjk(n), inside)];
            }
        }
        Pstream::listCombineGather(images, plusEqOp<label>());
        Pstream::listCombineScatter(images);
        lat.halo().addToOwners({haloExchange::field(count)});
        label nBadSum = 0;
        for (const label n : lat.cellNode())
        {
            bool inside;
            if (count[n] != images[wrapped(lat.globalIjk(n), inside)])
            {
                ++nBadSum;
            }
        }

        const label nOwned = returnReduce(lat.nOwned(), sumOp<label>());
        const word w = "width " + Foam::name(width) + ", " + decomp;
        checkAll
        (
            nBad == 0,
            "halo nodes hold the owner's value, " + w,
            Foam::name(returnReduce(nHalo, sumOp<label>())) + " halo nodes, "
          + Foam::name(returnReduce(nBad, sumOp<label>())) + " wrong"
        );
        checkAll
        (
            nMissing == 0,
            "every node within reach of an owned node is present, " + w,
            Foam::name(returnReduce(nMissing, sumOp<label>())) + " missing"
        );
        checkAll
        (
            nWrongWall == 0,
            "wall nodes are exactly those outside the domain, " + w,
            Foam::name(returnReduce(nWrongWall, sumOp<label>())) + " wrong"
        );
        checkAll
        (
            nBadCopy == 0,
            "copyToHalo of node-major lists, " + w,
            Foam::name(returnReduce(nBadCopy, sumOp<label>())) + " wrong"
        );
        checkAll
        (
            nBadSum == 0,
            "addToOwners: every owner receives its images' values, " + w,
            Foam::name(returnReduce(nBadSum, sumOp<label>())) + " wrong"
        );
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
