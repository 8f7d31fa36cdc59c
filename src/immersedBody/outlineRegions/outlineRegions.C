/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

\*---------------------------------------------------------------------------*/

#include "outlineRegions.H"
#include "SubList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::outlineRegions::outlineRegions
(
    const labelUList& owner,
    const labelUList& neighbour,
    const solidProjection& projection
)
:
    centroid_(projection.cellCentroids()),
    tol_(1e-8*projection.maxCellSize()),
    state_(projection.nCells(), -1),
    rep_(projection.nCells(), -1),
    queue_(projection.nCells()),
    nbrStart_(projection.nCells() + 1, 0)
{
    // Contiguous neighbour lists (walked every step)
    const label nCells = projection.nCells();
    forAll(neighbour, f)
    {
        if (neighbour[f] < 0) continue;
        ++nbrStart_[owner[f] + 1];
        ++nbrStart_[neighbour[f] + 1];
    }
    for (label c = 0; c < nCells; ++c)
    {
        nbrStart_[c + 1] += nbrStart_[c];
    }
    nbr_.setSize(nbrStart_[nCells]);
    labelList fill(SubList<label>(nbrStart_, nCells));
    forAll(neighbour, f)
    {
        if (neighbour[f] < 0) continue;
        nbr_[fill[owner[f]]++] = neighbour[f];
        nbr_[fill[neighbour[f]]++] = owner[f];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::outlineRegions::update
(
    const UList<bool>& near,
    const vector2D& lo,
    const vector2D& hi
)
{
    // rep_: -1 near; -2 far, not yet in a region; -3 centroid outside the
    // solid's box [lo, hi] (no triangle's box holds it: no triangle tests
    // it, gas either way, not walked)
    forAll(rep_, c)
    {
        const vector2D& x = centroid_[c];
        const bool inBox =
            x.x() >= lo.x() && x.x() <= hi.x()
         && x.y() >= lo.y() && x.y() <= hi.y();
        rep_[c] = near[c] ? -1 : inBox ? -2 : -3;
    }

    // Regions: breadth-first through the faces between far cells; the
    // first cell of each (lowest label) represents it
    reps_.clear();
    forAll(rep_, seed)
    {
        if (rep_[seed] != -2) continue;
        reps_.append(seed);
        rep_[seed] = seed;
        label head = 0, tail = 0;
        queue_[tail++] = seed;
        while (head < tail)
        {
            const label c = queue_[head++];
            for (label j = nbrStart_[c]; j < nbrStart_[c + 1]; ++j)
            {
                const label n = nbr_[j];
                if (rep_[n] == -2)
                {
                    rep_[n] = seed;
                    queue_[tail++] = n;
                }
            }
        }
    }
    forAll(state_, c)
    {
        const label r = rep_[c];
        state_[c] = r == -1 || r == c ? -1 : 0;
    }
}


void Foam::outlineRegions::fill(scalarField& alphaSolid) const
{
    forAll(rep_, c)
    {
        const label r = rep_[c];
        if (r >= 0 && r != c)
        {
            alphaSolid[c] = alphaSolid[r];
        }
    }
}


// ************************************************************************* //
