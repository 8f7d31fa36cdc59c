/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    Gradients and limited face states of blastFluidSolver (see
    blastReconstruction.H).

\*---------------------------------------------------------------------------*/

#include "blastReconstruction.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blastReconstruction::blastReconstruction
(
    const fvMesh& mesh,
    const blastFaceAddressing& addr,
    const dictionary& fluidDict,
    const label nMaterials
)
:
    mesh_(mesh),
    addr_(addr),
    multiPhase_(nMaterials > 1),
    threePhase_(nMaterials > 2),
    limiter_(blastLimiter::New(fluidDict))
{
    auto makeGradS = [&](const word& name)
    {
        return new volVectorField
        (
            IOobject(name, mesh.time().timeName(), mesh),
            mesh,
            dimensionedVector(dimless, Zero),
            "zeroGradient"
        );
    };
    if (multiPhase_)
    {
        gradAlpha_.reset(makeGradS("gradAlpha"));
        gradRho1_.reset(makeGradS("gradRho1"));
        gradRho2_.reset(makeGradS("gradRho2"));
        if (threePhase_)
        {
            gradAlpha2_.reset(makeGradS("gradAlpha2"));
            gradRho3_.reset(makeGradS("gradRho3"));
        }
    }
    else
    {
        gradRho_.reset(makeGradS("gradRho"));
    }
    gradP_.reset(makeGradS("gradP"));
    gradU_.reset
    (
        new volTensorField
        (
            IOobject("gradU", mesh.time().timeName(), mesh),
            mesh,
            dimensionedTensor(dimless, Zero),
            "zeroGradient"
        )
    );

    if (multiPhase_)
    {
        const label n = addr_.nFaces();
        phases_.rho1L.setSize(n, 1); phases_.rho1R.setSize(n, 1);
        phases_.rho2L.setSize(n, 1); phases_.rho2R.setSize(n, 1);
        if (threePhase_)
        {
            phases_.rho3L.setSize(n, 1); phases_.rho3R.setSize(n, 1);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type, class GradType>
void Foam::blastReconstruction::gaussGrad
(
    const GeometricField<Type, fvPatchField, volMesh>& phi,
    GeometricField<GradType, fvPatchField, volMesh>& grad
) const
{
    Field<GradType>& g = grad.primitiveFieldRef();
    const Field<Type>& vf = phi.primitiveField();
    g = Zero;

    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        const Type phif = addr_.w()[f]*vf[P] + (1 - addr_.w()[f])*vf[N];
        const GradType s = addr_.Sf()[f]*phif;
        g[P] += s;
        g[N] -= s;
    }
    forAll(addr_.kinds(), patchi)
    {
        if (addr_.kinds()[patchi] == blastFaceAddressing::SKIP) continue;
        const fvPatchField<Type>& pf = phi.boundaryField()[patchi];
        const label start = addr_.patchStart()[patchi];
        if (addr_.kinds()[patchi] == blastFaceAddressing::COUPLED)
        {
            // Processor patch fields hold the neighbour cell values:
            // interpolate as on an internal face
            const tmp<Field<Type>> tnbr = pf.patchNeighbourField();
            const Field<Type>& nbr = tnbr();
            forAll(pf, j)
            {
                const label cf = start + j;
                const label P = addr_.own()[cf];
                g[P] += addr_.Sf()[cf]*(addr_.w()[cf]*vf[P] + (1 - addr_.w()[cf])*nbr[j]);
            }
        }
        else
        {
            forAll(pf, j)
            {
                const label cf = start + j;
                g[addr_.own()[cf]] += addr_.Sf()[cf]*pf[j];
            }
        }
    }
    const scalarField& V = mesh_.V();
    forAll(g, i)
    {
        g[i] /= V[i];
    }
    grad.correctBoundaryConditions();
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::blastReconstruction::faceStates
(
    const cellFields& cells,
    const volScalarField& lowOrder,
    const bool anyLowOrder,
    blastFaceStates& faces
)
{
    // One call of the limiter per field: its face loop is a template
    // instantiated with its inline psi
    const blastLimiter& limiter = limiter_();
    if (limiter.secondOrder())
    {
        if (multiPhase_)
        {
            gaussGrad(*cells.alpha1, gradAlpha_());
            gaussGrad(*cells.rho1, gradRho1_());
            gaussGrad(*cells.rho2, gradRho2_());
            if (threePhase_)
            {
                gaussGrad(*cells.alpha2, gradAlpha2_());
                gaussGrad(*cells.rho3, gradRho3_());
            }
        }
        else
        {
            gaussGrad(cells.rho, gradRho_());
        }
        gaussGrad(cells.U, gradU_());
        gaussGrad(cells.p, gradP_());
    }

    const bool lo = anyLowOrder;
    if (threePhase_)
    {
        limiter.jointFaceValues
        (
            addr_, *cells.alpha1, gradAlpha_(), *cells.alpha2, gradAlpha2_(),
            lowOrder, lo, faces.alphaL, faces.alphaR, faces.alpha2L,
            faces.alpha2R
        );
    }
    else if (multiPhase_)
    {
        limiter.faceValues
        (
            addr_, *cells.alpha1, gradAlpha_(), lowOrder, lo,
            faces.alphaL, faces.alphaR
        );
    }
    if (multiPhase_)
    {
        limiter.faceValues
        (
            addr_, *cells.rho1, gradRho1_(), lowOrder, lo,
            phases_.rho1L, phases_.rho1R
        );
        limiter.faceValues
        (
            addr_, *cells.rho2, gradRho2_(), lowOrder, lo,
            phases_.rho2L, phases_.rho2R
        );
        if (threePhase_)
        {
            limiter.faceValues
            (
                addr_, *cells.rho3, gradRho3_(), lowOrder, lo,
                phases_.rho3L, phases_.rho3R
            );
        }
    }
    else
    {
        limiter.faceValues
        (
            addr_, cells.rho, gradRho_(), lowOrder, lo, faces.rhoL, faces.rhoR
        );
    }
    limiter.faceValues
    (
        addr_, cells.U, gradU_(), lowOrder, lo, faces.UL, faces.UR
    );
    limiter.faceValues
    (
        addr_, cells.p, gradP_(), lowOrder, lo, faces.pL, faces.pR
    );
}


// ************************************************************************* //
