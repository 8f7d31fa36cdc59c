/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "crackGasCoupling.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::crackGasCoupling::crackGasCoupling
(
    const fvMesh& mesh,
    const solidProjection& projection,
    const jointTopology& topology,
    const blastMixture& mixture,
    const dictionary& dict,
    const scalar depth
)
:
    mesh_(mesh),
    projection_(projection),
    net_(topology, mixture, dict),
    depth_(depth),
    lostMass_(0),
    lostEnergy_(0)
{
    // A misspelt entry would silently take its default
    const wordList valid
    ({"flux", "RKorder", "frictionFactor", "minAperture", "ambient"});
    for (const word& key : dict.toc())
    {
        if (!valid.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "unknown entry '" << key << "' in crackGas; valid: "
                << valid << exit(FatalIOError);
        }
    }
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(dict)
            << "crackGas runs serial only for now (the network of each"
            << " rank's solid is not built); remove the sub-dictionary"
            << " 'crackGas' for a parallel run" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::crackGasCoupling::beginStep
(
    const UList<vector2D>& x,
    const boolList& broken,
    const gasView& view,
    const blastFluidSolver& fluid
)
{
    // The joints: broken, not open to the gas
    const boolList& open = view.openJoints();
    joints_.clear();
    forAll(broken, j)
    {
        if (broken[j] && !open[j]) joints_.append(j);
    }
    if (joints_ != net_.joints())
    {
        released_.clear();
        net_.setJoints(joints_, x, &released_);
        // Handed over: into the fluid cell with gas at the joint's
        // midpoint, else at one of its nodes (the crack opened to the gas
        // runs through them)
        const jointTopology& topo = view.view().topology();
        const scalarField* phi = fluid.fluidFractionField();
        for (const auto& r : released_)
        {
            const jointNodeList& jn = topo.jointNodes()[r.first];
            const vector2D at[5] =
            {
                0.25*(x[jn[0]] + x[jn[1]] + x[jn[2]] + x[jn[3]]),
                x[jn[0]], x[jn[1]], x[jn[2]], x[jn[3]]
            };
            label c = -1;
            for (const vector2D& pt : at)
            {
                const label ci = projection_.findCell(pt);
                if (ci >= 0 && (!phi || (*phi)[ci] > 0))
                {
                    c = ci;
                    break;
                }
            }
            if (c >= 0)
            {
                givenCell_.append(c);
                given_.append(r.second);
            }
            else
            {
                lostMass_ += r.second.m;
                lostEnergy_ += r.second.mE;
            }
        }
    }

    // Mouths: crack ends at points of the view's outline
    const continuousView& cv = view.view();
    onOutline_.setSize(cv.points().size());
    onOutline_ = false;
    for (const edge& e : cv.boundaryEdges())
    {
        onOutline_[e.start()] = true;
        onOutline_[e.end()] = true;
    }
    const labelList& pointOfNode = cv.pointOfNode();
    const scalarField* phi = fluid.fluidFractionField();
    mouths_.clear();
    mouthCell_.clear();
    forAll(net_.joints(), i)
    {
        const jointNodeList& jn = cv.topology().jointNodes()[net_.joints()[i]];
        for (const label e : {0, 1})
        {
            const label pt = pointOfNode[jn[e]];
            if (!onOutline_[pt]) continue;
            const label c = projection_.findCell(cv.points()[pt]);
            if (c < 0 || (phi && !((*phi)[c] > 0))) continue;
            mouths_.append(FixedList<label, 2>({i, e}));
            mouthCell_.append(c);
        }
    }
    net_.setMouths(mouths_);

    // Their plenums: the cells' states; a quarter of a cell's gas at most
    ductNetwork::plenumStates& pl = net_.plenum();
    const bool two = fluid.mixture().twoPhase();
    forAll(mouths_, k)
    {
        const label f = net_.mouthInterface(k), c = mouthCell_[k];
        pl.rho[f] = fluid.rho()[c];
        pl.p[f] = fluid.p()[c];
        if (two)
        {
            pl.alpha1[f] = fluid.alpha1()[c];
            pl.rho1[f] = fluid.rho1()[c];
            pl.rho2[f] = fluid.rho2()[c];
        }
        const scalar gasVolume = (phi ? (*phi)[c] : 1)*mesh_.V()[c];
        pl.maxMass[f] = 0.25*fluid.rho()[c]*gasVolume/depth_;
    }
}


Foam::label Foam::crackGasCoupling::advanceSolid
(
    femdemSolid& solid,
    const List<vector2D>& otherForces,
    const scalar dt
)
{
    crackNetwork::subSteps hook(net_, otherForces);
    const label n = solid.advance(dt, hook);
    net_.endStep(solid.x(), dt);
    return n;
}


void Foam::crackGasCoupling::exchange(blastFluidSolver& fluid)
{
    // What entered the mouths leaves their cells; handed-over gas enters
    // (per unit depth in the network, times the depth in the mesh)
    DynamicList<label>& cells = cells_;
    DynamicList<scalar>& dm = dm_;
    DynamicList<scalar>& dE = dE_;
    DynamicList<scalar>& dm1 = dm1_;
    DynamicList<vector>& dmU = dmU_;
    cells.clear(); dm.clear(); dE.clear(); dm1.clear(); dmU.clear();
    forAll(mouths_, k)
    {
        cells.append(mouthCell_[k]);
        dm.append(-depth_*net_.mouthMass()[k]);
        // No momentum: what crosses a mouth is mostly its pressure impulse,
        // which the cell's wall term already gives its gas (the mouth is
        // part of the solid's outline in the cell); handed to a small cell
        // it made kinetic energy out of nothing
        dmU.append(vector::zero);
        dE.append(-depth_*net_.mouthEnergy()[k]);
        dm1.append(-depth_*net_.mouthMass1()[k]);
    }
    forAll(givenCell_, k)
    {
        const ductNetwork::content& c = given_[k];
        cells.append(givenCell_[k]);
        dm.append(depth_*c.m);
        dmU.append(vector::zero);
        dE.append(depth_*c.mE);
        dm1.append(depth_*c.m1);
    }
    givenCell_.clear();
    given_.clear();
    if (cells.size())
    {
        fluid.addContent(cells, dm, dmU, dE, dm1);
    }
}


// ************************************************************************* //
