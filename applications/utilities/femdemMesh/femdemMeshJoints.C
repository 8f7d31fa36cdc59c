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
    std::ifstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(d)
            << "joint set " << spec.name << ", entry 'file': cannot read "
            << file << exit(FatalIOError);
    }
    std::string line;
    label lineNo = 0;
    std::vector<std::string> header;
    while (header.empty() && std::getline(is, line))
    {
        ++lineNo;
        if (!trim(line).empty() && trim(line)[0] != '#') header = splitCsv(line);
    }
    auto column = [&](const char* name, bool required)
    {
        for (size_t i = 0; i < header.size(); ++i)
        {
            if (header[i] == name) return label(i);
        }
        if (required)
        {
            FatalIOErrorInFunction(d)
                << "joint set " << spec.name << ", entry 'file': " << file
                << " has no column '" << name << "' in its header row"
                << " (needed: x y orientation length; optional:"
                << " tensileStrength frictionAngle)" << exit(FatalIOError);
        }
        return label(-1);
    };
    const label cx = column("x", true), cy = column("y", true);
    const label co = column("orientation", true), cl = column("length", true);
    const label cs = column("tensileStrength", false);
    const label cf = column("frictionAngle", false);
    const scalar ftSet = d.getOrDefault<scalar>("tensileStrength", -1);
    if (cs >= 0 && !(ftSet > 0))
    {
        FatalIOErrorInFunction(d)
            << "joint set " << spec.name << ": " << file << " has a column"
            << " 'tensileStrength', so the set needs a positive entry"
            << " 'tensileStrength' (the rows scale it)" << exit(FatalIOError);
    }
    spec.perEdgeFactor = (cs >= 0);
    spec.perEdgeFriction = (cf >= 0);

    while (std::getline(is, line))
    {
        ++lineNo;
        if (trim(line).empty() || trim(line)[0] == '#') continue;
        const std::vector<std::string> cells = splitCsv(line);
        auto value = [&](const label c)
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
                FatalIOErrorInFunction(d)
                    << "joint set " << spec.name << ", entry 'file': " << file
                    << " line " << lineNo << ", column '" << header[c].c_str()
                    << "': not a finite number" << exit(FatalIOError);
            }
            return scalar(v);
        };
        const vector2D c(value(cx), value(cy));
        const scalar a = value(co)*constant::mathematical::pi/180;
        const vector2D h = 0.5*value(cl)*vector2D(std::cos(a), std::sin(a));
        femdemMeshJoints::segment s{c - h, c + h, setIndex, 1, -1, lineNo};
        if (cs >= 0)
        {
            s.factor = value(cs)/ftSet;
            if (!(s.factor > 0))
            {
                FatalIOErrorInFunction(d)
                    << "joint set " << spec.name << ": " << file << " line "
                    << lineNo << ": tensileStrength must be positive"
                    << exit(FatalIOError);
            }
        }
        if (cf >= 0)
        {
            s.frictionAngle = value(cf);
            if (!(s.frictionAngle >= 0 && s.frictionAngle < 90))
            {
                FatalIOErrorInFunction(d)
                    << "joint set " << spec.name << ": " << file << " line "
                    << lineNo << ": frictionAngle must lie in [0, 90)"
                    << exit(FatalIOError);
            }
        }
        if (!(value(cl) > 0 && mag(s.b - s.a) > 0))
        {
            FatalIOErrorInFunction(d)
                << "joint set " << spec.name << ", entry 'file': " << file
                << " line " << lineNo << ", column 'length': the fracture"
                << " must have a positive length" << exit(FatalIOError);
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
    // Relative tolerance on the parameters: a joint end on an outline (to
    // round-off) is a crossing, shared with the outline
    const scalar eps = 1e-10;
    forAll(segments, si)
    {
        const segment& sg = segments[si];
        const vector2D d = sg.b - sg.a;
        // Crossings: parameter t on the segment, outline, side, s on side
        DynamicList<outlinePoint> hits;
        DynamicList<scalar> hitT;
        DynamicList<vector2D> hitX;
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
                hits.append(outlinePoint{o, label(k), s, -1});
                hitT.append(min(max(ti, scalar(0)), scalar(1)));
                hitX.append(p + min(max(s, scalar(0)), scalar(1))*e);
            }
        }
        // Pieces between consecutive distinct crossings, kept when inside
        SortableList<scalar> ts(hitT.size() + 2);
        ts[0] = 0; ts[1] = 1;
        forAll(hitT, i) ts[i + 2] = hitT[i];
        ts.sort();
        DynamicList<scalar> cuts;
        for (const scalar x : ts)
        {
            if (cuts.empty() || x - cuts.last() > eps) cuts.append(x);
        }
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
                vector2D x = sg.a + cuts[c]*d;
                forAll(hitT, h)
                {
                    if (mag(hitT[h] - cuts[c]) <= eps) { x = hitX[h]; break; }
                }
                out.points.append(x);
            }
            return cutPoint[c];
        };
        bool any = false;
        for (label c = 0; c + 1 < cuts.size(); ++c)
        {
            if (!inSolid(sg.a + 0.5*(cuts[c] + cuts[c + 1])*d))
            {
                ++out.nClipped;
                continue;
            }
            any = true;
            out.pieceStart.append(pointAt(c));
            out.pieceEnd.append(pointAt(c + 1));
            out.pieceSegment.append(si);
        }
        if (!any)
        {
            const dictionary& d =
                meshDict.subDict("jointSets").subDict(sets[sg.set].name);
            const jointSetSpec& js = sets[sg.set];
            FatalIOErrorInFunction(d) << "joint set " << js.name;
            if (js.file.empty())
            {
                FatalIOError << ", entry 'segments': segment " << sg.index;
            }
            else
            {
                FatalIOError
                    << ", entry 'file': " << js.file << " line " << sg.index;
            }
            FatalIOError
                << " " << sg.a << " " << sg.b << " lies outside the solid"
                << " (no part of it is in a solid of entry 'solids' outside"
                << " the holes)" << exit(FatalIOError);
        }
        // Crossings used by a kept piece go into their outline side
        forAll(hits, h)
        {
            label c = 0;
            while (c + 1 < cuts.size() && mag(cuts[c] - hitT[h]) > eps) ++c;
            if (cutPoint[c] >= 0)
            {
                outlinePoint op = hits[h];
                op.point = cutPoint[c];
                out.inserted.append(op);
            }
        }
    }
    return out;
}


// ************************************************************************* //
