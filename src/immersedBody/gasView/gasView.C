/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "gasView.H"
#include "Time.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasView::gasView
(
    const fvMesh& mesh,
    const dictionary& dict
)
:
    mesh_(mesh),
    crackOpening_(dict.getOrDefault<scalar>("crackOpening", 0.5)),
    crackVenting_(dict.getOrDefault<bool>("crackVenting", true)),
    openJoints_
    (
        IOobject
        (
            "openJoints",
            mesh.time().timeName(),
            "uniform",
            mesh.time(),
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    ),
    nOpen_(0)
{
    if (!(crackOpening_ >= 0 && crackOpening_ < GREAT))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'crackOpening' is " << crackOpening_ << "; it must be"
            << " >= 0 (the crack width, in local cell sizes, from which the"
            << " gas enters a crack)" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gasView::initialise
(
    const continuousView& solidView,
    const UList<vector2D>& x
)
{
    const jointTopology& topo = solidView.topology();
    const boolList& broken = solidView.jointBroken();
    // Broken joints at the first step: a restart, which needs the list
    if (!openJoints_.headerOk() && solidView.nBrokenJoints() > 0)
    {
        FatalErrorInFunction
            << "Restart with broken joints but without the joints open to"
            << " the gas: file " << openJoints_.objectPath() << " is missing"
            << " (written with every time by method cutCell)"
            << exit(FatalError);
    }
    open_.setSize(topo.nJoints(), false);
    view_.reset(new continuousView(topo));

    // Replay the openings step by step
    for (const labelList& step : openJoints_)
    {
        for (const label j : step)
        {
            if (j < 0 || j >= topo.nJoints() || !broken[j] || open_[j])
            {
                FatalErrorInFunction
                    << "file " << openJoints_.objectPath() << ": joint " << j
                    << " cannot be open to the gas: the solid has "
                    << topo.nJoints() << " joints and this one is "
                    << (j < 0 || j >= topo.nJoints() ? "out of range"
                      : open_[j] ? "listed twice" : "not broken")
                    << exit(FatalError);
            }
            open_[j] = true;
            ++nOpen_;
        }
        view_->update(x, open_);
    }
}


void Foam::gasView::candidateCellSizes
(
    const UList<vector2D>& x,
    const solidProjection& cells
)
{
    // The cell holding the joint's midpoint, on whichever
    // processor has it; outside the mesh the size is 0 (opens at once:
    // there is no gas there to see it). Only for the joints the outline
    // reaches (exposed_): the others cannot open (their size is left 0;
    // the same on every processor, which all hold the whole view)
    const List<jointNodeList>& nodes = view_->topology().jointNodes();
    const labelList& pointOfNode = view_->pointOfNode();
    const scalarField& area = cells.cellArea();
    cellSize_.setSize(candidates_.size());
    forAll(candidates_, i)
    {
        const jointNodeList& n = nodes[candidates_[i]];
        if (!exposed_[pointOfNode[n[0]]] && !exposed_[pointOfNode[n[1]]])
        {
            cellSize_[i] = 0;
            continue;
        }
        const vector2D m = 0.25*(x[n[0]] + x[n[1]] + x[n[2]] + x[n[3]]);
        const label c = cells.findCell(m);
        cellSize_[i] = c >= 0 ? Foam::sqrt(area[c]) : 0;
    }
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(cellSize_, maxEqOp<scalar>());
        Pstream::listCombineScatter(cellSize_);
    }
}


void Foam::gasView::markExposedPoints()
{
    exposed_.setSize(view_->nPoints());
    exposed_ = false;
    for (const edge& e : view_->boundaryEdges())
    {
        exposed_[e.start()] = true;
        exposed_[e.end()] = true;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::continuousView& Foam::gasView::update
(
    const continuousView& solidView,
    const UList<vector2D>& x,
    const solidProjection& cells
)
{
    if (!view_.valid())
    {
        initialise(solidView, x);
    }
    const boolList& broken = solidView.jointBroken();
    const List<jointNodeList>& nodes = solidView.topology().jointNodes();
    candidates_.clear();
    forAll(broken, j)
    {
        if (crackVenting_ && broken[j] && !open_[j]) candidates_.append(j);
    }
    if (candidates_.size())
    {
        markExposedPoints();
        candidateCellSizes(x, cells);
        const labelList& pointOfNode = view_->pointOfNode();
        DynamicList<label> opened;
        forAll(candidates_, i)
        {
            const label j = candidates_[i];
            const jointNodeList& n = nodes[j];
            const scalar gap =
                max(mag(x[n[2]] - x[n[0]]), mag(x[n[3]] - x[n[1]]));
            const bool reached =
                exposed_[pointOfNode[n[0]]] || exposed_[pointOfNode[n[1]]];
            if (reached && gap >= crackOpening_*cellSize_[i])
            {
                open_[j] = true;
                opened.append(j);
            }
        }
        if (opened.size())
        {
            nOpen_ += opened.size();
            openJoints_.append(labelList(opened));
        }
    }
    view_->update(x, open_);
    return view_();
}


// ************************************************************************* //
