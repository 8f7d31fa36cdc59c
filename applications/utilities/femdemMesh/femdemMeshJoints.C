/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemMeshJoints.H"
#include "mathematicalConstants.H"
#include "SortableList.H"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(" \t\r\"'");
    if (b == std::string::npos) return std::string();
    const auto e = s.find_last_not_of(" \t\r\"'");
    return s.substr(b, e - b + 1);
}


std::vector<std::string> splitCsv(const std::string& line)
{
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ','))
    {
        cells.push_back(trim(cell));
    }
    return cells;
}


//- A DFN file being read: its header and messages naming the set's
//  dictionary, the file, the line and the column
class csvFile
{
    const dictionary& d_;
    const word& set_;
    const fileName& file_;
    std::ifstream is_;

public:

    std::vector<std::string> header;
    label lineNo = 0;

    csvFile(const dictionary& d, const word& set, const fileName& file)
    :
        d_(d), set_(set), file_(file), is_(file)
    {
        if (!is_.good()) fail("") << "cannot read " << file_ << exit(FatalIOError);
        std::vector<std::string> cells;
        while (header.empty() && next(cells)) header = cells;
    }

    //- FatalIOError stream with the set, the entry, file and line
    error& fail(const std::string& column)
    {
        FatalIOErrorInFunction(d_) << "joint set " << set_ << ", entry 'file': ";
        if (lineNo > 0) FatalIOError << file_ << " line " << lineNo << ", ";
        if (!column.empty()) FatalIOError << "column '" << column.c_str() << "': ";
        return FatalIOError;
    }

    //- The next row that is not empty nor a comment; false at the end
    bool next(std::vector<std::string>& cells)
    {
        std::string line;
        while (std::getline(is_, line))
        {
            ++lineNo;
            if (trim(line).empty() || trim(line)[0] == '#') continue;
            cells = splitCsv(line);
            return true;
        }
        return false;
    }

    //- Index of a column by name (-1 if absent and not required)
    label column(const char* name, const bool required)
    {
        for (size_t i = 0; i < header.size(); ++i)
        {
            if (header[i] == name) return label(i);
        }
        if (required)
        {
            lineNo = 0;
            fail("") << file_ << " has no column '" << name << "' in its header"
                << " row (needed: x y orientation length; optional:"
                << " tensileStrength frictionAngle)" << exit(FatalIOError);
        }
        return -1;
    }

    //- The number in column c of a row
    scalar value(const std::vector<std::string>& cells, const label c)
    {
        double v = 0;
        size_t used = 0;
        bool ok = c < label(cells.size());
        if (ok)
        {
            try { v = std::stod(cells[c], &used); }
            catch (...) { ok = false; }
        }
        if (!ok || used != cells[c].size() || !std::isfinite(v))
        {
            fail(header[c]) << "not a finite number" << exit(FatalIOError);
        }
        return v;
    }
};


//- Read the fractures of a CSV file (columns by name, see header)
void readCsv
(
    const dictionary& d,
    const label setIndex,
    const fileName& file,
    femdemMeshJoints::jointSetSpec& spec,
    DynamicList<femdemMeshJoints::segment>& segments
)
{
    csvFile csv(d, spec.name, file);
    const label cx = csv.column("x", true), cy = csv.column("y", true);
    const label co = csv.column("orientation", true);
    const label cl = csv.column("length", true);
    const label cs = csv.column("tensileStrength", false);
    const label cf = csv.column("frictionAngle", false);
    const scalar ftSet = d.getOrDefault<scalar>("tensileStrength", -1);
    if (cs >= 0 && !(ftSet > 0))
    {
        csv.fail("tensileStrength") << "the rows scale the set's entry"
            << " 'tensileStrength', which must be given and positive"
            << exit(FatalIOError);
    }
    spec.perEdgeFactor = (cs >= 0);
    spec.perEdgeFriction = (cf >= 0);

    std::vector<std::string> row;
    while (csv.next(row))
    {
        const vector2D c(csv.value(row, cx), csv.value(row, cy));
        const scalar a = csv.value(row, co)*constant::mathematical::pi/180;
        const scalar L = csv.value(row, cl);
        const vector2D h = 0.5*L*vector2D(std::cos(a), std::sin(a));
        femdemMeshJoints::segment s{c - h, c + h, setIndex, 1, -1, csv.lineNo};
        if (!(L > 0 && mag(s.b - s.a) > 0))
        {
            csv.fail("length") << "the fracture must have a positive length"
                << exit(FatalIOError);
        }
        if (cs >= 0 && !((s.factor = csv.value(row, cs)/ftSet) > 0))
        {
            csv.fail("tensileStrength") << "must be positive" << exit(FatalIOError);
        }
        if (cf >= 0)
        {
            s.frictionAngle = csv.value(row, cf);
            if (!(s.frictionAngle >= 0 && s.frictionAngle < 90))
            {
                csv.fail("frictionAngle") << "must lie in [0, 90) degrees"
                    << exit(FatalIOError);
            }
        }
        segments.append(s);
    }
}


scalar cross(const vector2D& a, const vector2D& b)
{
    return a.x()*b.y() - a.y()*b.x();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::femdemMeshJoints::read
(
    const dictionary& meshDict,
    const fileName& casePath,
    DynamicList<jointSetSpec>& sets,
    DynamicList<segment>& segments
)
{
    const dictionary* jPtr = meshDict.findDict("jointSets");
    if (!jPtr) return;
    for (const word& key : jPtr->toc())
    {
        const dictionary& d = jPtr->subDict(key);
        jointSetSpec spec{key, d, false, false, fileName()};
        spec.properties.remove("type");
        spec.properties.remove("segments");
        spec.properties.remove("file");
        const word type = d.get<word>("type");
        const label first = segments.size();
        if (type == "lines")
        {
            const List<Pair<vector2D>> segs =
                d.get<List<Pair<vector2D>>>("segments");
            forAll(segs, i)
            {
                if (!(mag(segs[i].second() - segs[i].first()) > 0))
                {
                    FatalIOErrorInFunction(d)
                        << "joint set " << key << ", entry 'segments':"
                        << " segment " << i << " " << segs[i]
                        << " has zero length" << exit(FatalIOError);
                }
                segments.append
                (
                    segment{segs[i].first(), segs[i].second(), sets.size(), 1, -1, i}
                );
            }
        }
        else if (type == "file")
        {
            fileName file = d.get<fileName>("file");
            file.expand();
            if (!file.isAbsolute()) file = casePath/file;
            spec.file = file;
            readCsv(d, sets.size(), file, spec, segments);
        }
        else
        {
            FatalIOErrorInFunction(d)
                << "joint set " << key << ": unknown type " << type
                << "; valid types: (lines file)" << exit(FatalIOError);
        }
        if (segments.size() == first)
        {
            FatalIOErrorInFunction(d)
                << "joint set " << key << " has no segments"
                << exit(FatalIOError);
        }
        sets.append(spec);
    }
}


namespace
{

//- Relative tolerance on the parameters: a joint end on an outline (to
//  round-off) is a crossing, shared with the outline
const Foam::scalar eps = 1e-10;

//- Where a segment crosses the outlines: the outline points (side, s),
//  the parameter t on the segment and the point on the side
struct crossings
{
    DynamicList<femdemMeshJoints::outlinePoint> hits;
    DynamicList<scalar> t;
    DynamicList<vector2D> x;

    crossings
    (
        const femdemMeshJoints::segment& sg,
        const UList<List<vector2D>>& outlines
    )
    {
        const vector2D d = sg.b - sg.a;
        forAll(outlines, o)
        {
            const List<vector2D>& P = outlines[o];
            forAll(P, k)
            {
                const vector2D& p = P[k];
                const vector2D e = P[(k + 1) % P.size()] - p;
                const scalar den = cross(d, e);
                if (den == 0) continue;     // parallel (or overlapping)
                const scalar ti = cross(p - sg.a, e)/den;
                const scalar s = cross(p - sg.a, d)/den;
                if (ti < -eps || ti > 1 + eps || s < -eps || s > 1 + eps)
                {
                    continue;
                }
                hits.append({o, label(k), s, -1});
                t.append(min(max(ti, scalar(0)), scalar(1)));
                x.append(p + min(max(s, scalar(0)), scalar(1))*e);
            }
        }
    }

    //- Distinct parameters of the cuts: 0, the crossings, 1
    DynamicList<scalar> cuts() const
    {
        SortableList<scalar> ts(t.size() + 2);
        ts[0] = 0; ts[1] = 1;
        forAll(t, i) ts[i + 2] = t[i];
        ts.sort();
        DynamicList<scalar> c;
        for (const scalar v : ts)
        {
            if (c.empty() || v - c.last() > eps) c.append(v);
        }
        return c;
    }
};


[[noreturn]] void outsideError
(
    const dictionary& meshDict,
    const femdemMeshJoints::jointSetSpec& js,
    const femdemMeshJoints::segment& sg
)
{
    const dictionary& d = meshDict.subDict("jointSets").subDict(js.name);
    FatalIOErrorInFunction(d) << "joint set " << js.name;
    if (js.file.empty())
    {
        FatalIOError << ", entry 'segments': segment " << sg.index;
    }
    else
    {
        FatalIOError << ", entry 'file': " << js.file << " line " << sg.index;
    }
    FatalIOError
        << " " << sg.a << " " << sg.b << " lies outside the solid (no part"
        << " of it is in a solid of entry 'solids' outside the holes)"
        << exit(FatalIOError);
    std::abort();   // not reached
}

} // End anonymous namespace


Foam::femdemMeshJoints::clippedJoints Foam::femdemMeshJoints::clip
(
    const dictionary& meshDict,
    const UList<jointSetSpec>& sets,
    const UList<segment>& segments,
    const UList<List<vector2D>>& outlines,
    const std::function<bool(const vector2D&)>& inSolid
)
{
    clippedJoints out;
    forAll(segments, si)
    {
        const segment& sg = segments[si];
        const crossings X(sg, outlines);
        const DynamicList<scalar> cuts = X.cuts();
        // One point per cut, shared by the outlines that cross there. A
        // crossing is placed on the outline side (exactly on an axis-aligned
        // side): a boundary bent by round-off makes CGAL's mesher fail on
        // the near-degenerate corner; the joint takes the round-off instead
        labelList cutPoint(cuts.size(), -1);
        auto pointAt = [&](const label c)
        {
            if (cutPoint[c] < 0)
            {
                cutPoint[c] = out.points.size();
                vector2D x = sg.a + cuts[c]*(sg.b - sg.a);
                forAll(X.t, h)
                {
                    if (mag(X.t[h] - cuts[c]) <= eps) { x = X.x[h]; break; }
                }
                out.points.append(x);
            }
            return cutPoint[c];
        };
        // Pieces between consecutive cuts, kept when their middle is inside
        bool any = false;
        for (label c = 0; c + 1 < cuts.size(); ++c)
        {
            if (!inSolid(sg.a + 0.5*(cuts[c] + cuts[c + 1])*(sg.b - sg.a)))
            {
                ++out.nClipped;
                continue;
            }
            any = true;
            out.pieceStart.append(pointAt(c));
            out.pieceEnd.append(pointAt(c + 1));
            out.pieceSegment.append(si);
        }
        if (!any) outsideError(meshDict, sets[sg.set], sg);
        // Crossings used by a kept piece go into their outline side
        forAll(X.hits, h)
        {
            label c = 0;
            while (c + 1 < cuts.size() && mag(cuts[c] - X.t[h]) > eps) ++c;
            if (cutPoint[c] >= 0)
            {
                outlinePoint op = X.hits[h];
                op.point = cutPoint[c];
                out.inserted.append(op);
            }
        }
    }
    return out;
}


// ************************************************************************* //
