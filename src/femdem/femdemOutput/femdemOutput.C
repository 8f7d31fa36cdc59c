/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemOutput.H"
#include "caseChecks.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "edgeList.H"
#include "strengthDistribution.H"
#include "Pstream.H"
#include <cstring>
#include <cstdio>

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::femdemOutput::writeState
(
    const femdemSolid& solid,
    const fileName& file
)
{
    mkDir(file.path());
    OFstream os(file);
    os  << "FoamFile" << nl << "{" << nl
        << "    version     2.0;" << nl
        << "    format      ascii;" << nl
        << "    class       dictionary;" << nl
        << "    object      " << file.name() << ";" << nl
        << "}" << nl << nl;
    solid.writeState(os);
}


void Foam::femdemOutput::checkStateShape
(
    const femdemSolid& solid,
    const dictionary& dict
)
{
    // The solver stops before a triangle inverts or stretches its edges
    // tenfold (elastic rock strains are below a percent): such a state is
    // a damaged or edited file, not a state to continue
    const List<vector2D>& x = solid.x();
    const List<vector2D>& X0 = solid.topology().initialPoints();
    const labelList& vertex = solid.topology().nodeVertex();
    for (label t = 0; t < solid.topology().nTriangles(); ++t)
    {
        const label n0 = jointTopology::node(t, 0);
        const vector2D ab = x[n0 + 1] - x[n0], ac = x[n0 + 2] - x[n0];
        scalar stretch = 1;
        for (label k = 0; k < 3; ++k)
        {
            const label i = n0 + k, j = n0 + (k + 1)%3;
            const scalar L0 = mag(X0[vertex[j]] - X0[vertex[i]]);
            const scalar L = mag(x[j] - x[i]);
            stretch = max(stretch, max(L/L0, L0/max(L, VSMALL)));
        }
        if (!(ab.x()*ac.y() - ab.y()*ac.x() > 0) || !(stretch < 10))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'x': triangle " << t << " (nodes " << n0 << ' '
                << n0 + 1 << ' ' << n0 + 2 << ") is inverted or an edge is"
                << " stretched by a factor " << stretch << " relative to"
                << " constant/solidMesh: not a state the solver writes"
                << exit(FatalIOError);
        }
    }
}


bool Foam::femdemOutput::readState(femdemSolid& solid, const fileName& file)
{
    if (!isFile(file))
    {
        return false;
    }
    IFstream is(file);
    const dictionary dict(is);
    // Duplicates, numbers, list sizes; the counts the state declares
    caseChecks::checkInput(dict);
    const label nNodes = dict.get<label>("nNodes");
    const label nJoints = dict.get<label>("nJoints");
    const label nx = dict.get<List<vector2D>>("x").size();
    const label nb = dict.get<boolList>("broken").size();
    if (nNodes != nx || nJoints != nb)
    {
        FatalIOErrorInFunction(dict)
            << "entries 'nNodes' " << nNodes << " and 'nJoints' " << nJoints
            << " do not match the sizes of 'x' (" << nx << ") and 'broken' ("
            << nb << ')' << exit(FatalIOError);
    }
    solid.readState(dict);
    checkStateShape(solid, dict);
    return true;
}


void Foam::femdemOutput::writeVtk
(
    solidVtkWriter& writer,
    const femdemSolid& solid,
    const fileName& vtkDir,
    const scalar time,
    const UList<word>& jointFieldNames,
    const UList<scalarList>& jointFieldValues
)
{
    // The first step of a run continues the series of an earlier run: a
    // restarted solid (timeIndex > 0, read from a femdemState) keeps the
    // frames up to the restart time and does not write that one again; a
    // fresh solid replaces the frames from its start time on
    if (writer.nSteps() == 0 && !writer.continued())
    {
        writer.setLinesName("cracks");
        if (writer.continueSeries(time, solid.timeIndex() > 0))
        {
            return;
        }
    }

    const continuousView& view = solid.view();
    writer.beginStep(time, view.points(), view.triangles());
    writer.addTriangleField("stress", solid.stress());
    writer.addTriangleField("velocity", solid.triangleVelocity());
    writer.addTriangleField("damage", solid.triangleDamage());
    writer.addTriangleField("material", solid.triangleMaterial());
    writer.addTriangleField("fragment", view.fragmentOfTriangle());

    // Broken joints as lines along their mid-line, with the joint's
    // initial length: VTK/cracks_<step>.vtp and cracks.vtp.series
    const List<jointNodeList>& jn = solid.topology().jointNodes();
    DynamicList<vector2D> pts;
    DynamicList<edge> lines;
    DynamicList<scalar> length;
    forAll(jn, j)
    {
        if (!solid.jointBroken()[j]) continue;
        const jointNodeList& n = jn[j];
        const label i = pts.size();
        pts.append(0.5*(solid.x()[n[0]] + solid.x()[n[2]]));
        pts.append(0.5*(solid.x()[n[1]] + solid.x()[n[3]]));
        lines.append(edge(i, i + 1));
        length.append(solid.jointLength0()[j]);
    }
    writer.addLines(pts, edgeList(lines), length, "initialJointLength");
    // A per-joint list as CellData of the broken joints' lines
    const auto addBroken = [&](const word& name, const scalarList& all)
    {
        if (all.size() != jn.size())
        {
            FatalErrorInFunction
                << "joint field " << name << " has " << all.size()
                << " values for " << jn.size() << " joints"
                << exit(FatalError);
        }
        scalarList values(lines.size());
        label i = 0;
        forAll(jn, j)
        {
            if (solid.jointBroken()[j]) values[i++] = all[j];
        }
        writer.addLineField(name, values);
    };
    if (solid.jointStrength().size())
    {
        addBroken("strengthFactor", solid.jointStrength());
    }
    forAll(jointFieldValues, k)
    {
        addBroken(jointFieldNames[k], jointFieldValues[k]);
    }
    writer.endStep();
}


void Foam::femdemOutput::reportJointStrengths
(
    const femdemSolid& solid,
    const bool compareRanks
)
{
    const scalarList& w = solid.jointStrength();
    if
    (
        compareRanks
      ? !returnReduce(w.size() > 0, orOp<bool>())
      : w.empty()
    )
    {
        return;
    }
    scalar sum = 0, sum2 = 0, lo = GREAT, hi = -GREAT;
    uint64_t digest = 0;
    for (const scalar f : w)
    {
        sum += f;
        sum2 += f*f;
        lo = min(lo, f);
        hi = max(hi, f);
        uint64_t b;
        std::memcpy(&b, &f, sizeof b);
        digest += strengthDistribution::mix(b);   // order-free (mod 2^64)
    }
    const label n = w.size();
    const scalar mean = n ? sum/n : 0;
    const scalar cv =
        n > 1 && mean > 0
      ? std::sqrt(max(sum2/n - mean*mean, scalar(0))*n/(n - 1))/mean
      : 0;
    char hex[24];
    std::snprintf
    (
        hex, sizeof hex, "%016llx", static_cast<unsigned long long>(digest)
    );

    // Every rank's digest and count to the master, which compares them
    List<word> digests(Pstream::nProcs());
    label differ = 0;
    if (compareRanks)
    {
        digests[Pstream::myProcNo()] = word(hex) + "/" + Foam::name(n);
        Pstream::gatherList(digests);
        if (Pstream::master())
        {
            forAll(digests, proci)
            {
                if (digests[proci] != digests[0]) ++differ;
            }
        }
        reduce(differ, maxOp<label>());
    }
    Info<< "Joint strengths (strengthDistribution): " << n << " joints,"
        << " factor mean " << mean << ", coefficient of variation " << cv
        << ", min " << lo << ", max " << hi << ", digest " << hex;
    if (Pstream::parRun() && compareRanks)
    {
        if (differ)
        {
            Info<< "; DIFFER between ranks";
        }
        else
        {
            Info<< "; the same on all " << Pstream::nProcs() << " ranks";
        }
    }
    Info<< endl;
    if (differ)
    {
        FatalErrorInFunction
            << "the joint strengths differ between the ranks (digest/joints"
            << " per rank: " << digests << "): every rank must read the"
            << " same constant/solidMesh and femdemProperties"
            << exit(FatalError);
    }
}


void Foam::femdemOutput::writeCracks
(
    const femdemSolid& solid,
    const fileName& file
)
{
    OFstream os(file);
    os.precision(10);
    os  << "# broken joints: x0 y0 x1 y1 (initial positions of face p)" << nl;
    const List<jointNodeList>& jn = solid.topology().jointNodes();
    const List<vector2D>& X0 = solid.topology().initialPoints();
    const labelList& vertex = solid.topology().nodeVertex();
    forAll(jn, j)
    {
        if (!solid.jointBroken()[j]) continue;
        const vector2D& a = X0[vertex[jn[j][0]]];
        const vector2D& b = X0[vertex[jn[j][1]]];
        os  << a.x() << ' ' << a.y() << ' ' << b.x() << ' ' << b.y() << nl;
    }
}


// ************************************************************************* //
