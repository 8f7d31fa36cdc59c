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
    dict_(dict),
    projection_(mesh),
    depth_(returnReduce(mesh.bounds().span().z(), maxOp<scalar>())),
    beta_(dict.getOrDefault<scalar>("beta", 1)),
    minFluidFraction_(dict.getOrDefault<scalar>("minFluidFraction", 0.02)),
    crackPressure_(dict.getOrDefault<bool>("crackPressure", false)),
    alphaSolid_
    (
        IOobject
        (
            "alpha.solid",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
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
    triangles_(nTriangles),
    alphaSolidRead_(alphaSolid_.headerOk())
{
    // A misspelt optional entry would silently take its default
    const wordList valid({"beta", "minFluidFraction", "crackPressure"});
    for (const entry& e : dict)
    {
        if (e.keyword() != "FoamFile" && !valid.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << e.keyword()
                << "'. Valid entries: " << flatOutput(valid)
                << exit(FatalIOError);
        }
    }
    if (!(beta_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'beta' must be positive, not " << beta_
            << exit(FatalIOError);
    }
    if (!(minFluidFraction_ > 0 && minFluidFraction_ < 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'minFluidFraction' must lie in (0, 0.5), not "
            << minFluidFraction_ << exit(FatalIOError);
    }
    if (!(depth_ > 0))
    {
        FatalErrorInFunction
            << "The fluid mesh has no depth: the immersed solid needs a 2D"
            << " mesh one cell thick in z" << exit(FatalError);
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


void Foam::immersedBodyCoupling::solidForces
(
    const UList<vector2D>& nodePositions,
    const jointTopology& topology,
    const UList<bool>& jointBroken,
    const volScalarField& p,
    const scalarField& fluidFraction,
    const vectorField& solidImpulse,
    const scalar dt,
    List<vector2D>& nodeForces
)
{
    // Momentum per unit time and unit depth
    const scalar scale = 1/(dt*depth_);
    forAll(cellForce_, celli)
    {
        cellForce_[celli] = vector2D
        (
            scale*solidImpulse[celli].x(), scale*solidImpulse[celli].y()
        );
    }
    nodeForces.setSize(nodePositions.size());
    nodeForces = Zero;
    projection_.distributeToPoints
    (
        cellForce_, alphaWork_, nodePositions, triangles_, nodeForces
    );

    if (crackPressure_)
    {
        addCrackPressure
        (
            nodePositions, topology, jointBroken, p, fluidFraction,
            nodeForces
        );
    }

    if (Pstream::parRun())
    {
        // The same solid on every processor: sum the parts
        Pstream::listCombineGather(nodeForces, plusEqOp<vector2D>());
        Pstream::listCombineScatter(nodeForces);
    }
}


void Foam::immersedBodyCoupling::addCrackPressure
(
    const UList<vector2D>& nodePositions,
    const jointTopology& topology,
    const UList<bool>& jointBroken,
    const volScalarField& p,
    const scalarField& fluidFraction,
    List<vector2D>& nodeForces
) const
{
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
        const vector2D gapMid =
            0.5*(nodePositions[n[2]] + nodePositions[n[3]]) - mid;
        const vector2D d = p1 - p0;
        // Unit normal from A into B times the face length
        const vector2D nL(d.y(), -d.x());
        if ((gapMid & nL) <= 0)
        {
            continue;   // closed crack: no gas between the faces
        }
        // Only a crack narrower than the fluid cells: once its faces lie in
        // different cells, the fluid mesh sees the gap and its wall faces
        // already push each side (counting them again would create energy)
        const label celli = projection_.findCell(mid);
        if
        (
            celli < 0 || fluidFraction[celli] <= 0
         || projection_.findCell(mid + gapMid) != celli
        )
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


// ************************************************************************* //
