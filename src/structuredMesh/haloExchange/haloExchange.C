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

#include "haloExchange.H"
#include "PstreamBuffers.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::haloExchange::haloExchange()
:
    sendNodes_(Pstream::nProcs()),
    recvNodes_(Pstream::nProcs())
{}


Foam::haloExchange::haloExchange
(
    const labelUList& haloNodes,
    const labelUList& haloOwnerProc,
    const labelUList& haloOwnerNode
)
:
    sendNodes_(Pstream::nProcs()),
    recvNodes_(Pstream::nProcs())
{
    const label nProcs = Pstream::nProcs();

    List<DynamicList<label>> recv(nProcs);
    List<DynamicList<label>> request(nProcs);
    forAll(haloNodes, i)
    {
        recv[haloOwnerProc[i]].append(haloNodes[i]);
        request[haloOwnerProc[i]].append(haloOwnerNode[i]);
    }
    forAll(recv, proci)
    {
        recvNodes_[proci].transfer(recv[proci]);
    }

    // Tell each owner which of its nodes we need, in our receive order
    const label myProc = Pstream::myProcNo();
    sendNodes_[myProc] = request[myProc];

    if (Pstream::parRun())
    {
        PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (proci != myProc)
            {
                UOPstream toProc(proci, pBufs);
                toProc << labelList(request[proci]);
            }
        }
        pBufs.finishedSends();
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (proci != myProc)
            {
                UIPstream fromProc(proci, pBufs);
                fromProc >> sendNodes_[proci];
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::haloExchange::nRecv() const
{
    label n = 0;
    forAll(recvNodes_, proci)
    {
        n += recvNodes_[proci].size();
    }
    return n;
}


Foam::label Foam::haloExchange::nSend() const
{
    label n = 0;
    forAll(sendNodes_, proci)
    {
        n += sendNodes_[proci].size();
    }
    return n;
}


Foam::labelList Foam::haloExchange::neighbours() const
{
    DynamicList<label> procs;
    forAll(recvNodes_, proci)
    {
        if (recvNodes_[proci].size() || sendNodes_[proci].size())
        {
            procs.append(proci);
        }
    }
    return labelList(procs);
}


void Foam::haloExchange::exchange
(
    scalar* data,
    const labelUList& components,
    const label componentStride
) const
{
    const label myProc = Pstream::myProcNo();

    // Periodic copies within this processor first: no communication
    {
        const labelList& send = sendNodes_[myProc];
        const labelList& recv = recvNodes_[myProc];
        forAll(components, ci)
        {
            scalar* __restrict__ d = data + components[ci]*componentStride;
            forAll(send, i)
            {
                d[recv[i]] = d[send[i]];
            }
        }
    }

    if (!Pstream::parRun())
    {
        return;
    }

    const label nComp = components.size();
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);

    forAll(sendNodes_, proci)
    {
        const labelList& send = sendNodes_[proci];
        if (proci == myProc || send.empty())
        {
            continue;
        }
        scalarList buf(nComp*send.size());
        label k = 0;
        forAll(components, ci)
        {
            const scalar* d = data + components[ci]*componentStride;
            forAll(send, i)
            {
                buf[k++] = d[send[i]];
            }
        }
        UOPstream toProc(proci, pBufs);
        toProc << buf;
    }
    pBufs.finishedSends();

    forAll(recvNodes_, proci)
    {
        const labelList& recv = recvNodes_[proci];
        if (proci == myProc || recv.empty())
        {
            continue;
        }
        scalarList buf;
        UIPstream fromProc(proci, pBufs);
        fromProc >> buf;
        label k = 0;
        forAll(components, ci)
        {
            scalar* d = data + components[ci]*componentStride;
            forAll(recv, i)
            {
                d[recv[i]] = buf[k++];
            }
        }
    }
}


void Foam::haloExchange::exchange
(
    scalar* data,
    const label nComponents,
    const label componentStride
) const
{
    labelList components(nComponents);
    forAll(components, ci)
    {
        components[ci] = ci;
    }
    exchange(data, components, componentStride);
}


void Foam::haloExchange::setComponents(const labelListList& recvComponents)
{
    const label myProc = Pstream::myProcNo();
    recvComponents_ = recvComponents;
    sendComponents_.setSize(Pstream::nProcs());
    sendComponents_[myProc] = recvComponents_[myProc];

    if (Pstream::parRun())
    {
        PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
        forAll(recvComponents_, proci)
        {
            if (proci != myProc)
            {
                UOPstream toProc(proci, pBufs);
                toProc << recvComponents_[proci];
            }
        }
        pBufs.finishedSends();
        forAll(sendComponents_, proci)
        {
            if (proci != myProc)
            {
                UIPstream fromProc(proci, pBufs);
                fromProc >> sendComponents_[proci];
            }
        }
    }
}


void Foam::haloExchange::exchangeSelected
(
    scalar* data,
    const label componentStride
) const
{
    const label myProc = Pstream::myProcNo();

    // Periodic copies within this processor
    {
        const labelList& send = sendNodes_[myProc];
        const labelList& recv = recvNodes_[myProc];
        for (const label c : recvComponents_[myProc])
        {
            scalar* __restrict__ d = data + c*componentStride;
            forAll(send, i)
            {
                d[recv[i]] = d[send[i]];
            }
        }
    }

    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(sendNodes_, proci)
    {
        const labelList& send = sendNodes_[proci];
        const labelList& comps = sendComponents_[proci];
        if (proci == myProc || send.empty() || comps.empty())
        {
            continue;
        }
        scalarList buf(comps.size()*send.size());
        label k = 0;
        for (const label c : comps)
        {
            const scalar* d = data + c*componentStride;
            forAll(send, i)
            {
                buf[k++] = d[send[i]];
            }
        }
        UOPstream toProc(proci, pBufs);
        toProc << buf;
    }
    pBufs.finishedSends();

    forAll(recvNodes_, proci)
    {
        const labelList& recv = recvNodes_[proci];
        const labelList& comps = recvComponents_[proci];
        if (proci == myProc || recv.empty() || comps.empty())
        {
            continue;
        }
        scalarList buf;
        UIPstream fromProc(proci, pBufs);
        fromProc >> buf;
        label k = 0;
        for (const label c : comps)
        {
            scalar* d = data + c*componentStride;
            forAll(recv, i)
            {
                d[recv[i]] = buf[k++];
            }
        }
    }
}


void Foam::haloExchange::exchange(labelUList& data) const
{
    const label myProc = Pstream::myProcNo();
    {
        const labelList& send = sendNodes_[myProc];
        const labelList& recv = recvNodes_[myProc];
        forAll(send, i)
        {
            data[recv[i]] = data[send[i]];
        }
    }
    if (!Pstream::parRun())
    {
        return;
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(sendNodes_, proci)
    {
        const labelList& send = sendNodes_[proci];
        if (proci != myProc && send.size())
        {
            UOPstream toProc(proci, pBufs);
            toProc << labelList(UIndirectList<label>(data, send));
        }
    }
    pBufs.finishedSends();
    forAll(recvNodes_, proci)
    {
        const labelList& recv = recvNodes_[proci];
        if (proci != myProc && recv.size())
        {
            labelList buf;
            UIPstream fromProc(proci, pBufs);
            fromProc >> buf;
            forAll(recv, i)
            {
                data[recv[i]] = buf[i];
            }
        }
    }
}


void Foam::haloExchange::copyToHalo
(
    std::initializer_list<nodeField> fields
) const
{
    const label myProc = Pstream::myProcNo();

    // Periodic images on this processor: no communication
    {
        const labelList& send = sendNodes_[myProc];
        const labelList& recv = recvNodes_[myProc];
        for (const nodeField& f : fields)
        {
            const label nc = f.nComponents;
            scalar* __restrict__ d = f.data;
            forAll(send, i)
            {
                for (label c = 0; c < nc; ++c)
                {
                    d[recv[i]*nc + c] = d[send[i]*nc + c];
                }
            }
        }
    }

    if (!Pstream::parRun())
    {
        return;
    }

    label nComp = 0;
    for (const nodeField& f : fields)
    {
        nComp += f.nComponents;
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(sendNodes_, proci)
    {
        const labelList& send = sendNodes_[proci];
        if (proci == myProc || send.empty())
        {
            continue;
        }
        scalarList buf(nComp*send.size());
        label k = 0;
        for (const nodeField& f : fields)
        {
            const label nc = f.nComponents;
            const scalar* d = f.data;
            forAll(send, i)
            {
                for (label c = 0; c < nc; ++c)
                {
                    buf[k++] = d[send[i]*nc + c];
                }
            }
        }
        UOPstream toProc(proci, pBufs);
        toProc << buf;
    }
    pBufs.finishedSends();

    forAll(recvNodes_, proci)
    {
        const labelList& recv = recvNodes_[proci];
        if (proci == myProc || recv.empty())
        {
            continue;
        }
        scalarList buf;
        UIPstream fromProc(proci, pBufs);
        fromProc >> buf;
        label k = 0;
        for (const nodeField& f : fields)
        {
            const label nc = f.nComponents;
            scalar* d = f.data;
            forAll(recv, i)
            {
                for (label c = 0; c < nc; ++c)
                {
                    d[recv[i]*nc + c] = buf[k++];
                }
            }
        }
    }
}


void Foam::haloExchange::addToOwners
(
    std::initializer_list<nodeField> fields
) const
{
    const label myProc = Pstream::myProcNo();

    // The images' values travel the copy's routes backwards: from the
    // receiving halo nodes to the sending owner nodes. Periodic images on
    // this processor first, then the other processors in rank order (a
    // fixed order of the additions: the run repeats itself exactly)
    {
        const labelList& send = sendNodes_[myProc];
        const labelList& recv = recvNodes_[myProc];
        for (const nodeField& f : fields)
        {
            const label nc = f.nComponents;
            scalar* __restrict__ d = f.data;
            forAll(send, i)
            {
                for (label c = 0; c < nc; ++c)
                {
                    d[send[i]*nc + c] += d[recv[i]*nc + c];
                }
            }
        }
    }

    if (!Pstream::parRun())
    {
        return;
    }

    label nComp = 0;
    for (const nodeField& f : fields)
    {
        nComp += f.nComponents;
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(recvNodes_, proci)
    {
        const labelList& recv = recvNodes_[proci];
        if (proci == myProc || recv.empty())
        {
            continue;
        }
        scalarList buf(nComp*recv.size());
        label k = 0;
        for (const nodeField& f : fields)
        {
            const label nc = f.nComponents;
            const scalar* d = f.data;
            forAll(recv, i)
            {
                for (label c = 0; c < nc; ++c)
                {
                    buf[k++] = d[recv[i]*nc + c];
                }
            }
        }
        UOPstream toProc(proci, pBufs);
        toProc << buf;
    }
    pBufs.finishedSends();

    forAll(sendNodes_, proci)
    {
        const labelList& send = sendNodes_[proci];
        if (proci == myProc || send.empty())
        {
            continue;
        }
        scalarList buf;
        UIPstream fromProc(proci, pBufs);
        fromProc >> buf;
        label k = 0;
        for (const nodeField& f : fields)
        {
            const label nc = f.nComponents;
            scalar* d = f.data;
            forAll(send, i)
            {
                for (label c = 0; c < nc; ++c)
                {
                    d[send[i]*nc + c] += buf[k++];
                }
            }
        }
    }
}


// ************************************************************************* //
