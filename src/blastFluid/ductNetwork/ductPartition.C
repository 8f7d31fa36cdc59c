/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "ductPartition.H"
#include "Pstream.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include <algorithm>
#include <utility>
#include <vector>

// * * * * * * * * * * * * * * * * Local Data * * * * * * * * * * * * * * * //

namespace
{
    // Message tag of the ghost exchange (the solid's halo uses 4711)
    constexpr int ductTag = 4713;

    // Sorted, each once
    void uniqueSort(std::vector<std::pair<Foam::label, Foam::label>>& l)
    {
        std::sort(l.begin(), l.end());
        l.erase(std::unique(l.begin(), l.end()), l.end());
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ductPartition::ductPartition()
:
    whole_(true)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::ductPartition::setWhole(const label n, const label nf)
{
    whole_ = true;
    if (own_.size() != n || active_.size() != n)
    {
        own_ = identity(n);
        active_ = own_;
    }
    if (faces_.size() != nf)
    {
        faces_ = identity(nf);
    }
    ghosts_.clear();
    procs_.clear();
}


void Foam::ductPartition::set
(
    const labelUList& volumeRank,
    const labelUList& owner,
    const labelUList& neighbour
)
{
    whole_ = false;
    const label me = Pstream::myProcNo();

    // The interfaces with an own end, and per interface between two
    // ranks what crosses it: (other rank, its volume) received, (other
    // rank, own volume) sent
    std::vector<std::pair<label, label>> in, out;
    DynamicList<label> faces(owner.size());
    forAll(owner, f)
    {
        const label P = owner[f], N = neighbour[f];
        const label rP = volumeRank[P], rN = N >= 0 ? volumeRank[N] : rP;
        if (rP != me && rN != me) continue;
        faces.append(f);
        if (rP == rN) continue;
        if (rP == me)
        {
            in.emplace_back(rN, N);
            out.emplace_back(rN, P);
        }
        else
        {
            in.emplace_back(rP, P);
            out.emplace_back(rP, N);
        }
    }
    faces_.transfer(faces);
    uniqueSort(in);
    uniqueSort(out);

    DynamicList<label> own(volumeRank.size());
    forAll(volumeRank, i)
    {
        if (volumeRank[i] == me) own.append(i);
    }
    own_.transfer(own);
    ghosts_.setSize(in.size());
    forAll(ghosts_, k)
    {
        ghosts_[k] = in[k].second;
    }
    Foam::sort(ghosts_);
    active_.setSize(own_.size() + ghosts_.size());
    std::merge
    (
        own_.cbegin(), own_.cend(), ghosts_.cbegin(), ghosts_.cend(),
        active_.begin()
    );

    // The ranks of the messages: a face's two sides list each other
    DynamicList<label> procs;
    for (const auto& p : in) procs.append(p.first);
    for (const auto& p : out) procs.append(p.first);
    Foam::sort(procs);
    label m = 0;
    forAll(procs, i)
    {
        if (m == 0 || procs[i] != procs[m - 1]) procs[m++] = procs[i];
    }
    procs.setSize(m);
    procs_.transfer(procs);
    send_.setSize(procs_.size());
    recv_.setSize(procs_.size());
    sendBuf_.setSize(procs_.size());
    recvBuf_.setSize(procs_.size());
    forAll(procs_, i)
    {
        DynamicList<label> s, r;
        for (const auto& p : out) if (p.first == procs_[i]) s.append(p.second);
        for (const auto& p : in) if (p.first == procs_[i]) r.append(p.second);
        send_[i].transfer(s);
        recv_[i].transfer(r);
    }
}


void Foam::ductPartition::exchange
(
    std::initializer_list<scalarField*> scalars,
    std::initializer_list<vectorField*> vectors
)
{
    if (whole_ || procs_.empty()) return;
    const label nComp = scalars.size() + 3*vectors.size();

    const label start = UPstream::nRequests();
    forAll(procs_, i)
    {
        scalarList& buf = recvBuf_[i];
        buf.setSize(nComp*recv_[i].size());
        if (buf.empty()) continue;
        UIPstream::read
        (
            UPstream::commsTypes::nonBlocking, procs_[i],
            reinterpret_cast<char*>(buf.data()), buf.byteSize(), ductTag
        );
    }
    forAll(procs_, i)
    {
        scalarList& buf = sendBuf_[i];
        buf.setSize(nComp*send_[i].size());
        if (buf.empty()) continue;
        scalar* b = buf.data();
        for (const label v : send_[i])
        {
            for (const scalarField* s : scalars) *b++ = (*s)[v];
            for (const vectorField* u : vectors)
            {
                const vector& x = (*u)[v];
                *b++ = x.x(); *b++ = x.y(); *b++ = x.z();
            }
        }
        UOPstream::write
        (
            UPstream::commsTypes::nonBlocking, procs_[i],
            reinterpret_cast<const char*>(buf.cdata()), buf.byteSize(),
            ductTag
        );
    }
    UPstream::waitRequests(start);
    forAll(procs_, i)
    {
        const scalar* b = recvBuf_[i].cdata();
        for (const label v : recv_[i])
        {
            for (scalarField* s : scalars) (*s)[v] = *b++;
            for (vectorField* u : vectors)
            {
                vector& x = (*u)[v];
                x.x() = *b++; x.y() = *b++; x.z() = *b++;
            }
        }
    }
}


void Foam::ductPartition::fromOwners
(
    UList<scalar>& values,
    const label nComp,
    const labelUList& itemRank
)
{
    if (!Pstream::parRun()) return;
    const label me = Pstream::myProcNo();
    List<scalarList> all(Pstream::nProcs());
    {
        DynamicList<scalar> mine(values.size());
        forAll(itemRank, i)
        {
            if (itemRank[i] != me) continue;
            for (label k = 0; k < nComp; ++k) mine.append(values[nComp*i + k]);
        }
        all[me].transfer(mine);
    }
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    labelList pos(Pstream::nProcs(), 0);
    forAll(itemRank, i)
    {
        const label r = itemRank[i];
        if (r != me)
        {
            const scalarList& from = all[r];
            for (label k = 0; k < nComp; ++k)
            {
                values[nComp*i + k] = from[pos[r] + k];
            }
        }
        pos[r] += nComp;
    }
}


// ************************************************************************* //
