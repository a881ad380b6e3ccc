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
#include "ListOps.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

// Call visit(value) for every value of the nodes of a list, node by node
// and component by component (the order of packing and unpacking)
template<class Type, class Visit>
inline void forEachValue
(
    const haloExchange::nodeList<Type>& list,
    const labelUList& nodes,
    const Visit& visit
)
{
    const label nc = list.nComponents;
    Type* __restrict__ d = list.data;
    if (nc == 1)
    {
        for (const label n : nodes)
        {
            visit(d[n]);
        }
    }
    else
    {
        for (const label n : nodes)
        {
            for (label c = 0; c < nc; ++c)
            {
                visit(d[n*nc + c]);
            }
        }
    }
}


// Combine the values of the nodes from[i] of a list into its nodes to[i]:
// the periodic images on this processor
template<class Type, class CombineOp>
inline void combineLocal
(
    const haloExchange::nodeList<Type>& list,
    const labelUList& from,
    const labelUList& to,
    const CombineOp& combine
)
{
    const label nc = list.nComponents;
    Type* d = list.data;
    forAll(from, i)
    {
        for (label c = 0; c < nc; ++c)
        {
            combine(d[to[i]*nc + c], d[from[i]*nc + c]);
        }
    }
}


// Call act(list) for the lists selected for processor proci (all if
// selection is nullptr)
template<class Type, class Action>
inline void forEachSelected
(
    const UList<haloExchange::nodeList<Type>>& lists,
    const labelListList* selection,
    const label proci,
    const Action& act
)
{
    if (selection)
    {
        for (const label i : (*selection)[proci])
        {
            act(lists[i]);
        }
    }
    else
    {
        for (const haloExchange::nodeList<Type>& list : lists)
        {
            act(list);
        }
    }
}

} // End namespace Foam


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type, class CombineOp>
void Foam::haloExchange::transfer
(
    const UList<nodeList<Type>>& lists,
    const labelListList& fromNodes,
    const labelListList& toNodes,
    const labelListList* fromLists,
    const labelListList* toLists,
    const CombineOp& combine
) const
{
    const label myProc = Pstream::myProcNo();

    // Periodic images on this processor: no communication, and first (a
    // fixed order of the additions: the run repeats itself exactly)
    forEachSelected
    (
        lists, toLists, myProc,
        [&](const nodeList<Type>& list)
        {
            combineLocal(list, fromNodes[myProc], toNodes[myProc], combine);
        }
    );

    if (!Pstream::parRun())
    {
        return;
    }

    // Number of values per node in the message to or from proci
    auto nValues = [&](const labelListList* selection, const label proci)
    {
        label n = 0;
        forEachSelected
        (
            lists, selection, proci,
            [&](const nodeList<Type>& list) { n += list.nComponents; }
        );
        return n;
    };

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(fromNodes, proci)
    {
        const labelList& nodes = fromNodes[proci];
        const label nv = nValues(fromLists, proci);
        if (proci == myProc || nodes.empty() || nv == 0)
        {
            continue;
        }
        List<Type> buf(nv*nodes.size());
        label k = 0;
        forEachSelected
        (
            lists, fromLists, proci,
            [&](const nodeList<Type>& list)
            {
                forEachValue
                (
                    list, nodes, [&](const Type& x) { buf[k++] = x; }
                );
            }
        );
        UOPstream toProc(proci, pBufs);
        toProc << buf;
    }
    pBufs.finishedSends();

    forAll(toNodes, proci)
    {
        const labelList& nodes = toNodes[proci];
        if (proci == myProc || nodes.empty() || nValues(toLists, proci) == 0)
        {
            continue;
        }
        List<Type> buf;
        UIPstream fromProc(proci, pBufs);
        fromProc >> buf;
        label k = 0;
        forEachSelected
        (
            lists, toLists, proci,
            [&](const nodeList<Type>& list)
            {
                forEachValue
                (
                    list, nodes, [&](Type& x) { combine(x, buf[k++]); }
                );
            }
        );
    }
}


Foam::List<Foam::haloExchange::nodeField> Foam::haloExchange::componentLists
(
    scalar* data,
    const labelUList& components,
    const label componentStride
)
{
    List<nodeField> lists(components.size());
    forAll(components, ci)
    {
        lists[ci] = nodeField{data + components[ci]*componentStride, 1};
    }
    return lists;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::haloExchange::haloExchange()
:
    sendNodes_(Pstream::nProcs()),
    recvNodes_(Pstream::nProcs()),
    nSelectable_(0)
{}


Foam::haloExchange::haloExchange
(
    const labelUList& haloNodes,
    const labelUList& haloOwnerProc,
    const labelUList& haloOwnerNode
)
:
    sendNodes_(Pstream::nProcs()),
    recvNodes_(Pstream::nProcs()),
    nSelectable_(0)
{
    const label nProcs = Pstream::nProcs();

    List<DynamicList<label>> recv(nProcs);
    List<DynamicList<label>> request(nProcs);
    forAll(haloNodes, i)
    {
        recv[haloOwnerProc[i]].append(haloNodes[i]);
        request[haloOwnerProc[i]].append(haloOwnerNode[i]);
    }
    labelListList requested(nProcs);
    forAll(recv, proci)
    {
        recvNodes_[proci].transfer(recv[proci]);
        requested[proci].transfer(request[proci]);
    }

    // Tell each owner which of its nodes we need, in our receive order
    Pstream::exchange<labelList, label>(requested, sendNodes_);
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
    transfer
    (
        componentLists(data, components, componentStride),
        sendNodes_, recvNodes_, nullptr, nullptr, assignOp()
    );
}


void Foam::haloExchange::exchange
(
    scalar* data,
    const label nComponents,
    const label componentStride
) const
{
    exchange(data, identity(nComponents), componentStride);
}


void Foam::haloExchange::setComponents(const labelListList& recvComponents)
{
    recvComponents_ = recvComponents;

    // Tell each processor which components we need from it
    Pstream::exchange<labelList, label>(recvComponents_, sendComponents_);

    nSelectable_ = 0;
    for (const labelListList* comps : {&recvComponents_, &sendComponents_})
    {
        for (const labelList& c : *comps)
        {
            for (const label ci : c)
            {
                nSelectable_ = max(nSelectable_, ci + 1);
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
    transfer
    (
        componentLists(data, identity(nSelectable_), componentStride),
        sendNodes_, recvNodes_, &sendComponents_, &recvComponents_,
        assignOp()
    );
}


void Foam::haloExchange::exchangeSelected
(
    scalar* data,
    const labelUList& componentStart
) const
{
    List<nodeField> lists(nSelectable_);
    forAll(lists, ci)
    {
        lists[ci] = nodeField{data + componentStart[ci], 1};
    }
    transfer
    (
        lists, sendNodes_, recvNodes_, &sendComponents_, &recvComponents_,
        assignOp()
    );
}


void Foam::haloExchange::exchange(labelUList& data) const
{
    transfer
    (
        List<nodeList<label>>(1, nodeList<label>{data.data(), 1}),
        sendNodes_, recvNodes_, nullptr, nullptr, assignOp()
    );
}


void Foam::haloExchange::copyToHalo
(
    std::initializer_list<nodeField> fields
) const
{
    transfer
    (
        List<nodeField>(fields),
        sendNodes_, recvNodes_, nullptr, nullptr, assignOp()
    );
}


void Foam::haloExchange::addToOwners
(
    std::initializer_list<nodeField> fields
) const
{
    // The images' values travel the copy's routes backwards: from the
    // receiving halo nodes to the sending owner nodes
    transfer
    (
        List<nodeField>(fields),
        recvNodes_, sendNodes_, nullptr, nullptr, addOp()
    );
}


void Foam::haloExchange::copyToHalo
(
    std::initializer_list<nodeField> fields,
    const routes& r
) const
{
    transfer
    (
        List<nodeField>(fields), r.send, r.recv, nullptr, nullptr, assignOp()
    );
}


void Foam::haloExchange::addToOwners
(
    std::initializer_list<nodeField> fields,
    const routes& r
) const
{
    transfer
    (
        List<nodeField>(fields), r.recv, r.send, nullptr, nullptr, addOp()
    );
}


// ************************************************************************* //
