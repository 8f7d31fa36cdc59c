/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    The geometry of a cut-cell step (see cutCellGeometry.H).

\*---------------------------------------------------------------------------*/

#include "cutCellGeometry.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cutCellGeometry::cutCellGeometry
(
    const fvMesh& mesh,
    const blastFaceAddressing& addr
)
:
    mesh_(mesh),
    addr_(addr),
    aperture_(addr.nFaces(), 1),
    wallVector_(mesh.nCells(), Zero),
    sweptVolume_(mesh.nCells(), 0)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::cutCellGeometry::meshFaceAperture(const label f) const
{
    if (f < addr_.nInternal()) return aperture_[f];
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const label patchi = pbm.whichPatch(f);
    if (addr_.kinds()[patchi] == blastFaceAddressing::SKIP) return 0;
    return aperture_[addr_.patchStart()[patchi] + f - pbm[patchi].start()];
}


void Foam::cutCellGeometry::loadApertures
(
    const surfaceScalarField& aperture
)
{
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        aperture_[f] = aperture[f];
    }
    forAll(addr_.kinds(), patchi)
    {
        if (addr_.kinds()[patchi] == blastFaceAddressing::SKIP) continue;
        const scalarField& ap = aperture.boundaryField()[patchi];
        const label start = addr_.patchStart()[patchi];
        forAll(ap, j)
        {
            aperture_[start + j] = ap[j];
        }
    }
}


void Foam::cutCellGeometry::set
(
    const volScalarField& phi0Field,
    volScalarField& phi1Field,
    const surfaceScalarField& aperture
)
{
    const scalarField& phi0 = phi0Field.primitiveField();
    const scalarField& phi1 = phi1Field.primitiveField();
    scalarField& phi0Nbr = phi0Nbr_;
    scalarField& phi1Nbr = phi1Nbr_;
    addr_.coupledNeighbourValues(phi0Field, phi0Nbr);
    addr_.coupledNeighbourValues(phi1Field, phi1Nbr);

    // Compact faces; a face next to a cell without gas at both ends of the
    // step is closed (no gas can pass into the solid)
    loadApertures(aperture);
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if ((phi0[P] <= 0 && phi1[P] <= 0) || (phi0[N] <= 0 && phi1[N] <= 0))
        {
            aperture_[f] = 0;
        }
    }
    forAll(addr_.kinds(), patchi)
    {
        if (addr_.kinds()[patchi] == blastFaceAddressing::SKIP) continue;
        const label start = addr_.patchStart()[patchi];
        const label n = aperture.boundaryField()[patchi].size();
        for (label cf = start; cf < start + n; ++cf)
        {
            const label P = addr_.own()[cf], b = cf - addr_.nInternal();
            bool shut = phi0[P] <= 0 && phi1[P] <= 0;
            if (addr_.kinds()[patchi] == blastFaceAddressing::COUPLED)
            {
                shut = shut || (phi0Nbr[b] <= 0 && phi1Nbr[b] <= 0);
            }
            if (shut) aperture_[cf] = 0;
        }
    }

    // A cell that opens in the step where no gas can reach it (no open
    // face to a cell holding gas: a void inside the solid, a joint opening
    // by elastic strain) stays closed: nothing is created; it opens once
    // gas is next to it
    boolList& reached = reached_;
    reached.setSize(phi0.size());
    reached = false;
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        if (aperture_[f] <= 0) continue;
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if (phi0[N] > 0) reached[P] = true;
        if (phi0[P] > 0) reached[N] = true;
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label b = cf - addr_.nInternal();
        if (aperture_[cf] > 0 && addr_.coupledFace()[b] && phi0Nbr[b] > 0)
        {
            reached[addr_.own()[cf]] = true;
        }
    }
    scalarField& phi1Ref = phi1Field.primitiveFieldRef();
    bool closed = false;
    forAll(phi1Ref, i)
    {
        if (phi0[i] <= 0 && phi1Ref[i] > 0 && !reached[i])
        {
            phi1Ref[i] = 0;
            closed = true;
        }
    }
    if (returnReduce(closed, orOp<bool>()))
    {
        phi1Field.correctBoundaryConditions();
        addr_.coupledNeighbourValues(phi1Field, phi1Nbr);
        for (label f = 0; f < addr_.nInternal(); ++f)
        {
            const label P = addr_.own()[f], N = addr_.nei()[f];
            if
            (
                (phi0[P] <= 0 && phi1[P] <= 0)
             || (phi0[N] <= 0 && phi1[N] <= 0)
            )
            {
                aperture_[f] = 0;
            }
        }
        for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
        {
            const label P = addr_.own()[cf], b = cf - addr_.nInternal();
            if
            (
                (phi0[P] <= 0 && phi1[P] <= 0)
             || (addr_.coupledFace()[b] && phi0Nbr[b] <= 0 && phi1Nbr[b] <= 0)
            )
            {
                aperture_[cf] = 0;
            }
        }
    }

    // Closure: the wall of a cell closes its open faces
    wallVector_ = Zero;
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        wallVector_[addr_.own()[f]] -= aperture_[f]*addr_.Sf()[f];
        wallVector_[addr_.nei()[f]] += aperture_[f]*addr_.Sf()[f];
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        wallVector_[addr_.own()[cf]] -= aperture_[cf]*addr_.Sf()[cf];
    }
    const scalarField& V = mesh_.V();
    newCell_.setSize(V.size());
    forAll(V, i)
    {
        newCell_[i] = phi0[i] <= 0 && phi1[i] > 0;
        // The front and back planes of a 2D mesh close each other
        if (mesh_.nSolutionD() == 2) wallVector_[i].z() = 0;
        sweptVolume_[i] = (phi1[i] - phi0[i])*V[i];
        if (phi0[i] <= 0 && phi1[i] <= 0) wallVector_[i] = Zero;
    }
}


// ************************************************************************* //
