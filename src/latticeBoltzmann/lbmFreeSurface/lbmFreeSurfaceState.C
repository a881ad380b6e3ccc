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

// The free surface's state: its start from alpha.water, its restart
// files, the water's mass

#include "lbmFreeSurface.H"
#include "nodeFieldIO.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::lbmFreeSurface::setFromFraction
(
    const scalarField& alpha,
    scalar* f
)
{
    const label Q = vs_.Q();
    const label nBox = lattice_.nBox();
    const labelList& cellNode = lattice_.cellNode();
    const scalarList& w = vs_.w();

    // (alpha is checked by the caller: finite, in [0, 1]). Within
    // alphaRoundOff of 0 or 1 a cell is gas or liquid: cut-cell fractions
    // (setAlphaField) leave 1e-17..1e-13 around the surface, which made
    // interface nodes of no water that emptied at the first step, and a
    // changed bit in a binary alpha.water's zero changed the run
    const scalar roundOff = alphaRoundOff;
    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        if (obstacles_.solid(n))
        {
            continue;
        }
        const scalar rho = density(f, n);
        const scalar a = alpha[celli];
        if (a >= 1 - roundOff)
        {
            type_[n] = LIQUID;
            mass_[n] = capacity(rho, n);
            fill_[n] = 1;
        }
        else if (a <= roundOff)
        {
            type_[n] = GAS;
            mass_[n] = 0;
            fill_[n] = 0;
        }
        else
        {
            type_[n] = INTERFACE;
            mass_[n] = a*capacity(rho, n);
            fill_[n] = a;
        }
    }
    exchangeTypes();

    // Close the interface layer: a liquid node next to gas is an interface
    // node, full
    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        if (type_[n] != LIQUID)
        {
            continue;
        }
        for (label q = 1; q < Q; ++q)
        {
            if (type_[n - offset_[q]] == GAS)
            {
                type_[n] = INTERFACE;
                break;
            }
        }
    }
    exchangeTypes();
    lattice_.halo().exchange(fill_.data(), 1, nBox);

    // The gas at rest at its own density (its populations are never
    // streamed into water: only finite)
    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        if (type_[n] == GAS)
        {
            const scalar rhoG = 1 + porosity(n)*(rhoGas_ - 1);
            for (label q = 0; q < Q; ++q)
            {
                f[layout_->at(q, n)] = w[q]*rhoG;
            }
        }
    }
    rebuild();
}


void Foam::lbmFreeSurface::readState(scalar* f)
{
    const label nBox = lattice_.nBox();
    scalarList t(nBox, 0.0);
    readNodeField(lattice_, "lbmFreeSurfaceType", t.data());
    readNodeField(lattice_, "lbmFreeSurfaceMass", mass_.data());
    // The interface nodes' fill levels as the run had them (in a soil the
    // porosity they were taken with is mapped again only in the coming
    // step, after the drag has used them)
    scalarList writtenFill;
    if (foundNodeField(lattice_, "lbmFreeSurfaceFill"))
    {
        writtenFill.setSize(nBox, 0.0);
        readNodeField(lattice_, "lbmFreeSurfaceFill", writtenFill.data());
    }
    const labelList& cellNode = lattice_.cellNode();
    for (const label n : cellNode)
    {
        if (obstacles_.solid(n))
        {
            continue;
        }
        const label ti = label(t[n]);
        if
        (
            !(t[n] == ti)
         || (ti != LIQUID && ti != INTERFACE && ti != GAS)
        )
        {
            FatalErrorInFunction
                << "lbmFreeSurfaceType in " << lattice_.mesh().time().timePath()
                << " holds " << t[n] << " at node " << n << ": only "
                << label(LIQUID) << " (liquid), " << label(INTERFACE)
                << " (interface) or " << label(GAS) << " (gas) are written."
                << nl << "    The file is damaged: restart from another"
                << " written time" << exit(FatalError);
        }
        type_[n] = ti;
        const scalar C = capacity(density(f, n), n);
        if (ti == LIQUID)
        {
            mass_[n] = C;
            fill_[n] = 1;
        }
        else if (ti == GAS)
        {
            mass_[n] = 0;
            fill_[n] = 0;
        }
        else
        {
            fill_[n] =
                writtenFill.size()
              ? writtenFill[n]
              : min(max(mass_[n]/C, 0.0), 1.0);
        }
    }
    exchangeTypes();
    lattice_.halo().exchange(fill_.data(), 1, nBox);
    rebuild();
}


void Foam::lbmFreeSurface::resetMasses(const scalar* f)
{
    for (const label n : lattice_.cellNode())
    {
        const label t = type_[n];
        if (t == LIQUID || t == INTERFACE)
        {
            mass_[n] = fill_[n]*capacity(density(f, n), n);
        }
    }
}


void Foam::lbmFreeSurface::writeState() const
{
    // The types, and the masses of the interface nodes (a liquid node's is
    // its density, a gas node's 0: not written, so a restart's files equal
    // a straight run's byte for byte)
    scalarList t(lattice_.nBox(), 0.0);
    scalarList m(lattice_.nBox(), 0.0);
    scalarList phi(lattice_.nBox(), 0.0);
    forAll(t, n)
    {
        t[n] = type_[n];
        if (type_[n] == INTERFACE)
        {
            m[n] = mass_[n];
            phi[n] = fill_[n];
        }
    }
    writeNodeField(lattice_, "lbmFreeSurfaceType", t.cdata());
    writeNodeField(lattice_, "lbmFreeSurfaceMass", m.cdata());
    writeNodeField(lattice_, "lbmFreeSurfaceFill", phi.cdata());
}


Foam::wordList Foam::lbmFreeSurface::stateFiles() const
{
    return wordList
    ({
        "lbmFreeSurfaceType", "lbmFreeSurfaceMass", "lbmFreeSurfaceFill"
    });
}


Foam::scalar Foam::lbmFreeSurface::mass(const scalar* f) const
{
    const label Q = vs_.Q();
    scalar m = 0;
    for (const label n : lattice_.cellNode())
    {
        const label t = type_[n];
        if (t == LIQUID)
        {
            scalar rho = 0;
            for (label q = 0; q < Q; ++q)
            {
                rho += f[layout_->at(q, n)];
            }
            m += capacity(rho, n);
        }
        else if (t == INTERFACE)
        {
            m += mass_[n];
        }
    }
    return m;
}


Foam::scalar Foam::lbmFreeSurface::storedSum(const scalar* f) const
{
    scalar sum = 0;
    for (const label n : lattice_.cellNode())
    {
        const label t = type_[n];
        if (t == LIQUID)
        {
            sum += density(f, n);
        }
        else if (t == INTERFACE)
        {
            sum += mass_[n];
        }
    }
    return sum;
}


// ************************************************************************* //
