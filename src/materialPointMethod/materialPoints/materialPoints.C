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

#include "caseChecks.H"
#include "materialPoints.H"
#include "passiveParticleCloud.H"
#include "IFstream.H"
#include "IOField.H"
#include "globalIndex.H"
#include "PstreamBuffers.H"
#include "DynamicList.H"
#include "PtrList.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::materialPoints::cloudName("materialPoints");


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

template<class Type>
void writeField
(
    const Foam::passiveParticleCloud& cloud,
    const Foam::word& name,
    const Foam::UList<Type>& values,
    const bool binary
)
{
    Foam::IOField<Type> fld
    (
        cloud.fieldIOobject(name, Foam::IOobject::NO_READ),
        values.size()
    );
    fld.Foam::UList<Type>::deepCopy(values);
    if (binary)
    {
        fld.writeObject
        (
            Foam::IOstream::BINARY,
            Foam::IOstream::currentVersion,
            Foam::IOstream::UNCOMPRESSED,
            true
        );
    }
    else
    {
        fld.write();
    }
}


template<class Type>
bool readField
(
    const Foam::passiveParticleCloud& cloud,
    const Foam::word& name,
    Foam::List<Type>& values
)
{
    Foam::IOobject io(cloud.fieldIOobject(name, Foam::IOobject::MUST_READ));
    if (!io.typeHeaderOk<Foam::IOField<Type>>(true))
    {
        return false;
    }
    Foam::IOField<Type> fld(io);
    if (fld.size() != cloud.size())
    {
        FatalErrorInFunction
            << "Field " << fld.objectPath() << " of the material points has "
            << fld.size() << " values for " << cloud.size() << " points"
            << Foam::exit(Foam::FatalError);
    }
    values.transfer(fld);
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::materialPoints::setSize(const label n)
{
    x.setSize(n);
    v.setSize(n);
    m.setSize(n);
    V.setSize(n);
    V0.setSize(n);
    F.setSize(n);
    sigma.setSize(n);
    plasticStrain.setSize(n);
    C.setSize(n);
    material.setSize(n);
    halfLength.setSize(n);
    porosity.setSize(n);
    id.setSize(n);
    if (carriesFines)
    {
        fines.setSize(n, Zero);
    }
}


void Foam::materialPoints::enableFines()
{
    if (!carriesFines)
    {
        carriesFines = true;
        fines.setSize(size(), Zero);
    }
}


void Foam::materialPoints::append
(
    const vector& position,
    const vector& velocity,
    const scalar mass,
    const scalar volume,
    const symmTensor& stress,
    const label materialIndex,
    const vector& halfSize,
    const scalar pointPorosity
)
{
    const label i = size();
    setSize(i + 1);
    x[i] = position;
    v[i] = velocity;
    m[i] = mass;
    V[i] = volume;
    V0[i] = volume;
    F[i] = tensor::I;
    sigma[i] = stress;
    plasticStrain[i] = 0;
    C[i] = Zero;
    material[i] = materialIndex;
    halfLength[i] = halfSize;
    porosity[i] = pointPorosity;
    id[i] = i;
}


Foam::label Foam::materialPoints::memoryPerPoint()
{
    return
        4*sizeof(vector)/3*3       // x, v, halfLength, + spare
      + 2*sizeof(tensor)           // F, C
      + sizeof(symmTensor)         // sigma
      + 5*sizeof(scalar)           // m, V, V0, plasticStrain, porosity
      + sizeof(label);             // material (id: in the spare)
}


Foam::label Foam::materialPoints::compact
(
    const labelUList& gone,
    List<vector>* extra,
    List<symmTensor>* extraStress
)
{
    // Close the gaps from the first gone point on
    const label n = size();
    label k = gone.size() ? gone[0] : n;
    label next = 0;
    for (label p = k; p < n; ++p)
    {
        if (next < gone.size() && gone[next] == p)
        {
            ++next;
            continue;
        }
        x[k] = x[p]; v[k] = v[p]; m[k] = m[p]; V[k] = V[p];
        V0[k] = V0[p]; F[k] = F[p]; sigma[k] = sigma[p];
        plasticStrain[k] = plasticStrain[p]; C[k] = C[p];
        material[k] = material[p]; halfLength[k] = halfLength[p];
        porosity[k] = porosity[p]; id[k] = id[p];
        if (carriesFines)
        {
            fines[k] = fines[p];
        }
        if (extra)
        {
            (*extra)[k] = (*extra)[p];
        }
        if (extraStress)
        {
            (*extraStress)[k] = (*extraStress)[p];
        }
        ++k;
    }
    return k;
}


void Foam::materialPoints::remove
(
    const labelUList& gone,
    List<vector>* extra,
    List<symmTensor>* extraStress
)
{
    if (gone.empty())
    {
        return;
    }
    const label k = compact(gone, extra, extraStress);
    setSize(k);
    if (extra)
    {
        extra->setSize(k);
    }
    if (extraStress)
    {
        extraStress->setSize(k);
    }
}


void Foam::materialPoints::reorder
(
    const labelUList& order,
    List<vector>* extra,
    List<symmTensor>* extraStress
)
{
    auto permute = [&](auto& values)
    {
        typedef typename std::decay<decltype(values[0])>::type Type;
        List<Type> sorted(values.size());
        forAll(order, k)
        {
            sorted[k] = values[order[k]];
        }
        values.transfer(sorted);
    };
    permute(x); permute(v); permute(m); permute(V); permute(V0); permute(F);
    permute(sigma); permute(plasticStrain); permute(C); permute(material);
    permute(halfLength); permute(porosity); permute(id);
    if (carriesFines)
    {
        permute(fines);
    }
    if (extra)
    {
        if (extra->size() != order.size())
        {
            FatalErrorInFunction
                << "A per-point list of " << extra->size() << " values for "
                << order.size() << " points" << abort(FatalError);
        }
        permute(*extra);
    }
    if (extraStress)
    {
        if (extraStress->size() != order.size())
        {
            FatalErrorInFunction
                << "A per-point list of " << extraStress->size()
                << " stresses for " << order.size() << " points"
                << abort(FatalError);
        }
        permute(*extraStress);
    }
}


void Foam::materialPoints::migrate
(
    const labelUList& leaving,
    const labelUList& toProc,
    List<vector>* extra,
    List<symmTensor>* extraStress
)
{
    const label nProcs = Pstream::nProcs();
    const label n = size();

    List<DynamicList<label>> sendPoints(nProcs);
    forAll(leaving, i)
    {
        sendPoints[toProc[i]].append(leaving[i]);
    }

    // Send every quantity of the leaving points, in one message per
    // processor, headed by their number
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(sendPoints, proci)
    {
        const labelUList& idx = sendPoints[proci];
        if (idx.empty())
        {
            continue;
        }
        UOPstream os(proci, pBufs);
        os << idx.size();
        auto put = [&](const auto& values)
        {
            typedef typename std::decay<decltype(values[0])>::type Type;
            os << List<Type>(UIndirectList<Type>(values, idx));
        };
        put(x); put(v); put(m); put(V); put(V0); put(F); put(sigma);
        put(plasticStrain); put(C); put(material); put(halfLength);
        put(porosity); put(id);
        if (carriesFines)
        {
            put(fines);
        }
        if (extra)
        {
            put(*extra);
        }
        if (extraStress)
        {
            put(*extraStress);
        }
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);

    // The number of arrivals from each sender first, so that each array
    // is resized once
    PtrList<UIPstream> from(nProcs);
    label nArriving = 0;
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            from.set(proci, new UIPstream(proci, pBufs));
            label nFrom = 0;
            from[proci] >> nFrom;
            nArriving += nFrom;
        }
    }
    if (leaving.empty() && !nArriving)
    {
        return;
    }

    // Keep the others, in their order
    label k = compact(leaving, extra, extraStress);
    if (k + nArriving != n)
    {
        setSize(k + nArriving);
        if (extra)
        {
            extra->setSize(k + nArriving);
        }
        if (extraStress)
        {
            extraStress->setSize(k + nArriving);
        }
    }

    // Append the arrivals by sending processor
    forAll(from, proci)
    {
        if (!from.set(proci))
        {
            continue;
        }
        UIPstream& is = from[proci];
        const label start = k;
        auto get = [&](auto& values)
        {
            typedef typename std::decay<decltype(values[0])>::type Type;
            const List<Type> in(is);
            forAll(in, i)
            {
                values[start + i] = in[i];
            }
            k = start + in.size();
        };
        get(x); get(v); get(m); get(V); get(V0); get(F); get(sigma);
        get(plasticStrain); get(C); get(material); get(halfLength);
        get(porosity); get(id);
        if (carriesFines)
        {
            get(fines);
        }
        if (extra)
        {
            get(*extra);
        }
        if (extraStress)
        {
            get(*extraStress);
        }
    }
}


namespace
{
    // FNV-1a over the bytes of a value
    template<class T>
    inline void fnv(uint64_t& h, const T& value)
    {
        const unsigned char* b = reinterpret_cast<const unsigned char*>(&value);
        for (size_t i = 0; i < sizeof(T); ++i)
        {
            h ^= b[i];
            h *= 1099511628211ULL;
        }
    }
}


Foam::HashTable<Foam::scalar> Foam::materialPoints::hashSums() const
{
    HashTable<scalar> sums;
    auto add = [&sums](const word& name, const auto& list)
    {
        scalar s = 0;
        forAll(list, i)
        {
            uint64_t h = 14695981039346656037ULL;
            fnv(h, list[i]);
            s += scalar(h & 0xFFFF);
        }
        sums.set(name, s);
    };
    add("x", x);
    add("U", v);
    add("mass", m);
    add("volume", V);
    add("initialVolume", V0);
    add("F", F);
    add("stress", sigma);
    add("plasticStrain", plasticStrain);
    add("C", C);
    add("material", material);
    add("halfLength", halfLength);
    add("porosity", porosity);
    add("origId", id);
    if (carriesFines)
    {
        add("fines", fines);
    }
    return sums;
}


bool Foam::materialPoints::read(const fvMesh& mesh, const word& timeName)
{
    IOobject posIO
    (
        "positions",
        timeName,
        cloud::prefix/cloudName,
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    IOobject coordIO(posIO);
    coordIO.rename("coordinates");
    const bool here =
        posIO.typeHeaderOk<IOField<vector>>(false)
     || coordIO.typeHeaderOk<IOField<vector>>(false);
    // A cloud whose positions are gone is damaged, not absent: read as
    // none, its soil vanished without a word. Which file OpenFOAM's cloud
    // reads (Cloud::readCloudUniformProperties): coordinates without a
    // uniform/lagrangian/<cloud>/cloudProperties, else the geometry it
    // names (positions if none: a cloud older than v1706). Per processor:
    // one that has the fields but not that file
    word geometry("coordinates");
    {
        const fileName props
        (
            mesh.time().path()/timeName/"uniform"/cloud::prefix/cloudName
           /"cloudProperties"
        );
        if (isFile(props))
        {
            geometry = "positions";
            // (a damaged file is refused naming it below)
            catchFatal
            (
                [&]()
                {
                    IFstream is(props);
                    const dictionary dict(is);
                    if (dict.getOrDefault<word>("geometry", "positions") == "coordinates")
                    {
                        geometry = "coordinates";
                    }
                },
                false
            );
        }
    }
    IOobject geometryIO(posIO);
    geometryIO.rename(geometry);
    IOobject massIO(posIO);
    massIO.rename("mass");
    const bool positionsGone =
        massIO.typeHeaderOk<IOField<scalar>>(false)
     && !geometryIO.typeHeaderOk<IOField<vector>>(false);
    if (returnReduce(positionsGone, orOp<bool>()))
    {
        // (every processor stops: those with their files name the
        // damaged one's by its place in the time)
        FatalErrorInFunction
            << "file: "
            << (
                   positionsGone
                 ? geometryIO.objectPath()
                 : fileName(timeName/cloud::prefix/cloudName/geometry)
               )
            << " is missing" << (positionsGone ? "" : " on a processor")
            << ": the"
            << " cloud " << cloudName << " of time " << timeName << " has"
            << " its fields (mass, ...) but not the points' positions, which"
            << " OpenFOAM reads from " << geometry << "." << nl
            << "    Restore it, restart from another time, or run"
            << " setMaterialPoints again" << exit(FatalError);
    }
    if (!returnReduce(here, orOp<bool>()))
    {
        return false;
    }

    // OpenFOAM's bookkeeping of the cloud (a particle counter per
    // processor), which the cloud reads: a damaged one is refused naming
    // it (OpenFOAM's own error named an IOstream). Its values are not used:
    // the points carry their identities
    {
        const fileName props
        (
            mesh.time().timePath()/"uniform"/cloud::prefix/cloudName
           /"cloudProperties"
        );
        const string damaged = catchFatal
        (
            [&]()
            {
                if (isFile(props))
                {
                    IFstream is(props);
                    const dictionary dict(is);
                    for (const entry& e : dict)
                    {
                        if (e.isDict())
                        {
                            e.dict().get<label>("particleCount");
                        }
                    }
                }
            },
            false
        );
        if (!damaged.empty())
        {
            FatalErrorInFunction
                << "file: " << props << " is damaged: " << damaged.c_str()
                << nl << "    Restore it, or remove it (it holds only"
                << " OpenFOAM's particle counter, which the soil does not"
                << " use)" << exit(FatalError);
        }
    }

    // (on every processor, those without points too: the cloud's
    // construction is collective)
    passiveParticleCloud cloud(mesh, cloudName, false);
    const label n = cloud.size();
    setSize(n);
    bool haveIds = true;
    if (n)
    {
        readFields(cloud, mesh.time().path()/timeName);
        haveIds = readField(cloud, "origId", id);
    }
    // Fines, where the points carry them (any processor's cloud)
    fines.clear();
    carriesFines = false;
    const bool haveFines = n && readField(cloud, "fines", fines);
    if (returnReduce(haveFines, orOp<bool>()))
    {
        checkFinite
        (
            fines,
            mesh.time().path()/timeName/"lagrangian"/cloudName/"fines",
            "values"
        );
        carriesFines = true;
        if (!haveFines)
        {
            fines.setSize(n, Zero);
        }
    }
    if (!returnReduce(haveIds, andOp<bool>()))
    {
        // (a cloud from elsewhere: numbered in processor order)
        const globalIndex offsets(n);
        forAll(id, i)
        {
            id[i] = offsets.toGlobal(i);
        }
    }
    return true;
}


void Foam::materialPoints::readFields
(
    const passiveParticleCloud& cloud,
    const fileName& where
)
{
    // Positions from the cloud, unless the exact binary copy is there
    if (!readField(cloud, "x", x))
    {
        label i = 0;
        for (const passiveParticle& p : cloud)
        {
            x[i++] = p.position();
        }
    }

    auto required = [&](const word& name, auto& values)
    {
        if (!readField(cloud, name, values))
        {
            FatalErrorInFunction
                << "The material points in " << where
                << "/lagrangian/" << cloudName << " have no field " << name
                << ": write them with setMaterialPoints or mpmLbmFoam"
                << exit(FatalError);
        }
    };
    required("U", v);
    required("mass", m);
    required("volume", V);
    required("initialVolume", V0);
    required("stress", sigma);
    required("plasticStrain", plasticStrain);
    required("material", material);
    required("halfLength", halfLength);
    required("porosity", porosity);
    if (!readField(cloud, "F", F))
    {
        F = tensor::I;
    }
    if (!readField(cloud, "C", C))
    {
        C = Zero;
    }

    // Damaged fields stop here, naming the file and the point
    const fileName dir(where/"lagrangian"/cloudName);
    checkFinite(x, dir/"x", "values");
    checkFinite(v, dir/"U", "values");
    checkFinite(m, dir/"mass", "values");
    checkFinite(V, dir/"volume", "values");
    checkFinite(V0, dir/"initialVolume", "values");
    checkFinite(sigma, dir/"stress", "values");
    checkFinite(plasticStrain, dir/"plasticStrain", "values");
    checkFinite(halfLength, dir/"halfLength", "values");
    checkFinite(porosity, dir/"porosity", "values");
    checkFinite(F, dir/"F", "values");
    checkFinite(C, dir/"C", "values");

    // Values no soil can have (a damaged or hand-made cloud): stopped here,
    // not by a floating-point trap or a silent answer steps later
    const boundBox bb(cloud.pMesh().bounds());
    const scalar tol = 1e-6*mag(bb.span());
    checkValues
    (
        x, dir/"x", "values",
        [&](const vector& p)
        {
            return
                p.x() >= bb.min().x() - tol && p.x() <= bb.max().x() + tol
             && p.y() >= bb.min().y() - tol && p.y() <= bb.max().y() + tol
             && p.z() >= bb.min().z() - tol && p.z() <= bb.max().z() + tol;
        },
        "inside the mesh, " + Foam::name(bb.min()) + " to "
      + Foam::name(bb.max())
    );
    auto positive = [](const scalar s) { return s > 0; };
    checkValues(m, dir/"mass", "values", positive, "positive: a mass");
    checkValues(V, dir/"volume", "values", positive, "positive: a volume");
    checkValues
    (
        V0, dir/"initialVolume", "values", positive, "positive: a volume"
    );
    checkValues
    (
        halfLength, dir/"halfLength", "values",
        [](const vector& h) { return h.x() > 0 && h.y() > 0 && h.z() > 0; },
        "positive in every direction: a point's half size"
    );
    checkValues
    (
        porosity, dir/"porosity", "values",
        [](const scalar n) { return n >= 0 && n < 1; },
        "in [0, 1): a porosity"
    );
    checkValues
    (
        F, dir/"F", "values",
        [](const tensor& f)
        {
            return cmptMax(cmptMag(f)) <= 1e6 && det(f) > 0;
        },
        "of positive determinant, within 1e6 in every component: a"
        " deformation gradient"
    );
    // (1e300 in the affine velocity overflowed the volume's update in the
    // first step)
    checkValues
    (
        C, dir/"C", "values",
        [](const tensor& c) { return cmptMax(cmptMag(c)) <= 1e8; },
        "within 1e8 1/s in every component: a velocity gradient"
    );
    checkValues
    (
        v, dir/"U", "values",
        [](const vector& u) { return cmptMax(cmptMag(u)) <= 1e5; },
        "within 1e5 m/s in every component: a soil's velocity"
    );
    checkValues
    (
        plasticStrain, dir/"plasticStrain", "values",
        [](const scalar e) { return e >= 0; },
        "non-negative: an accumulated plastic strain"
    );
    // (random bytes read as a double are mostly beyond any soil's: a
    // stress of 1e250 Pa ran into a floating-point trap in the first step)
    checkValues
    (
        sigma, dir/"stress", "values",
        [](const symmTensor& s) { return cmptMax(cmptMag(s)) <= 1e12; },
        "within 1e12 Pa in every component: a soil's stress (1 TPa is a"
        " thousand times a rock's strength)"
    );
    checkValues
    (
        v, dir/"U", "values",
        [](const vector& u) { return mag(u) <= 1e5; },
        "within 1e5 m/s: a soil's speed"
    );

    // The soil keeps V = det(F) V0 at every step (erosion shrinks V and
    // V0 alike): a volume, initial volume or deformation gradient damaged
    // alone breaks it (a damaged initialVolume ran away as det F 1e271)
    forAll(V, i)
    {
        const scalar J = det(F[i]);
        if (!(mag(V[i] - J*V0[i]) <= 1e-9*V[i]))
        {
            FatalErrorInFunction
                << "file: " << (dir/"volume").c_str() << ", values: volume "
                << V[i] << " at index " << i << " is not det(F) "
                << J << " x initialVolume " << V0[i] << " (" << J*V0[i]
                << "), as the soil keeps it." << nl
                << "    One of volume, initialVolume and F in " << dir.c_str()
                << " is damaged: restore them, or start from an earlier time"
                << " or from the initial fields" << exit(FatalError);
        }
    }
}


void Foam::materialPoints::write
(
    const fvMesh& mesh,
    const latticeMesh& lattice
) const
{
    // OpenFOAM's particle counter (uniform/lagrangian/.../cloudProperties,
    // for new particles' identities) counts this write's points only: the
    // points carry their own identity (origId), and a count carried on
    // from a read cloudProperties made a damaged one change every later
    // time's files without a word
    passiveParticle::particleCount_ = 0;
    passiveParticleCloud cloud(mesh, cloudName, IDLList<passiveParticle>());

    // Attach each point to its cell through the lattice (no search)
    const scalar dx = lattice.dx();
    const vector& origin = lattice.origin();
    const labelVector& bs = lattice.boxStart();
    const labelList& nodeCell = lattice.nodeCell();
    forAll(x, i)
    {
        labelVector b;
        for (direction d = 0; d < 3; ++d)
        {
            b[d] = (d == 2 && lattice.twoD())
                 ? 0
                 : label(std::floor((x[i][d] - origin[d])/dx)) - bs[d];
        }
        const label celli = nodeCell[lattice.node(b.x(), b.y(), b.z())];
        passiveParticle* p = new passiveParticle(mesh, x[i], celli);

        // The point's identity, the same whatever the decomposition
        p->origProc() = 0;
        p->origId() = id[i];
        cloud.addParticle(p);
    }
    cloud.write();
    if (!size())
    {
        // (a processor without points writes no cloud, as OpenFOAM's
        // clouds and decomposePar)
        return;
    }

    // All in binary, whatever the case's format: a restart continues
    // exactly, and ParaView reads binary fields as well
    writeField(cloud, "x", x, true);
    writeField(cloud, "U", v, true);
    writeField(cloud, "mass", m, true);
    writeField(cloud, "volume", V, true);
    writeField(cloud, "initialVolume", V0, true);
    writeField(cloud, "stress", sigma, true);
    writeField(cloud, "plasticStrain", plasticStrain, true);
    writeField(cloud, "material", material, true);
    writeField(cloud, "halfLength", halfLength, true);
    writeField(cloud, "porosity", porosity, true);
    writeField(cloud, "F", F, true);
    writeField(cloud, "C", C, true);
    if (carriesFines)
    {
        writeField(cloud, "fines", fines, true);
    }
    scalarList pressure(size());
    forAll(pressure, i)
    {
        pressure[i] = -tr(sigma[i])/3.0;
    }
    writeField(cloud, "pressure", pressure, true);
}


// ************************************************************************* //
