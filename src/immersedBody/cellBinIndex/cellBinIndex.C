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
    ny_(1)
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cellBinIndex::countFlagged
(
    const UList<bool>& binFlag,
    labelList& table
) const
{
    const label w = nx_ + 1;
    table.setSize(w*(ny_ + 1));
    for (label i = 0; i < w; ++i)
    {
        table[i] = 0;
    }
    for (label j = 0; j < ny_; ++j)
    {
        label row = 0;
        table[(j + 1)*w] = 0;
        for (label i = 0; i < nx_; ++i)
        {
            row += binFlag[j*nx_ + i];
            table[(j + 1)*w + i + 1] = table[j*w + i + 1] + row;
        }
    }
}


// ************************************************************************* //
