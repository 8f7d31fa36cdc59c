/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "programmedBurn.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::programmedBurn::programmedBurn(const fvMesh& mesh)
:
    lightingTime_(caseChecks::fieldIO("lightingTime", mesh, IOobject::MUST_READ), mesh),
    burnTime_(caseChecks::fieldIO("burnTime", mesh, IOobject::MUST_READ), mesh),
    burnFraction_
    (
        caseChecks::fieldIO("burnFraction", mesh, IOobject::NO_READ),
        mesh,
        dimensionedScalar(dimless, Zero),
        "zeroGradient"
    )
{
    caseChecks::checkDimensions(lightingTime_, dimTime);
    caseChecks::checkDimensions(burnTime_, dimTime);
    const scalarField& tau = burnTime_.primitiveField();
    forAll(tau, i)
    {
        if (tau[i] < 0)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, burnTime_.objectPath(),
                -1, -1
            )
                << "entry 'internalField': burnTime = " << tau[i]
                << " in cell " << i << " (centre " << mesh.C()[i]
                << ") must be >= 0 (written by setCharge)"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::programmedBurn::present(const fvMesh& mesh)
{
    return IOobject
    (
        "lightingTime", mesh.time().timeName(), mesh, IOobject::MUST_READ
    ).typeHeaderOk<volScalarField>(true);
}


void Foam::programmedBurn::update(const scalar t)
{
    const scalarField& tb = lightingTime_.primitiveField();
    const scalarField& tau = burnTime_.primitiveField();
    scalarField& F = burnFraction_.primitiveFieldRef();
    forAll(F, i)
    {
        F[i] = fraction(t, tb[i], tau[i]);
    }
    burnFraction_.correctBoundaryConditions();
}


// ************************************************************************* //
