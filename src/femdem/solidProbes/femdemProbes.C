/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemProbes.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::femdemProbes::femdemProbes
(
    const femdemSolid& solid,
    const dictionary& dict
)
:
    points_(dict.get<List<vector2D>>("points")),
    triangle_(points_.size(), -1),
    weights_(points_.size())
{
    const List<vector2D>& X0 = solid.topology().initialPoints();
    const labelList& vertex = solid.topology().nodeVertex();
    // Barycentric weights, tolerant of a point on an edge (round-off)
    const scalar tol = 1e-10;
    for (label t = 0; t < solid.nTriangles(); ++t)
    {
        const vector2D& a = X0[vertex[3*t]];
        const vector2D e1 = X0[vertex[3*t + 1]] - a;
        const vector2D e2 = X0[vertex[3*t + 2]] - a;
        const scalar det = e1.x()*e2.y() - e1.y()*e2.x();
        forAll(points_, i)
        {
            if (triangle_[i] >= 0) continue;
            const vector2D d = points_[i] - a;
            const scalar w1 = (d.x()*e2.y() - d.y()*e2.x())/det;
            const scalar w2 = (e1.x()*d.y() - e1.y()*d.x())/det;
            if (w1 >= -tol && w2 >= -tol && w1 + w2 <= 1 + tol)
            {
                triangle_[i] = t;
                weights_[i] = FixedList<scalar, 3>({1 - w1 - w2, w1, w2});
            }
        }
    }
    forAll(points_, i)
    {
        if (triangle_[i] < 0)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'points': point " << i << " " << points_[i]
                << " lies in no triangle of the solid (outside it or in a"
                << " hole); give the points in the initial configuration"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::vector2D> Foam::femdemProbes::sample
(
    const UList<vector2D>& nodal
) const
{
    List<vector2D> out(points_.size(), vector2D::zero);
    forAll(points_, i)
    {
        const label t = triangle_[i];
        for (label k = 0; k < 3; ++k)
        {
            out[i] += weights_[i][k]*nodal[3*t + k];
        }
    }
    return out;
}


Foam::List<Foam::vector2D> Foam::femdemProbes::velocity
(
    const femdemSolid& solid
) const
{
    return sample(solid.v());
}


// ************************************************************************* //
