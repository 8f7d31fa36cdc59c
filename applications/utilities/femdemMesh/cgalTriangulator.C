/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    CGAL side of femdemMesh: only CGAL and standard headers here.

\*---------------------------------------------------------------------------*/

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <cmath>
#include <fenv.h>
#include <stdexcept>
#include <unordered_map>

#include "cgalTriangulator.H"

namespace
{

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_with_info_2<int, K> VbInfo;
typedef CGAL::Delaunay_mesh_vertex_base_2<K, VbInfo> Vb;
typedef CGAL::Constrained_triangulation_face_base_2<K> CFb;
typedef CGAL::Triangulation_face_base_with_info_2<int, K, CFb> FbInfo;
typedef CGAL::Delaunay_mesh_face_base_2<K, FbInfo> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2
<
    K, Tds, CGAL::Exact_predicates_tag
> CDTbase;
typedef CGAL::Constrained_triangulation_plus_2<CDTbase> CDT;
typedef CDT::Point Point;
typedef CDT::Face_handle Face_handle;
typedef CDT::Vertex_handle Vertex_handle;


// CGAL's size-and-shape criteria with the size bound taken from a size
// function at the triangle's centroid instead of a constant: the quality's
// size is (longest edge / local size)^2, a triangle with size > 1 must be
// split; the shape part (squared sine of the smallest angle) is CGAL's.
class localSizeCriteria
:
    public CGAL::Delaunay_mesh_size_criteria_2<CDT>
{
    typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Base;

    const std::function<double(double, double)>* size_;

public:

    typedef Base::Quality Quality;

    localSizeCriteria
    (
        const double sineSquaredBound,
        const std::function<double(double, double)>& size
    )
    :
        CGAL::Delaunay_mesh_criteria_2<CDT>(sineSquaredBound),
        Base(sineSquaredBound, 0),
        size_(&size)
    {}

    class Is_bad
    :
        public Base::Is_bad
    {
        const std::function<double(double, double)>* size_;

    public:

        Is_bad
        (
            const double bound,
            const std::function<double(double, double)>* size,
            const Geom_traits& traits
        )
        :
            Base::Is_bad(bound, 0, traits),
            size_(size)
        {}

        CGAL::Mesh_2::Face_badness operator()(const Quality q) const
        {
            return Base::Is_bad::operator()(q);
        }

        CGAL::Mesh_2::Face_badness operator()
        (
            const Face_handle& fh,
            Quality& q
        ) const
        {
            const Point& pa = fh->vertex(0)->point();
            const Point& pb = fh->vertex(1)->point();
            const Point& pc = fh->vertex(2)->point();
            double l[3] =
            {
                CGAL::to_double(CGAL::squared_distance(pb, pc)),
                CGAL::to_double(CGAL::squared_distance(pc, pa)),
                CGAL::to_double(CGAL::squared_distance(pa, pb))
            };
            std::sort(l, l + 3);

            const double h = (*size_)
            (
                (pa.x() + pb.x() + pc.x())/3.0,
                (pa.y() + pb.y() + pc.y())/3.0
            );
            q.second = l[2]/(h*h);
            if (q.second > 1)
            {
                q.first = 1;
                return CGAL::Mesh_2::IMPERATIVELY_BAD;
            }
            const double area2 = CGAL::to_double(CGAL::area(pa, pb, pc))*2;
            q.first = area2*area2/(l[2]*l[1]);
            return q.first < this->B
                ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }
    };

    Is_bad is_bad_object() const
    {
        return Is_bad(this->bound(), size_, this->traits);
    }
};

typedef CGAL::Delaunay_mesher_2<CDT, localSizeCriteria> Mesher;


Point centroid(const Face_handle& f)
{
    return CGAL::centroid
    (
        f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()
    );
}


// Label the regions (faces connected across unconstrained edges) of the
// finite faces accepted by 'use', asking 'region' once per region; the
// label goes to face->info(). Returns the number of regions.
template<class Accept>
int labelRegions
(
    CDT& cdt,
    const std::function<int(double, double)>& region,
    Accept use
)
{
    for (Face_handle f : cdt.all_face_handles())
    {
        f->info() = -2;
    }
    int nRegions = 0;
    std::vector<Face_handle> stack;
    for (Face_handle f0 : cdt.finite_face_handles())
    {
        if (f0->info() != -2 || !use(f0))
        {
            continue;
        }
        const Point c = centroid(f0);
        const int label = region(CGAL::to_double(c.x()), CGAL::to_double(c.y()));
        ++nRegions;
        f0->info() = label;
        stack.assign(1, f0);
        while (!stack.empty())
        {
            const Face_handle f = stack.back();
            stack.pop_back();
            for (int i = 0; i < 3; ++i)
            {
                const Face_handle n = f->neighbor(i);
                if
                (
                    n->info() == -2
                 && !cdt.is_infinite(n)
                 && !cdt.is_constrained(CDT::Edge(f, i))
                 && use(n)
                )
                {
                    n->info() = label;
                    stack.push_back(n);
                }
            }
        }
    }
    return nRegions;
}

} // End anonymous namespace


namespace
{

// Floating-point traps off while CGAL runs (OpenFOAM enables them,
// FOAM_SIGFPE): CGAL's filtered predicates may meet non-finite values of
// a degenerate input and then stop with an assertion (an exception that
// femdemMesh reports with the dictionary) instead of a signal
struct noFpeTraps
{
    const int saved = fegetexcept();
    noFpeTraps() { fedisableexcept(FE_ALL_EXCEPT); }
    ~noFpeTraps() { feclearexcept(FE_ALL_EXCEPT); feenableexcept(saved); }
};

} // End anonymous namespace


cgalTriangulator::mesh cgalTriangulator::triangulate(const domain& input)
{
    const noFpeTraps guard;
    if (input.minAngleDegrees <= 0 || input.minAngleDegrees > 35)
    {
        throw std::runtime_error("minAngle must be in (0, 35] degrees");
    }

    CDT cdt;
    std::vector<Vertex_handle> vertex(input.x.size());
    for (size_t i = 0; i < input.x.size(); ++i)
    {
        vertex[i] = cdt.insert(Point(input.x[i], input.y[i]));
    }
    std::vector<std::pair<CDT::Constraint_id, int>> constraints;
    for (size_t s = 0; s < input.segmentStart.size(); ++s)
    {
        const Vertex_handle a = vertex.at(input.segmentStart[s]);
        const Vertex_handle b = vertex.at(input.segmentEnd[s]);
        if (a != b)
        {
            constraints.emplace_back
            (
                cdt.insert_constraint(a, b), input.segmentTag[s]
            );
        }
    }

    std::vector<std::pair<CDT::Constraint_id, int>> joints;
    for (size_t s = 0; s < input.jointStart.size(); ++s)
    {
        const Vertex_handle a = vertex.at(input.jointStart[s]);
        const Vertex_handle b = vertex.at(input.jointEnd[s]);
        if (a != b)
        {
            joints.emplace_back(cdt.insert_constraint(a, b), input.jointTag[s]);
        }
    }

    // Mark the regions to mesh on the constrained triangulation of the
    // input, then refine: the mesher keeps the marks on new triangles
    labelRegions(cdt, input.region, [](const Face_handle&) { return true; });
    for (Face_handle f : cdt.all_face_handles())
    {
        f->set_in_domain(!cdt.is_infinite(f) && f->info() >= 0);
    }

    const double sine = std::sin(input.minAngleDegrees*M_PI/180.0);
    Mesher mesher(cdt, localSizeCriteria(sine*sine, input.size));
    mesher.init(true);
    mesher.refine_mesh();

    labelRegions
    (
        cdt,
        input.region,
        [](const Face_handle& f) { return f->is_in_domain(); }
    );

    // Points used by the meshed triangles, in the triangulation's order
    mesh result;
    int nVertices = 0;
    for (Vertex_handle v : cdt.finite_vertex_handles())
    {
        v->info() = -1;
    }
    for (Face_handle f : cdt.finite_face_handles())
    {
        if (!f->is_in_domain() || f->info() < 0)
        {
            continue;
        }
        for (int k = 0; k < 3; ++k)
        {
            const Vertex_handle v = f->vertex(k);
            if (v->info() < 0)
            {
                v->info() = nVertices++;
                result.x.push_back(CGAL::to_double(v->point().x()));
                result.y.push_back(CGAL::to_double(v->point().y()));
            }
            result.triangles.push_back(v->info());
        }
        result.triangleRegion.push_back(f->info());
    }

    // Tag of each piece of an input segment (a constraint split by the
    // mesher), keyed by its end vertices
    std::unordered_map<long long, int> pieceTag;
    auto key = [](const Vertex_handle& a, const Vertex_handle& b)
    {
        const long long i = a->info(), j = b->info();
        return i < j ? (i << 32) + j : (j << 32) + i;
    };
    for (const auto& ct : constraints)
    {
        auto v = cdt.vertices_in_constraint_begin(ct.first);
        auto next = v;
        for (++next; next != cdt.vertices_in_constraint_end(ct.first); ++v, ++next)
        {
            if ((*v)->info() >= 0 && (*next)->info() >= 0)
            {
                pieceTag[key(*v, *next)] = ct.second;
            }
        }
    }

    // Joint edges: the pieces of the joint constraints in the mesh
    for (const auto& ct : joints)
    {
        auto v = cdt.vertices_in_constraint_begin(ct.first);
        auto next = v;
        for (++next; next != cdt.vertices_in_constraint_end(ct.first); ++v, ++next)
        {
            if ((*v)->info() >= 0 && (*next)->info() >= 0)
            {
                result.jointEdgeStart.push_back((*v)->info());
                result.jointEdgeEnd.push_back((*next)->info());
                result.jointEdgeTag.push_back(ct.second);
            }
        }
    }

    // Boundary edges: meshed triangle on the left, no meshed one on the right
    for (Face_handle f : cdt.finite_face_handles())
    {
        if (!f->is_in_domain() || f->info() < 0)
        {
            continue;
        }
        for (int i = 0; i < 3; ++i)
        {
            const Face_handle n = f->neighbor(i);
            if (!cdt.is_infinite(n) && n->is_in_domain() && n->info() >= 0)
            {
                continue;
            }
            const Vertex_handle a = f->vertex((i + 1) % 3);
            const Vertex_handle b = f->vertex((i + 2) % 3);
            const auto iter = pieceTag.find(key(a, b));
            result.edgeStart.push_back(a->info());
            result.edgeEnd.push_back(b->info());
            result.edgeTag.push_back(iter == pieceTag.end() ? -1 : iter->second);
        }
    }
    return result;
}
