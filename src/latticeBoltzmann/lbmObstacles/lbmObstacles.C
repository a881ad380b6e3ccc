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

#include "lbmObstacles.H"
#include "selectEntry.H"
#include "optionalEntry.H"
#include "caseChecks.H"
#include "Time.H"
#include "volumeType.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::lbmObstacles::boundaryType>
Foam::lbmObstacles::boundaryTypeNames
({
    { boundaryType::INTERPOLATED, "interpolated" },
    { boundaryType::STAIRCASE, "staircase" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::lbmObstacles::lbmObstacles
(
    const latticeMesh& lattice,
    const dictionary& fluidDict
)
:
    lattice_(lattice),
    boundary_(INTERPOLATED)
{
    const dictionary* bodiesPtr = fluidDict.findDict("obstacles");
    if (!bodiesPtr)
    {
        if (foundEntry(fluidDict, "obstacles"))
        {
            FatalIOErrorInFunction(fluidDict)
                << "obstacles must be a dictionary of bodies, e.g." << nl
                << "    obstacles { pier { type searchableCylinder;"
                << " point1 (0 0 -1); point2 (0 0 1); radius 0.1; } }"
                << exit(FatalIOError);
        }
        runs_ = lattice_.runs();
        return;
    }
    const dictionary& bodies = *bodiesPtr;
    boundary_ = selectEntry
    (
        boundaryTypeNames,
        "obstacleBoundary",
        fluidDict,
        true,
        INTERPOLATED
    );

    const Time& runTime = lattice_.mesh().time();
    for (const entry& e : bodies)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(bodies)
                << "obstacles: " << e.keyword() << " is not a dictionary:"
                << " each body is a searchable surface { type ...; }"
                << exit(FatalIOError);
        }
        const dictionary& bodyDict = e.dict();
        const word type = bodyDict.get<word>("type");
        autoPtr<searchableSurface> surface;
        // OpenFOAM's surfaces raise errors that name no file: each is
        // given the body's dictionary
        const string failure = catchFatal
        (
            [&]()
            {
                surface = searchableSurface::New
                (
                    type,
                    IOobject
                    (
                        e.keyword(),
                        runTime.constant(),
                        "triSurface",
                        runTime,
                        IOobject::MUST_READ,
                        IOobject::NO_WRITE
                    ),
                    bodyDict
                );
            },
            false
        );
        if (!failure.empty())
        {
            FatalIOErrorInFunction(bodyDict)
                << "Obstacle " << e.keyword() << ": " << failure.c_str()
                << exit(FatalIOError);
        }
        if (!surface->hasVolumeType())
        {
            FatalIOErrorInFunction(bodyDict)
                << "Obstacle " << e.keyword() << ": surface type " << type
                << " does not enclose a volume. Use a closed surface"
                << " (searchableBox, searchableCylinder, searchableSphere, a"
                << " closed triSurfaceMesh)" << exit(FatalIOError);
        }
        names_.append(e.keyword());
        surfaces_.append(surface.ptr());
    }
    if (surfaces_.empty())
    {
        runs_ = lattice_.runs();
        return;
    }

    // The bodies' periodic images: a node is solid where any image of a
    // body holds it (given as it is, a sphere centred on a corner of a
    // periodic box kept the eighth of it inside the bounds: its drag 82%
    // low, without a word)
    images_.setSize(1, Zero);
    for (direction d = 0; d < 3; ++d)
    {
        if (!lattice_.periodic()[d])
        {
            continue;
        }
        vector L(Zero);
        L[d] = lattice_.globalN()[d]*lattice_.dx();
        const label nImages = images_.size();
        for (label k = 0; k < nImages; ++k)
        {
            images_.append(images_[k] + L);
            images_.append(images_[k] - L);
        }
    }

    // The body of every box node (owned, halo and wall nodes alike: a
    // link from a processor's node sees the same bodies as the serial run;
    // a halo image across a cyclic face tests its owner's position, so
    // both see the same images)
    const label nBox = lattice_.nBox();
    pointField positions(nBox);
    body_.setSize(nBox, -1);
    // (an image that cannot reach the box is not searched)
    boundBox box(lattice_.mesh().bounds());
    const scalar margin = (lattice_.haloWidth() + 2)*lattice_.dx();
    box.min() -= vector::uniform(margin);
    box.max() += vector::uniform(margin);
    for (const vector& shift : images_)
    {
        forAll(positions, n)
        {
            positions[n] = wrappedPosition(n) + shift;
        }
        forAll(surfaces_, b)
        {
            const boundBox bb(surfaces_[b].bounds());
            if (!box.overlaps(boundBox(bb.min() - shift, bb.max() - shift)))
            {
                continue;
            }
            List<volumeType> inside;
            surfaces_[b].getVolumeType(positions, inside);
            forAll(inside, n)
            {
                if (body_[n] < 0 && inside[n] == volumeType::INSIDE)
                {
                    body_[n] = b;
                }
            }
        }
    }

    nSolid_.setSize(surfaces_.size(), 0);
    for (const label n : lattice_.cellNode())
    {
        if (body_[n] >= 0)
        {
            ++nSolid_[body_[n]];
        }
    }
    labelList total(nSolid_);
    Pstream::listCombineGather(total, plusEqOp<label>());
    Pstream::listCombineScatter(total);
    forAll(total, b)
    {
        if (total[b] == 0)
        {
            FatalIOErrorInFunction(bodies.subDict(names_[b]))
                << "Obstacle " << names_[b] << " contains no lattice node"
                << " (cell centre): it is smaller than a cell or outside the"
                << " mesh. Refine the mesh or enlarge the body"
                << exit(FatalIOError);
        }
    }
    // (a body over the whole mesh leaves no water to simulate)
    if (sum(total) >= returnReduce(lattice_.cellNode().size(), sumOp<label>()))
    {
        FatalIOErrorInFunction(bodies)
            << "The obstacles " << names_ << " cover every lattice node of"
            << " the mesh: no water is left. Each body must leave water"
            << " around it (check their sizes, e.g. a radius, against the"
            << " mesh's bounds " << lattice_.mesh().bounds() << ")"
            << exit(FatalIOError);
    }

    // The kernel's runs without the solid nodes
    DynamicList<latticeMesh::nodeRun> runs;
    for (const latticeMesh::nodeRun& r : lattice_.runs())
    {
        label start = -1;
        for (label n = r[0]; n < r[1]; ++n)
        {
            if (body_[n] < 0 && start < 0)
            {
                start = n;
            }
            else if (body_[n] >= 0 && start >= 0)
            {
                runs.append(latticeMesh::nodeRun({start, n}));
                start = -1;
            }
        }
        if (start >= 0)
        {
            runs.append(latticeMesh::nodeRun({start, r[1]}));
        }
    }
    runs_.transfer(runs);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::point Foam::lbmObstacles::wrappedPosition(const label n) const
{
    point p = lattice_.position(n);
    for (direction d = 0; d < 3; ++d)
    {
        if (lattice_.periodic()[d])
        {
            const scalar L = lattice_.globalN()[d]*lattice_.dx();
            p[d] -= std::floor((p[d] - lattice_.origin()[d])/L)*L;
        }
    }
    return p;
}


Foam::scalar Foam::lbmObstacles::wallFraction
(
    const label x,
    const label s
) const
{
    if (boundary_ == STAIRCASE)
    {
        return 0.5;
    }
    // (along the image of the body that holds s, as the constructor
    // found it: the link's ends shifted alike, a link across a cyclic face
    // included)
    const searchableSurface& surface = surfaces_[body_[s]];
    const point wrapped(wrappedPosition(s));
    const vector wrap(wrapped - lattice_.position(s));
    vector shift(wrap);
    for (const vector& image : images_)
    {
        List<volumeType> inside;
        surface.getVolumeType(pointField(1, wrapped + image), inside);
        if (inside[0] == volumeType::INSIDE)
        {
            shift = wrap + image;
            break;
        }
    }
    const point start = lattice_.position(x) + shift;
    const point end = lattice_.position(s) + shift;
    List<pointIndexHit> hit;
    surface.findLine
    (
        pointField(1, start),
        pointField(1, end),
        hit
    );
    if (!hit[0].hit())
    {
        // (a link that grazes the surface at its end)
        return 1.0;
    }
    const scalar q = mag(hit[0].hitPoint() - start)/mag(end - start);
    // (a surface through the water node itself: the wall is at x)
    return min(max(q, 1e-6), 1.0);
}


void Foam::lbmObstacles::report(Ostream& os) const
{
    if (surfaces_.empty())
    {
        return;
    }
    labelList total(nSolid_);
    Pstream::listCombineGather(total, plusEqOp<label>());
    Pstream::listCombineScatter(total);
    os  << "Obstacles in the water (" << boundaryTypeNames[boundary_]
        << " bounce-back)" << nl;
    forAll(names_, b)
    {
        os  << "    " << names_[b] << ": " << surfaces_[b].type() << ", "
            << total[b] << " solid nodes" << nl;
    }
    os  << endl;
}


// ************************************************************************* //
