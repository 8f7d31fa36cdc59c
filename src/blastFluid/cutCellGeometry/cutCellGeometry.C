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


void Foam::cutCellGeometry::closeShutFaces
(
    const scalarField& phi0,
    const scalarField& phi1
)
{
    // A face next to a cell without gas at both ends of the step is closed
    // (no gas can pass into the solid); the wall vectors of the final
    // apertures are summed in the same pass (face by face, in the order of
    // the compact faces)
    const label nInternal = addr_.nInternal();
    const labelList& own = addr_.own();
    const labelList& nei = addr_.nei();
    const vectorField& Sf = addr_.Sf();
    wallVector_ = Zero;
    for (label f = 0; f < nInternal; ++f)
    {
        const label P = own[f], N = nei[f];
        if ((phi0[P] <= 0 && phi1[P] <= 0) || (phi0[N] <= 0 && phi1[N] <= 0))
        {
            aperture_[f] = 0;
        }
        wallVector_[P] -= aperture_[f]*Sf[f];
        wallVector_[N] += aperture_[f]*Sf[f];
    }
    for (label cf = nInternal; cf < addr_.nFaces(); ++cf)
    {
        const label P = own[cf], b = cf - nInternal;
        if
        (
            (phi0[P] <= 0 && phi1[P] <= 0)
         || (
                addr_.coupledFace()[b]
             && phi0Nbr_[b] <= 0 && phi1Nbr_[b] <= 0
            )
        )
        {
            aperture_[cf] = 0;
        }
        wallVector_[P] -= aperture_[cf]*Sf[cf];
    }
}


bool Foam::cutCellGeometry::reachedByGas
(
    const label celli,
    const scalarField& phi0
) const
{
    // An open face to a cell holding gas at the step's start (across a
    // processor face: the neighbour's phi0)
    const label nInternal = addr_.nInternal();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    for (const label f : mesh_.cells()[celli])
    {
        if (f < nInternal)
        {
            const label o =
                addr_.own()[f] == celli ? addr_.nei()[f] : addr_.own()[f];
            if (aperture_[f] > 0 && phi0[o] > 0) return true;
            continue;
        }
        const label patchi = pbm.whichPatch(f);
        if (addr_.kinds()[patchi] != blastFaceAddressing::COUPLED) continue;
        const label cf = addr_.patchStart()[patchi] + f - pbm[patchi].start();
        if (aperture_[cf] > 0 && phi0Nbr_[cf - nInternal] > 0) return true;
    }
    return false;
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
    addr_.coupledNeighbourValues(phi0Field, phi0Nbr_);
    addr_.coupledNeighbourValues(phi1Field, phi1Nbr_);
    loadApertures(aperture);
    closeShutFaces(phi0, phi1);

    // A cell that opens in the step where no gas can reach it (no open
    // face to a cell holding gas: a void inside the solid, a joint opening
    // by elastic strain) stays closed: nothing is created; it opens once
    // gas is next to it. Only the opening cells' faces are looked at
    scalarField& phi1Ref = phi1Field.primitiveFieldRef();
    bool closed = false;
    forAll(phi1Ref, i)
    {
        if (phi0[i] <= 0 && phi1Ref[i] > 0 && !reachedByGas(i, phi0))
        {
            phi1Ref[i] = 0;
            closed = true;
        }
    }
    if (returnReduce(closed, orOp<bool>()))
    {
        phi1Field.correctBoundaryConditions();
        addr_.coupledNeighbourValues(phi1Field, phi1Nbr_);
        closeShutFaces(phi0, phi1);
    }

    const scalarField& V = mesh_.V();
    const bool twoD = mesh_.nSolutionD() == 2;
    newCell_.setSize(V.size());
    forAll(V, i)
    {
        newCell_[i] = phi0[i] <= 0 && phi1[i] > 0;
        // The front and back planes of a 2D mesh close each other
        if (twoD) wallVector_[i].z() = 0;
        sweptVolume_[i] = (phi1[i] - phi0[i])*V[i];
        if (phi0[i] <= 0 && phi1[i] <= 0) wallVector_[i] = Zero;
    }
}


// ************************************************************************* //
