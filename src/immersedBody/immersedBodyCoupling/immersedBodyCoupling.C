/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBodyCoupling.H"
#include "fvMesh.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::immersedBodyCoupling::immersedBodyCoupling
(
    const fvMesh& mesh,
    const dictionary& dict,
    const label nTriangles
)
:
    mesh_(mesh),
    projection_(mesh),
    depth_(mesh.bounds().span().z()),
    beta_(dict.getOrDefault<scalar>("beta", 1)),
    crackPressure_(dict.getOrDefault<bool>("crackPressure", true)),
    alphaSolid_
    (
        IOobject
        (
            "alpha.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    Usolid_
    (
        IOobject
        (
            "U.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    cellForce_(mesh.nCells(), Zero),
    triangles_(nTriangles)
{
    if (beta_ <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "beta must be positive, not " << beta_ << exit(FatalIOError);
    }
    forAll(triangles_, t)
    {
        triangles_[t] = FixedList<label, 3>({3*t, 3*t + 1, 3*t + 2});
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::immersedBodyCoupling::project
(
    const UList<vector2D>& nodePositions,
    const UList<vector2D>& nodeVelocities
)
{
    projection_.project
    (
        nodePositions, triangles_, nodeVelocities, alphaWork_, UsolidWork_
    );
    scalarField& alpha = alphaSolid_.primitiveFieldRef();
    vectorField& Us = Usolid_.primitiveFieldRef();
    forAll(alpha, celli)
    {
        alpha[celli] = alphaWork_[celli];
        Us[celli] = vector(UsolidWork_[celli].x(), UsolidWork_[celli].y(), 0);
    }
    alphaSolid_.correctBoundaryConditions();
    Usolid_.correctBoundaryConditions();
}


void Foam::immersedBodyCoupling::absorb
(
    const volScalarField& rho,
    volVectorField& rhoU,
    volScalarField& rhoE,
    const scalar dt
)
{
    const scalarField& alpha = alphaSolid_;
    const vectorField& Us = Usolid_;
    const scalarField& V = mesh_.V();

    forAll(alpha, celli)
    {
        cellForce_[celli] = Zero;
        if (alpha[celli] <= 0 || rho[celli] <= 0)
        {
            continue;
        }
        // Implicit: rho (u1 - u0)/dt = sigma (u_s - u1), sigma dt/rho = beta alpha
        const scalar k = beta_*alpha[celli];
        const vector u0 = rhoU[celli]/rho[celli];
        const vector u1 = (u0 + k*Us[celli])/(1 + k);
        const vector dMomentum = rho[celli]*(u1 - u0);

        rhoU[celli] += dMomentum;
        // The gas does work dMomentum . u_s on the solid; the rest of its
        // kinetic energy change is dissipated into heat: total energy kept
        rhoE[celli] += dMomentum & Us[celli];

        // Reaction on the solid, per unit time and unit depth
        const vector f = -dMomentum*V[celli]/(dt*depth_);
        cellForce_[celli] = vector2D(f.x(), f.y());
    }
}


void Foam::immersedBodyCoupling::solidForces
(
    const UList<vector2D>& nodePositions,
    const jointTopology& topology,
    const UList<bool>& jointBroken,
    const volScalarField& p,
    List<vector2D>& nodeForces
) const
{
    nodeForces.setSize(nodePositions.size());
    nodeForces = Zero;
    projection_.distributeToPoints
    (
        cellForce_, alphaWork_, nodePositions, triangles_, nodeForces
    );

    if (!crackPressure_)
    {
        return;
    }
    const List<jointNodeList>& jointNodes = topology.jointNodes();
    forAll(jointNodes, j)
    {
        if (!jointBroken[j])
        {
            continue;
        }
        const jointNodeList& n = jointNodes[j];
        const vector2D& p0 = nodePositions[n[0]];
        const vector2D& p1 = nodePositions[n[1]];
        const vector2D mid = 0.5*(p0 + p1);
        const vector2D gapMid = 0.5*(nodePositions[n[2]] + nodePositions[n[3]]) - mid;
        const vector2D d = p1 - p0;
        // Unit normal from A into B times the face length
        const vector2D nL(d.y(), -d.x());
        if ((gapMid & nL) <= 0)
        {
            continue;   // closed crack: no gas between the faces
        }
        const label celli = mesh_.findCell(point(mid.x(), mid.y(), mesh_.bounds().centre().z()));
        if (celli < 0)
        {
            continue;
        }
        // Gas pushes A along -n and B along +n: an internal pair
        const vector2D f = 0.5*p[celli]*nL;
        nodeForces[n[0]] -= f;
        nodeForces[n[1]] -= f;
        nodeForces[n[2]] += f;
        nodeForces[n[3]] += f;
    }
}


Foam::vector2D Foam::immersedBodyCoupling::totalAbsorptionForce() const
{
    vector2D sum(Zero);
    for (const vector2D& f : cellForce_)
    {
        sum += f;
    }
    return sum;
}


// ************************************************************************* //
