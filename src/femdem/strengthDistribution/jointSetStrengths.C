/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "jointSetStrengths.H"
#include "EdgeMap.H"
#include "mathematicalConstants.H"
#include <map>
#include <tuple>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

//- A set's properties read from its dictionary; negative: not given
struct setProperties
{
    scalar ft, c, phi, GI, GII;
    strengthDistribution strength;
};


scalar positiveOrUnset(const dictionary& d, const word& key)
{
    const scalar v = d.getOrDefault<scalar>(key, -1);
    if (d.found(key) && !(v > 0))
    {
        FatalIOErrorInFunction(d)
            << "joint set " << d.dictName() << ": entry '" << key
            << "' must be positive, got " << v << exit(FatalIOError);
    }
    return v;
}


setProperties readSet(const triangleJointSet& js)
{
    const dictionary& d = js.properties;
    setProperties p;
    p.ft = positiveOrUnset(d, "tensileStrength");
    p.c = positiveOrUnset(d, "cohesion");
    p.GI = positiveOrUnset(d, "GI");
    p.GII = positiveOrUnset(d, "GII");
    p.phi = d.getOrDefault<scalar>("frictionAngle", -1);
    if (d.found("frictionAngle") && !(p.phi >= 0 && p.phi < 90))
    {
        FatalIOErrorInFunction(d)
            << "joint set " << js.name << ": entry 'frictionAngle' must lie"
            << " in [0, 90) degrees, got " << p.phi << exit(FatalIOError);
    }
    p.strength = strengthDistribution(d);
    return p;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::label Foam::jointSetStrengths::apply
(
    const triangleMesh& mesh,
    const jointTopology& topo,
    const UList<femdemMaterial>& materials,
    List<femdemJointProperties>& classes,
    labelList& jointClass,
    scalarList& jointStrength
)
{
    const List<triangleJointSet>& sets = mesh.jointSets();
    if (sets.empty()) return 0;

    List<setProperties> props(sets.size());
    EdgeMap<labelPair> setOfEdge;
    forAll(sets, s)
    {
        props[s] = readSet(sets[s]);
        forAll(sets[s].edges, i)
        {
            setOfEdge.set(sets[s].edges[i], labelPair(s, i));
        }
    }

    const scalar deg = constant::mathematical::pi/180;
    const label nPairClasses = classes.size();
    DynamicList<femdemJointProperties> newClasses(classes);
    std::map<std::tuple<label, label, scalar>, label> classOf;
    const List<vector2D>& X = topo.initialPoints();
    const labelList& vertex = topo.nodeVertex();
    DynamicList<label> setJoints;
    scalarList factor(jointClass.size(), scalar(1));
    bool anyFactor = !jointStrength.empty();

    forAll(jointClass, j)
    {
        const jointNodeList& n = topo.jointNodes()[j];
        const label a = vertex[n[0]], b = vertex[n[1]];
        const auto iter = setOfEdge.cfind(edge(a, b));
        if (!iter.found()) continue;
        const label s = (*iter).first(), i = (*iter).second();
        const triangleJointSet& js = sets[s];
        const setProperties& P = props[s];
        const scalar phi =
            js.frictionAngle.empty() ? P.phi : js.frictionAngle[i];

        const auto key = std::make_tuple(jointClass[j], s, phi);
        auto c = classOf.find(key);
        if (c == classOf.end())
        {
            femdemJointProperties q = classes[jointClass[j]];
            if (P.ft > 0) q.ft = P.ft;
            if (P.c > 0) q.c = P.c;
            if (phi >= 0) q.tanPhi = Foam::tan(phi*deg);
            if (P.GI > 0) q.GI = P.GI;
            if (P.GII > 0) q.GII = P.GII;
            c = classOf.emplace(key, newClasses.size()).first;
            newClasses.append(q);
        }
        jointClass[j] = c->second;
        factor[j] =
            (js.strengthFactor.empty() ? scalar(1) : js.strengthFactor[i])
           *P.strength.factor(X[a], X[b]);
        anyFactor = anyFactor || factor[j] != 1;
        setJoints.append(j);
    }
    if (newClasses.size() > 256)
    {
        FatalIOErrorInFunction(sets.last().properties)
            << "the joint sets of the solid mesh give "
            << newClasses.size() - nPairClasses << " joint classes (material"
            << " pair x set x distinct friction angle) besides the "
            << nPairClasses << " of the material pairs: at most 256 in all"
            << " (use fewer distinct frictionAngle values)"
            << exit(FatalIOError);
    }
    classes.transfer(newClasses);
    Info<< "Joint sets: " << setJoints.size() << " of " << jointClass.size()
        << " joints on set edges, " << classes.size() - nPairClasses
        << " joint classes added" << nl;

    if (anyFactor)
    {
        if (jointStrength.empty()) jointStrength.setSize(jointClass.size(), 1);
        for (const label j : setJoints) jointStrength[j] = factor[j];
    }
    return setJoints.size();
}


// ************************************************************************* //
