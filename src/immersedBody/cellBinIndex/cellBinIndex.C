/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "cellBinIndex.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::FixedList<Foam::label, 4> Foam::cellBinIndex::binRange
(
    const UList<vector2D>& vertices,
    const labelUList& polygonStart,
    const label p
) const
{
    vector2D lo(GREAT, GREAT), hi(-GREAT, -GREAT);
    for (label k = polygonStart[p]; k < polygonStart[p + 1]; ++k)
    {
        lo = min(lo, vertices[k]);
        hi = max(hi, vertices[k]);
    }
    return FixedList<label, 4>({binX(lo.x()), binX(hi.x()), binY(lo.y()), binY(hi.y())});
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cellBinIndex::cellBinIndex
(
    const UList<vector2D>& vertices,
    const labelUList& polygonStart
)
:
    origin_(Zero),
    binSize_(1, 1),
    invBinSize_(1, 1),
    nx_(1),
    ny_(1),
    nbx_(1),
    nby_(1)
{
    const label nPolygons = polygonStart.size() - 1;
    // Polygons without vertices are in no bin and do not size the bins
    label nPlaced = 0;
    for (label p = 0; p < nPolygons; ++p)
    {
        if (polygonStart[p + 1] > polygonStart[p]) ++nPlaced;
    }

    vector2D lo(GREAT, GREAT), hi(-GREAT, -GREAT);
    for (const vector2D& v : vertices)
    {
        lo = min(lo, v);
        hi = max(hi, v);
    }
    if (nPlaced > 0)
    {
        // Square-ish bins, about one polygon each
        const vector2D span = max(hi - lo, vector2D(SMALL, SMALL));
        const scalar binEdge = Foam::sqrt(span.x()*span.y()/nPlaced);
        nx_ = max(label(1), min(label(span.x()/binEdge) + 1, nPlaced));
        ny_ = max(label(1), min(label(span.y()/binEdge) + 1, nPlaced));
        origin_ = lo;
        binSize_ = vector2D(span.x()/nx_, span.y()/ny_)*(1 + 1e-12);
        invBinSize_ = vector2D(1/binSize_.x(), 1/binSize_.y());
    }

    nbx_ = (nx_ + blockSize - 1)/blockSize;
    nby_ = (ny_ + blockSize - 1)/blockSize;

    // Two passes: count, then fill (CSR)
    binStart_.setSize(nx_*ny_ + 1, Zero);
    for (label p = 0; p < nPolygons; ++p)
    {
        if (polygonStart[p + 1] == polygonStart[p]) continue;
        const FixedList<label, 4> r = binRange(vertices, polygonStart, p);
        for (label j = r[2]; j <= r[3]; ++j)
        {
            for (label i = r[0]; i <= r[1]; ++i)
            {
                ++binStart_[j*nx_ + i + 1];
            }
        }
    }
    for (label b = 0; b < nx_*ny_; ++b)
    {
        binStart_[b + 1] += binStart_[b];
    }
    binItems_.setSize(binStart_.last());
    labelList fill(SubList<label>(binStart_, nx_*ny_));
    for (label p = 0; p < nPolygons; ++p)
    {
        if (polygonStart[p + 1] == polygonStart[p]) continue;
        const FixedList<label, 4> r = binRange(vertices, polygonStart, p);
        for (label j = r[2]; j <= r[3]; ++j)
        {
            for (label i = r[0]; i <= r[1]; ++i)
            {
                binItems_[fill[j*nx_ + i]++] = p;
            }
        }
    }
}


// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

constexpr Foam::label Foam::cellBinIndex::blockSize;


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellBinIndex::clearSet(binSet& s) const
{
    const label nBlocks = nbx_*nby_;
    if (s.flag.size() != nBins() || s.blockCount.size() != nBlocks)
    {
        s.flag.setSize(nBins());
        s.flag = false;
        s.blockCount.setSize(nBlocks);
        s.blockCount = 0;
        s.flagged.clear();
        return;
    }
    for (const label b : s.flagged)
    {
        s.flag[b] = false;
        s.blockCount[blockOf(b)] = 0;
    }
    s.flagged.clear();
}


void Foam::cellBinIndex::finishSet(binSet& s) const
{
    const label w = nbx_ + 1;
    labelList& t = s.blockTable;
    t.setSize(w*(nby_ + 1));
    for (label i = 0; i < w; ++i)
    {
        t[i] = 0;
    }
    for (label bj = 0; bj < nby_; ++bj)
    {
        label row = 0;
        t[(bj + 1)*w] = 0;
        for (label bi = 0; bi < nbx_; ++bi)
        {
            row += s.blockCount[bj*nbx_ + bi];
            t[(bj + 1)*w + bi + 1] = t[bj*w + bi + 1] + row;
        }
    }
}


// ************************************************************************* //
