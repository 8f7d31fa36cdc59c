/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "blastFaceAddressing.H"
#include "emptyFvPatch.H"
#include "wedgeFvPatch.H"
#include "wallFvPatch.H"
#include "symmetryFvPatch.H"
#include "symmetryPlaneFvPatch.H"
#include "slipFvPatchFields.H"
#include "noSlipFvPatchVectorField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blastFaceAddressing::blastFaceAddressing
(
    const fvMesh& mesh,
    const volVectorField& U
)
:
    nInternal_(mesh.nInternalFaces()),
    nFaces_(nInternal_)
{
    const fvBoundaryMesh& bm = mesh.boundary();
    patchStart_.setSize(bm.size());
    patchKind_.setSize(bm.size());
    forAll(bm, patchi)
    {
        patchStart_[patchi] = nFaces_;
        patchKind_[patchi] = kindOf(bm[patchi], U.boundaryField()[patchi]);
        if (patchKind_[patchi] != SKIP) nFaces_ += bm[patchi].size();
    }
    coupledFace_.setSize(nFaces_ - nInternal_);
    coupledFace_ = false;
    forAll(bm, patchi)
    {
        if (patchKind_[patchi] != COUPLED) continue;
        SubList<bool>
        (
            coupledFace_, bm[patchi].size(), patchStart_[patchi] - nInternal_
        ) = true;
    }
    setFaces(mesh);
    setCellFactors(mesh);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::blastFaceAddressing::patchKind Foam::blastFaceAddressing::kindOf
(
    const fvPatch& pp,
    const fvPatchVectorField& Up
)
{
    if (pp.size() == 0 || isA<emptyFvPatch>(pp)) return SKIP;
    if (pp.coupled()) return COUPLED;
    if (isA<wedgeFvPatch>(pp)) return WEDGE;
    if
    (
        isA<wallFvPatch>(pp) || isA<symmetryFvPatch>(pp)
     || isA<symmetryPlaneFvPatch>(pp)
     || isA<slipFvPatchVectorField>(Up) || isA<noSlipFvPatchVectorField>(Up)
    )
    {
        return REFLECTIVE;
    }
    return GHOST;
}


void Foam::blastFaceAddressing::setFaces(const fvMesh& mesh)
{
    own_.setSize(nFaces_);
    nei_.setSize(nInternal_);
    Sf_.setSize(nFaces_);
    magSf_.setSize(nFaces_);
    w_.setSize(nFaces_, 1);
    delta_.setSize(nFaces_, Zero);

    const labelUList& owner = mesh.owner();
    const labelUList& neighbour = mesh.neighbour();
    const vectorField& C = mesh.C();
    const surfaceScalarField& weights = mesh.weights();
    for (label f = 0; f < nInternal_; ++f)
    {
        own_[f] = owner[f];
        nei_[f] = neighbour[f];
        Sf_[f] = mesh.Sf()[f];
        magSf_[f] = mesh.magSf()[f];
        w_[f] = weights[f];
        delta_[f] = C[neighbour[f]] - C[owner[f]];
    }

    const fvBoundaryMesh& bm = mesh.boundary();
    forAll(bm, patchi)
    {
        if (patchKind_[patchi] == SKIP) continue;
        const fvPatch& pp = bm[patchi];
        const labelUList& fc = pp.faceCells();
        const vectorField& pSf = mesh.Sf().boundaryField()[patchi];
        const scalarField& pmagSf = mesh.magSf().boundaryField()[patchi];
        const scalarField& pw = weights.boundaryField()[patchi];
        const vectorField pdelta(pp.delta());
        forAll(pp, j)
        {
            const label cf = patchStart_[patchi] + j;
            own_[cf] = fc[j];
            Sf_[cf] = pSf[j];
            magSf_[cf] = pmagSf[j];
            w_[cf] = (patchKind_[patchi] == COUPLED) ? pw[j] : 1;
            delta_[cf] = pdelta[j];
        }
    }
}


void Foam::blastFaceAddressing::setCellFactors(const fvMesh& mesh)
{
    // Wedge faces carry no flux across the wedge: they would only shrink
    // the time step and the Q-scheme length
    const scalarField& V = mesh.V();
    scalarField sumS(mesh.nCells(), 0);
    for (label f = 0; f < nInternal_; ++f)
    {
        sumS[own_[f]] += magSf_[f];
        sumS[nei_[f]] += magSf_[f];
    }
    const fvBoundaryMesh& bm = mesh.boundary();
    forAll(bm, patchi)
    {
        if (patchKind_[patchi] == SKIP || patchKind_[patchi] == WEDGE)
        {
            continue;
        }
        for (label j = 0; j < bm[patchi].size(); ++j)
        {
            const label cf = patchStart_[patchi] + j;
            sumS[own_[cf]] += magSf_[cf];
        }
    }
    const label nD = mesh.nSolutionD();
    CoGeom_ = 0.5*sumS/V;
    cellLength_ = 2*nD*V/sumS;
}


// ************************************************************************* //
