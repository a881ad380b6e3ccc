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

#include "latticeAdvectionDiffusion.H"
#include "nodeFieldIO.H"
#include "inletOutletFvPatchFields.H"
#include "emptyPolyPatch.H"
#include "IFstream.H"
#include "caseChecks.H"
#include "OFstream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(latticeAdvectionDiffusion, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- What one step of the kernel found
struct transportStats
{
    scalar sum = 0;
    scalar sourced = 0;
    scalar v2Max = 0;
    scalar PhiMin = GREAT;
    label limited = 0;
};


//- Pull, BGK collision towards the equilibrium of the class description,
//  positivity limit and source, over the runs of owned nodes. D: lattice
//  dimension (2: D2Q5, 3: D3Q7).
template<int D>
void streamCollide
(
    const scalar* gOld,
    scalar* gNew,
    const label nBox,
    const label* offset,
    const List<latticeMesh::nodeRun>& runs,
    const vector* u,
    const scalar* porosity,
    const scalar* source,
    const scalar omega,
    const scalar cs2,
    transportStats& st
)
{
    constexpr int Q = 2*D + 1;
    const scalar w0 = 1 - D*cs2;
    const scalar wi = 0.5*cs2;

    for (const latticeMesh::nodeRun& run : runs)
    {
        for (label n = run[0]; n < run[1]; ++n)
        {
            scalar g[Q];
            scalar Phi = 0;
            for (int q = 0; q < Q; ++q)
            {
                g[q] = gOld[q*nBox + n - offset[q]];
                Phi += g[q];
            }

            const scalar n1 = porosity ? 1/porosity[n] : 1;
            scalar v[D];
            scalar v2 = 0;
            for (int a = 0; a < D; ++a)
            {
                v[a] = u[n][a]*n1;
                v2 += v[a]*v[a];
            }

            scalar geq[Q];
            geq[0] = Phi*(w0 - v2);
            for (int a = 0; a < D; ++a)
            {
                const scalar even = 0.5*Phi*(cs2 + v[a]*v[a]);
                geq[2*a + 1] = even + 0.5*Phi*v[a];
                geq[2*a + 2] = even - 0.5*Phi*v[a];
            }

            bool negative = false;
            for (int q = 0; q < Q; ++q)
            {
                g[q] += omega*(geq[q] - g[q]);
                negative = negative || g[q] < 0;
            }
            if (negative)
            {
                // Over-relaxation would make a population negative: relax
                // fully (omega = 1), which conserves Phi and keeps every
                // population non-negative while |v|^2 <= w0
                for (int q = 0; q < Q; ++q)
                {
                    g[q] = geq[q];
                }
                ++st.limited;
            }

            if (source && source[n] != 0)
            {
                const scalar S = source[n];
                if (S > 0)
                {
                    g[0] += w0*S;
                    for (int q = 1; q < Q; ++q)
                    {
                        g[q] += wi*S;
                    }
                    Phi += S;
                    st.sourced += S;
                }
                else if (Phi > 0)
                {
                    // Removal: the same fraction of every population, at
                    // most what the node holds
                    const scalar removed = min(-S, Phi);
                    const scalar keep = 1 - removed/Phi;
                    for (int q = 0; q < Q; ++q)
                    {
                        g[q] *= keep;
                    }
                    Phi -= removed;
                    st.sourced -= removed;
                }
            }

            for (int q = 0; q < Q; ++q)
            {
                gNew[q*nBox + n] = g[q];
            }
            st.sum += Phi;
            st.v2Max = max(st.v2Max, v2);
            st.PhiMin = min(st.PhiMin, Phi);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::latticeAdvectionDiffusion::inflowValues
(
    const fvPatchScalarField& Cp
)
{
    if (Cp.type() == "inletOutlet")
    {
        return tmp<scalarField>::New
        (
            refCast<const inletOutletFvPatchScalarField>(Cp).refValue()
        );
    }
    if (Cp.type() == "fixedValue")
    {
        return tmp<scalarField>::New(Cp);
    }
    return tmp<scalarField>::New();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::latticeAdvectionDiffusion::setRelaxation(const dictionary& dict)
{
    D_ = dict.get<scalar>("D");
    if (!(D_ > 0) || !std::isfinite(D_))
    {
        FatalIOErrorInFunction(dict)
            << "D " << D_ << ": the diffusivity of " << C_.name()
            << " [m2/s] must be positive and finite (the lattice scheme"
            << " needs tau = 1/2 + D dt/(cs2 dx^2) > 1/2)"
            << exit(FatalIOError);
    }

    const scalar dx = units_.dx();
    const scalar dt = units_.dt();
    tau_ = 0.5 + D_*dt/(cs2_*dx*dx);
    if (tau_ > 10)
    {
        // (stable for any tau > 1/2, but each step then spreads the scalar
        // over several cells: its transients are not resolved in time)
        IOWarningInFunction(dict)
            << "D " << D_ << " m2/s gives the lattice advection-diffusion of "
            << C_.name() << " tau " << tau_ << ": each step spreads it over "
            << Foam::sqrt(2*D_*dt)/dx << " cells (sqrt(2 D dt)/dx): its"
            << " changes in time are not resolved. A tau of order 1"
            << " resolves them (D dt/dx^2 = c_s^2 (tau - 1/2)): a smaller"
            << " deltaT or larger cells" << nl << endl;
    }
}


void Foam::latticeAdvectionDiffusion::buildLinks
(
    const lbmBoundaries& water,
    const volVectorField& U
)
{
    const fvMesh& mesh = lattice_.mesh();
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const wordList allowed({"fixedValue", "zeroGradient", "inletOutlet"});

    // Every patch's type first, whether this processor has links on it
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const fvPatchScalarField& Cp = C_.boundaryField()[patchi];
        const word type = Cp.type();
        if (pp.coupled() || isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        if (allowed.found(type))
        {
            // The values the patch puts into the water: as the field's own,
            // finite and non-negative (a negative inflow would make the
            // suspension negative downstream)
            const tmp<scalarField> tgiven(inflowValues(Cp));
            const scalarField& given = tgiven();
            forAll(given, i)
            {
                if (!(given[i] >= 0 && given[i] < GREAT))
                {
                    const dictionary fieldDict
                    (
                        fileDictionary(C_.objectPath())
                    );
                    FatalIOErrorInFunction
                    (
                        fieldDict.subDict("boundaryField").subDict(pp.name())
                    )   << "Patch " << pp.name() << " (" << type << "): "
                        << (type == "inletOutlet" ? "inletValue " : "value ")
                        << given[i] << " (at its face " << i << " on this"
                        << " processor); the "
                        << C_.name() << " it brings in must be finite and"
                        << " non-negative" << exit(FatalIOError);
                }
            }
            continue;
        }
        const dictionary fieldDict(fileDictionary(C_.objectPath()));
        FatalIOErrorInFunction
        (
            fieldDict.subDict("boundaryField").subDict(pp.name())
        )   << "Patch " << pp.name() << ": type " << type
            << " is not supported by the lattice advection-diffusion of "
            << C_.name() << nl
            << "    Allowed types: " << allowed
            << " (and cyclic, empty)" << exit(FatalIOError);
    }

    DynamicList<label> node, dir, patch;
    DynamicList<linkKind> kind;
    DynamicList<scalar> value, velocity;
    DynamicList<bool> nodeVelocity;

    const labelList& cellNode = lattice_.cellNode();
    const List<unsigned char>& nodeKind = lattice_.kind();
    const List<FixedList<label, 6>>& faces = lattice_.cellBoundaryFace();

    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        for (label q = 1; q < Q_; ++q)
        {
            if (nodeKind[n + offset_[q]] != latticeMesh::WALL)
            {
                continue;
            }
            const label a = axisOf(q);
            const label facei = faces[celli][2*a + (signOf(q) > 0 ? 1 : 0)];
            const label patchi =
                facei >= 0 ? patches.whichPatch(facei) : -1;

            linkKind k = CLOSED;
            scalar Cw = 0;
            scalar cu = 0;
            bool useNode = false;
            if (patchi >= 0)
            {
                const label i = facei - patches[patchi].start();
                const fvPatchScalarField& Cp = C_.boundaryField()[patchi];
                const word type = Cp.type();
                if (type == "fixedValue")
                {
                    k = FIXED;
                    Cw = Cp[i];
                }
                else if (type == "zeroGradient")
                {
                    k = ADVECTIVE;
                }
                else if (type == "inletOutlet")
                {
                    k = INLETOUTLET;
                    Cw = refCast<const inletOutletFvPatchScalarField>(Cp)
                        .refValue()[i];
                }

                switch (water.patchKinds()[patchi])
                {
                    case lbmBoundaries::PRESSURE:
                        useNode = true;
                        break;
                    case lbmBoundaries::MOVINGWALL:
                        cu = signOf(q)
                           *units_.toLattice(U.boundaryField()[patchi][i])[a];
                        break;
                    default:
                        break;
                }
            }

            node.append(n);
            dir.append(q);
            patch.append(patchi);
            kind.append(k);
            value.append(Cw);
            velocity.append(cu);
            nodeVelocity.append(useNode);
        }
    }

    // Links into solid bodies: closed (the kernel does not run inside them;
    // a boundary's node a body covers keeps its patch's link, as the
    // water's does)
    if (bodies_)
    {
        for (const label n : cellNode)
        {
            if (bodies_->solid(n))
            {
                continue;
            }
            for (label q = 1; q < Q_; ++q)
            {
                const label s = n + offset_[q];
                if (nodeKind[s] != latticeMesh::WALL && bodies_->solid(s))
                {
                    node.append(n);
                    dir.append(q);
                    patch.append(-1);
                    kind.append(CLOSED);
                    value.append(0);
                    velocity.append(0);
                    nodeVelocity.append(false);
                }
            }
        }
    }

    linkNode_.transfer(node);
    linkDir_.transfer(dir);
    linkPatch_.transfer(patch);
    linkKind_.transfer(kind);
    linkValue_.transfer(value);
    linkVelocity_.transfer(velocity);
    linkNodeVelocity_.transfer(nodeVelocity);
}


void Foam::latticeAdvectionDiffusion::initialise
(
    const UList<vector>& u,
    const scalarList* porosity
)
{
    const label nBox = lattice_.nBox();
    gA_.setSize(Q_*nBox, 0.0);
    gB_.setSize(Q_*nBox, 0.0);
    AisCurrent_ = true;
    if (surface_)
    {
        forAll(wasWater_, n)
        {
            wasWater_[n] = surface_->water(n);
        }
    }
    scalarList& g = current();

    const word prefix(C_.name() + "G");
    const bool restart = writtenPopulations();
    if (restart)
    {
        if
        (
            !foundNodeField(lattice_, prefix + "0")
         || !foundNodeField(lattice_, prefix + Foam::name(Q_ - 1))
         || foundNodeField(lattice_, prefix + Foam::name(Q_))
        )
        {
            FatalErrorInFunction
                << "The populations of " << C_.name() << " in "
                << lattice_.mesh().time().timePath() << " were not written"
                << " for a " << lattice_.nDim() << "D lattice (" << Q_
                << " files " << prefix << "0.." << prefix << Q_ - 1
                << " expected)." << nl
                << "    Remove the " << prefix << "* files to start from "
                << C_.name() << " at equilibrium." << exit(FatalError);
        }
        Info<< "Reading populations " << prefix << "0.." << prefix << Q_ - 1
            << " from time " << lattice_.mesh().time().timeName() << endl;
        for (label q = 0; q < Q_; ++q)
        {
            readNodeField(lattice_, prefix + Foam::name(q), g.data() + q*nBox);
        }
    }
    else
    {
        const labelList& cellNode = lattice_.cellNode();
        label nDry = 0;
        forAll(cellNode, celli)
        {
            const label n = cellNode[celli];
            const scalar eps = porosity ? (*porosity)[n] : 1;
            if (!water(n))
            {
                // (the gas holds none: its populations stay 0)
                nDry += (C_[celli] > 0);
                continue;
            }
            // (an interface node's water fills the fraction phi of its
            // pores: C is per volume of water, as the field is written)
            const scalar Phi =
                eps*C_[celli]*(surface_ ? surface_->fill(n) : 1);
            const vector v = u[n]/eps;
            g[n] = Phi*(w0_ - magSqr(v));
            for (label q = 1; q < Q_; ++q)
            {
                const scalar va = v[axisOf(q)];
                g[q*nBox + n] = 0.5*Phi*(cs2_ + va*va + signOf(q)*va);
            }
        }
        if (returnReduce(nDry, sumOp<label>()))
        {
            WarningInFunction
                << C_.objectPath() << ": " << C_.name() << " is positive in "
                << returnReduce(nDry, sumOp<label>()) << " cells outside"
                << " the water (the gas, alpha.water 0, or a solid body):"
                << " the scalar lives in the water only, and starts at 0"
                << " there" << endl;
        }
    }

    initialised_ = true;
    content0_ = content();
    if (restart)
    {
        readBalance();
    }
}


void Foam::latticeAdvectionDiffusion::fillBoundaries
(
    scalar* g,
    const UList<vector>& u,
    const scalarList* porosity
)
{
    const label nBox = lattice_.nBox();
    const scalar Vcell = lattice_.cellVolume();
    forAll(linkNode_, l)
    {
        const label x = linkNode_[l];
        if (!water(x))
        {
            // (a gas node: not simulated, nothing crosses its links)
            continue;
        }
        const label i = linkDir_[l];
        const label slot = oppositeOf(i)*nBox + x + offset_[i];
        const scalar gi = g[i*nBox + x];
        const scalar eps = porosity ? (*porosity)[x] : 1;

        linkKind k = linkKind_[l];
        scalar cv = 0;
        if (k == ADVECTIVE || k == INLETOUTLET)
        {
            cv =
                (
                    linkNodeVelocity_[l]
                  ? signOf(i)*u[x][axisOf(i)]
                  : linkVelocity_[l]
                )/eps;
            if (k == INLETOUTLET)
            {
                k = cv > 0 ? ADVECTIVE : FIXED;
            }
        }

        scalar value = gi;
        if
        (
            settling_
         && (k == CLOSED || (k == ADVECTIVE && !linkNodeVelocity_[l]))
         && linkVelocity_[l] == 0
        )
        {
            // A wall: what settles into it is deposited there
            const scalar ws = signOf(i)*(*settling_)[x][axisOf(i)];
            if (ws > 0)
            {
                scalar Phi = 0;
                for (label q = 0; q < Q_; ++q)
                {
                    Phi += g[q*nBox + x];
                }
                value = max(gi - Phi*ws, scalar(0));
                deposited_ += (gi - value)*Vcell;
            }
            g[slot] = value;
            continue;
        }
        if (k == FIXED)
        {
            value = -gi + cs2_*eps*linkValue_[l];
        }
        else if (k == ADVECTIVE)
        {
            scalar Phi = 0;
            for (label q = 0; q < Q_; ++q)
            {
                Phi += g[q*nBox + x];
            }
            value = gi - Phi*cv;
        }
        g[slot] = value;

        if (linkPatch_[l] >= 0)
        {
            patchOutflow_[linkPatch_[l]] += (gi - value)*Vcell;
        }
    }
}


void Foam::latticeAdvectionDiffusion::instability
(
    const UList<vector>& u,
    const scalarList* porosity
) const
{
    const scalarList& g = current();
    const label nBox = lattice_.nBox();
    for (const label n : lattice_.cellNode())
    {
        if (!water(n))
        {
            continue;
        }
        scalar Phi = 0;
        for (label q = 0; q < Q_; ++q)
        {
            Phi += g[q*nBox + n];
        }
        const scalar eps = porosity ? (*porosity)[n] : 1;
        const scalar v2 = magSqr(u[n]/eps);
        if (!std::isfinite(Phi) || v2 > w0_)
        {
            FatalErrorInFunction
                << "The advection-diffusion of " << C_.name()
                << " left its stable range at time "
                << lattice_.mesh().time().timeName() << ", cell "
                << lattice_.nodeCell()[n] << " at "
                << lattice_.position(n) << ": " << C_.name() << " "
                << Phi/eps << ", pore speed "
                << std::sqrt(v2)*units_.velocityScale() << " m/s (lattice "
                << std::sqrt(v2) << ", limit sqrt(w0) = "
                << std::sqrt(w0_) << ")." << nl
                << "    A smaller deltaT lowers the lattice speed; the"
                << " water's own Mach limit (machLimit) is the other"
                << " bound." << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::word Foam::latticeAdvectionDiffusion::fieldFile
(
    const latticeMesh& lattice,
    const word& fieldName,
    const dictionary& dict
)
{
    // (OpenFOAM's own message names the missing file, not the entry that
    // asked for it)
    const fvMesh& mesh = lattice.mesh();
    IOobject io(fieldName, mesh.time().timeName(), mesh, IOobject::MUST_READ);
    if (!returnReduce(io.typeHeaderOk<volScalarField>(false), andOp<bool>()))
    {
        FatalIOErrorInFunction(dict)
            << "field " << fieldName << ": there is no volScalarField "
            << fieldName << " in " << io.path() << " to start from. Give"
            << " the name of the transported field, its file in the start"
            << " time with its patches (fixedValue, zeroGradient,"
            << " inletOutlet)"
            << (
                   fieldName.find('.') != string::npos
                 ? " (with suspensionPerMaterial each material's field is"
                   " <field>.<material>)"
                 : ""
               )
            << exit(FatalIOError);
    }
    return fieldName;
}


Foam::latticeAdvectionDiffusion::latticeAdvectionDiffusion
(
    const latticeMesh& lattice,
    const lbmUnits& units,
    const word& fieldName,
    const dictionary& dict,
    const lbmBoundaries& water,
    const volVectorField& U,
    const lbmFreeSurface* surface,
    const lbmObstacles* bodies
)
:
    lattice_(lattice),
    units_(units),
    C_
    (
        IOobject
        (
            fieldFile(lattice, fieldName, dict),
            lattice.mesh().time().timeName(),
            lattice.mesh(),
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        ),
        lattice.mesh()
    ),
    D_(0),
    d_(lattice.nDim()),
    Q_(2*d_ + 1),
    cs2_(d_ == 2 ? 1.0/3.0 : 0.25),
    w0_(1 - d_*cs2_),
    tau_(1),
    offset_(Q_, 0),
    AisCurrent_(true),
    patchOutflow_(lattice.mesh().boundaryMesh().nNonProcessor(), Zero),
    sourced_(0),
    settling_(nullptr),
    deposited_(0),
    content0_(0),
    limited_(0),
    PhiMin_(0),
    nSteps_(0),
    initialised_(false),
    ignoreWrittenBalance_(false),
    surface_(surface),
    stranded_(0),
    bodies_(bodies && !bodies->empty() ? bodies : nullptr)
{
    setRelaxation(dict);

    for (label q = 1; q < Q_; ++q)
    {
        labelVector c(Zero);
        c[axisOf(q)] = label(signOf(q));
        offset_[q] = lattice_.offset(c.x(), c.y(), c.z());
    }

    if (surface_)
    {
        const label nBox = lattice_.nBox();
        wasWater_.setSize(nBox, false);
        share_.setSize(nBox, Zero);
        DynamicList<label> nbr;
        const label zMax = (d_ == 3 ? 1 : 0);
        for (label k = -zMax; k <= zMax; ++k)
        {
            for (label j = -1; j <= 1; ++j)
            {
                for (label i = -1; i <= 1; ++i)
                {
                    if (i || j || k)
                    {
                        nbr.append(lattice_.offset(i, j, k));
                    }
                }
            }
        }
        neighbours_.transfer(nbr);
        DynamicList<label> halo;
        const List<unsigned char>& kind = lattice_.kind();
        forAll(kind, n)
        {
            if (kind[n] == latticeMesh::HALO)
            {
                halo.append(n);
            }
        }
        haloNodes_.transfer(halo);
    }

    forAll(C_, celli)
    {
        if (!std::isfinite(C_[celli]) || C_[celli] < 0)
        {
            FatalIOErrorInFunction(dict)
                << C_.objectPath() << ": " << C_.name() << " " << C_[celli]
                << " in cell " << celli << "; the transported scalar must"
                << " be finite and non-negative" << exit(FatalIOError);
        }
    }

    buildLinks(water, U);

    // Written populations are read now, at the start time (a start from
    // the field waits for the water's velocity and porosity of the first
    // step)
    if (foundNodeField(lattice_, C_.name() + "G0"))
    {
        initialise(List<vector>(), nullptr);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeAdvectionDiffusion::step
(
    const UList<vector>& uWater,
    const scalarList* porosity,
    const scalarList* source
)
{
    // Settling grains move at the water's pore velocity plus their own
    if (settling_)
    {
        uSettled_.setSize(uWater.size());
        forAll(uSettled_, n)
        {
            const scalar eps = porosity ? (*porosity)[n] : 1;
            uSettled_[n] = uWater[n] + eps*(*settling_)[n];
        }
    }
    const UList<vector>& u = settling_ ? uSettled_ : uWater;

    prepare(u, porosity);

    const label nBox = lattice_.nBox();
    scalarList& g = current();
    lattice_.halo().exchange(g.data(), Q_, nBox);
    fillBoundaries(g.data(), u, porosity);
    if (surface_)
    {
        surfaceLinks(g.data());
    }
    const List<latticeMesh::nodeRun>& runs =
        surface_ ? surface_->runs()
      : bodies_ ? bodies_->runs()
      : lattice_.runs();

    transportStats st;
    const scalar* eps = porosity ? porosity->cdata() : nullptr;
    const scalar* S = source ? source->cdata() : nullptr;
    if (d_ == 2)
    {
        streamCollide<2>
        (
            g.cdata(), next().data(), nBox, offset_.cdata(),
            runs, u.cdata(), eps, S,
            1/tau_, cs2_, st
        );
    }
    else
    {
        streamCollide<3>
        (
            g.cdata(), next().data(), nBox, offset_.cdata(),
            runs, u.cdata(), eps, S,
            1/tau_, cs2_, st
        );
    }

    sourced_ += st.sourced*lattice_.cellVolume();
    limited_ = st.limited;
    PhiMin_ = st.PhiMin;
    ++nSteps_;
    AisCurrent_ = !AisCurrent_;

    if (!std::isfinite(st.sum) || !(st.v2Max <= w0_))
    {
        instability(u, porosity);
    }
}


Foam::scalar Foam::latticeAdvectionDiffusion::Phi(const label n) const
{
    if (!water(n))
    {
        return 0;
    }
    const scalarList& g = current();
    const label nBox = lattice_.nBox();
    scalar sum = 0;
    for (label q = 0; q < Q_; ++q)
    {
        sum += g[q*nBox + n];
    }
    return sum;
}


Foam::scalar Foam::latticeAdvectionDiffusion::take
(
    const label n,
    const scalar amount
)
{
    scalarList& g = current();
    const label nBox = lattice_.nBox();
    const scalar held = Phi(n);
    if (!(amount > 0) || !(held > 0))
    {
        return 0;
    }
    const scalar keep = amount < held ? 1 - amount/held : 0;
    scalar left = 0;
    for (label q = 0; q < Q_; ++q)
    {
        g[q*nBox + n] *= keep;
        left += g[q*nBox + n];
    }

    // What the node lost, as its populations now sum (the balance closes
    // on the populations, not on the amount asked)
    const scalar taken = held - left;
    sourced_ -= taken*lattice_.cellVolume();
    return taken;
}


Foam::scalar Foam::latticeAdvectionDiffusion::content() const
{
    scalar sum = 0;
    if (initialised_)
    {
        for (const label n : lattice_.cellNode())
        {
            sum += Phi(n);
        }
    }
    return returnReduce
    (
        sum*lattice_.cellVolume() + stranded_,
        sumOp<scalar>()
    );
}


Foam::scalar Foam::latticeAdvectionDiffusion::minPhi() const
{
    return returnReduce(PhiMin_, minOp<scalar>());
}


Foam::label Foam::latticeAdvectionDiffusion::limitedNodes() const
{
    return returnReduce(limited_, sumOp<label>());
}


void Foam::latticeAdvectionDiffusion::updateField(const scalarList* porosity)
{
    if (!initialised_)
    {
        return;
    }
    const labelList& cellNode = lattice_.cellNode();
    scalarField& C = C_.primitiveFieldRef();
    forAll(cellNode, celli)
    {
        const label n = cellNode[celli];
        // (per volume of water: an interface node's water fills the
        // fraction phi of its pores; 0 in the gas)
        const scalar wet =
            surface_ ? max(surface_->fill(n), scalar(1e-3)) : 1;
        C[celli] = Phi(n)/((porosity ? (*porosity)[n] : 1)*wet);
    }
    // (the patch values stay as read: the lattice imposes the patches at
    // the half-way links, and inletOutlet would need a face flux phi)
}


Foam::scalar Foam::latticeAdvectionDiffusion::memoryBytes() const
{
    return returnReduce
    (
        scalar(sizeof(scalar))*(gA_.size() + gB_.size()),
        sumOp<scalar>()
    );
}


void Foam::latticeAdvectionDiffusion::report(Ostream& os) const
{
    label nKind[4] = {0, 0, 0, 0};
    for (const linkKind k : linkKind_)
    {
        ++nKind[k];
    }
    for (label& nk : nKind)
    {
        reduce(nk, sumOp<label>());
    }
    os  << "Advection-diffusion of " << C_.name() << ": D" << d_ << "Q" << Q_
        << ", D " << D_ << " m2/s, tau " << tau_
        << (tau_ < 1 ? " (over-relaxed: nodes that would turn negative"
            " relax fully)" : "") << nl
        << "    boundary links: " << nKind[CLOSED] << " closed, "
        << nKind[FIXED] << " fixedValue, " << nKind[ADVECTIVE]
        << " zeroGradient, " << nKind[INLETOUTLET] << " inletOutlet" << nl;
}


// ************************************************************************* //
