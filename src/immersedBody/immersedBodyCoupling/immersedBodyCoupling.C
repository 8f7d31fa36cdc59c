/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "immersedBodyCoupling.H"
#include "caseChecks.H"
#include "fvMesh.H"
#include "zeroGradientFvPatchFields.H"
#include "syncTools.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    //- Below this a fluid fraction or a face's open fraction is round-off
    //  of a covered cell or face (the overlaps or covered pieces summed a
    //  few ulp short of the whole): no gas, closed. Far below the slivers
    //  the coupling resolves (fractions down to 1.6e-11 in
    //  coupledCutCellsMore)
    const Foam::scalar roundOffFraction = 1e-13;

    //- Stop on a case written for the first-generation coupling (method
    //  fluidFraction, removed): 'method' other than cutCell, and the entries
    //  only that method read, each with what to do instead
    void checkRemovedEntries(const Foam::dictionary& dict)
    {
        using namespace Foam;
        const word method(dict.getOrDefault<word>("method", "cutCell"));
        if (method == "fluidFraction")
        {
            FatalIOErrorInFunction(dict)
                << "entry 'method fluidFraction': the first-generation"
                << " coupling (fluid fractions with apertures min(phi_P,"
                << " phi_N), the gas-transfer step, absorption) was removed;"
                << " delete the entry or write 'method cutCell;' (exact cut"
                << " cells, the only method: doc/theory-coupling.md)"
                << exit(FatalIOError);
        }
        if (method != "cutCell")
        {
            FatalIOErrorInFunction(dict)
                << "entry 'method' is '" << method << "': the only coupling"
                << " method is cutCell (the entry may be left out)"
                << exit(FatalIOError);
        }
        // Entry and what replaces it
        static const char* removed[][2] =
        {
            {
                "minFluidFraction",
                "small cells need no threshold, they are merged with their"
                " neighbours (weighted state redistribution); delete the"
                " entry"
            },
            {
                "beta",
                "the absorption towards the solid velocity is gone, the"
                " walls are moving boundaries of the gas; delete the entry"
            },
            {
                "crackPressure",
                "the sub-cell crack pressure did work the gas did not pay"
                " for; delete the entry (cracks open to the gas from"
                " crackOpening cells wide: crackOpening, crackVenting)"
            }
        };
        for (const auto& r : removed)
        {
            if (dict.found(r[0]))
            {
                FatalIOErrorInFunction(dict)
                    << "entry '" << r[0] << "' was removed with the"
                    << " first-generation coupling (method fluidFraction): "
                    << r[1] << exit(FatalIOError);
            }
        }
    }
}


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
    regions_(mesh.faceOwner(), mesh.faceNeighbour(), projection_),
    depth_(returnReduce(mesh.bounds().span().z(), maxOp<scalar>())),
    aperture_
    (
        IOobject
        (
            "aperture",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar("one", dimless, 1)
    ),
    nNodes_(0),
    viewTriangles_(nullptr),
    alphaSolid_
    (
        caseChecks::fieldIO("alpha.solid", mesh, IOobject::READ_IF_PRESENT),
        mesh,
        dimensionedScalar(dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    Usolid_
    (
        caseChecks::fieldIO("U.solid", mesh, IOobject::NO_READ),
        mesh,
        dimensionedVector(dimVelocity, Zero),
        zeroGradientFvPatchVectorField::typeName
    ),
    triangles_(nTriangles),
    alphaSolidRead_(alphaSolid_.headerOk())
{
    // A misspelt optional entry would silently take its default; the
    // entries of the removed first generation are named as such
    const wordList valid
    ({"method", "crackOpening", "crackVenting", "crackGas"});
    caseChecks::checkInput(dict);
    checkRemovedEntries(dict);
    // As the gas fields: a file with other dimensions is a wrong case
    // (U.solid is recomputed, not read, but a restart time holds it)
    caseChecks::checkDimensions(alphaSolid_, dimless);
    caseChecks::checkFieldFile(Usolid_, dimVelocity);
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
    apertures_.reset(new faceApertures(mesh));
    gasView_.reset(new gasView(mesh, dict));
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
    copyToFields();
}


void Foam::immersedBodyCoupling::copyToFields()
{
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


void Foam::immersedBodyCoupling::startStep
(
    const continuousView& solidView,
    const UList<vector2D>& nodePositions,
    const UList<vector2D>& nodeVelocities,
    const scalar dt
)
{
    const continuousView& view =
        gasView_->update(solidView, nodePositions, projection_);

    // Points of the view and their mean node velocities
    const labelList& pointOfNode = view.pointOfNode();
    const labelList& nNodes = view.nNodesOfPoint();
    nNodes_ = nodeVelocities.size();
    xStart_ = view.points();
    vPoint_.setSize(xStart_.size());
    vPoint_ = Zero;
    forAll(pointOfNode, n)
    {
        vPoint_[pointOfNode[n]] += nodeVelocities[n];
    }
    xEnd_.setSize(xStart_.size());
    forAll(vPoint_, p)
    {
        vPoint_[p] /= nNodes[p];
        xEnd_[p] = xStart_[p] + dt*vPoint_[p];
    }

    const List<triangleVertices>& tris = view.triangles();
    viewTriangles_ = &tris;

    // Wall pieces integrated over the step between the events of each
    // edge (see addWallPieces), so that in translation their sum in a
    // cell is the cell's wall vector W_i to round-off and a uniform
    // pressure puts on the nodes exactly the loads of the edges. The
    // cells the boundary crosses at the start and at the end are the
    // ones clipped by the projections
    clearWallPieces();
    setOutlineEdges(view);
    boundaryCell_.setSize(mesh_.nCells());
    addWallPieces(view);
    // The cells far from the outline take their region's state (one
    // centroid test per region instead of one per cell); at a write time
    // every cell is projected, so that the written U.solid holds the
    // velocity of every covered cell
    const bool byRegions = !mesh_.time().writeTime();
    markBoundaryCells(xStart_, byRegions ? &nearCell_ : nullptr);
    if (byRegions)
    {
        vector2D lo(GREAT, GREAT), hi(-GREAT, -GREAT);
        for (const vector2D& x : xStart_)
        {
            lo = min(lo, x);
            hi = max(hi, x);
        }
        regions_.update(nearCell_, lo, hi);
    }
    projection_.project
    (
        xStart_, tris, vPoint_, alphaWork_, UsolidWork_, overlapsStart_,
        &boundaryCell_, byRegions ? &regions_.cellState() : nullptr
    );
    if (byRegions)
    {
        regions_.fill(alphaWork_);
    }
    copyToFields();
    areaOf(alphaWork_, solidAreaStart_);
    faceApertures::cellStatesOf(boundaryCell_, alphaWork_, cellStateStart_);
    faceApertures::faceStatesFromCells
    (
        mesh_.faceOwner(), mesh_.faceNeighbour(), cellStateStart_,
        apertures_->activeFaces(), faceState_
    );

    // Apertures of every face over the linear motion from start to end
    apertures_->update(xStart_, xEnd_, tris, outlineEdges_, faceState_);

    markBoundaryCells(xEnd_);
    setCellStateEnd();
    projection_.project
    (
        xEnd_, tris, vPoint_, alphaEnd_, work2D_, overlapsEnd_,
        &boundaryCell_, &cellStateEnd_
    );
    areaOf(alphaEnd_, solidAreaEnd_);

    // A cell's wall force goes half to the solid at the start, half to
    // the solid at the end of the step (all to the one there is)
    // (the solid at the start of a cell its region decided has no
    // overlap to carry a force)
    overlapStart_.setSize(solidAreaStart_.size());
    overlapStart_ = false;
    for (const label c : overlapsStart_.cell)
    {
        overlapStart_[c] = true;
    }
    shareStart_.setSize(solidAreaStart_.size());
    forAll(shareStart_, i)
    {
        const bool s = overlapStart_[i], e = solidAreaEnd_[i] > 0;
        shareStart_[i] = s && e ? 0.5 : s ? 1 : 0;
    }

    // The two sides of a processor face (computed with the face reversed)
    // take the same aperture, so that both see the same flux and
    // neighbours
    // (a face of length 0, on an empty patch, keeps aperture 1)
    scalarField& faceAp = faceApertureWork_;
    if (faceAp.size() != mesh_.nFaces())
    {
        faceAp.setSize(mesh_.nFaces());
        faceAp = 1;
    }
    // What is left of a covered face by round-off (the covered pieces of
    // several triangles summed to a few ulp short of the face length) is
    // closed, as the gas fraction of a covered cell is (gasFraction).
    // The gas step decides on a_f > 0 (the redistribution's neighbours,
    // the reach of new cells, the empty-cell fill): a 3e-16 aperture of a
    // face covered all step linked a small cell to its neighbour in one
    // run and not in another whose nodes differed by round-off (2 ranks:
    // the nodal forces summed in another order), a jump of 2.6e-3 in the
    // small cell's density
    for (const label f : apertures_->activeFaces())
    {
        const scalar a = apertures_->aperture(f);
        faceAp[f] = a > roundOffFraction ? a : 0;
    }
    syncTools::syncFaceList(mesh_, faceAp, minEqOp<scalar>());
    scalarField& ai = aperture_.primitiveFieldRef();
    forAll(ai, f)
    {
        ai[f] = faceAp[f];
    }
    forAll(mesh_.boundary(), patchi)
    {
        fvsPatchScalarField& ap = aperture_.boundaryFieldRef()[patchi];
        const label start = mesh_.boundary()[patchi].patch().start();
        forAll(ap, j)
        {
            ap[j] = faceAp[start + j];
        }
    }
}


namespace
{
    // Gas fraction 1 - alpha into phi (sized once); what is left of a
    // covered cell by round-off (the sum of the overlaps against its area)
    // is no gas
    const Foam::scalarField& gasFraction
    (
        const Foam::scalarField& alpha,
        Foam::scalarField& phi
    )
    {
        phi.setSize(alpha.size());
        forAll(alpha, i)
        {
            const Foam::scalar f = 1 - alpha[i];
            phi[i] = f > roundOffFraction ? f : 0;
        }
        return phi;
    }
}


const Foam::scalarField&
Foam::immersedBodyCoupling::fluidFractionStart() const
{
    return gasFraction(alphaWork_, gasStart_);
}


const Foam::scalarField&
Foam::immersedBodyCoupling::fluidFractionEnd() const
{
    return gasFraction(alphaEnd_, gasEnd_);
}


void Foam::immersedBodyCoupling::clearWallPieces()
{
    pieceCell_.clear();
    pieceNodes_.clear();
    pieceMid_.clear();
    pieceArea_.clear();
    pieceAreaSum_.setSize(mesh_.nCells());
    pieceAreaSum_ = Zero;
    pieceLength_.setSize(mesh_.nCells());
    pieceLength_ = 0;
}


void Foam::immersedBodyCoupling::setOutlineEdges(const continuousView& view)
{
    // The view's boundary edges bound the union of its triangles only
    // while no triangle is inverted; a view folded where fragments of
    // closed cracks separate (crackVenting false) has inverted triangles,
    // and the edges of those bound the rest of the union
    outlineEdges_ = view.boundaryEdges();
    foldEdges_.clear();
    for (const triangleVertices& t : view.triangles())
    {
        if
        (
            polygonClipping::cross(xStart_[t[0]], xStart_[t[1]], xStart_[t[2]])
         <= 0
         || polygonClipping::cross(xEnd_[t[0]], xEnd_[t[1]], xEnd_[t[2]]) <= 0
        )
        {
            for (label k = 0; k < 3; ++k)
            {
                foldEdges_.append(edge(t[k], t[(k + 1) % 3]));
            }
        }
    }
    outlineEdges_.append(foldEdges_);
}


void Foam::immersedBodyCoupling::areaOf
(
    const scalarField& alpha,
    scalarField& area
) const
{
    // Into a list sized once (alpha*cellArea would be a new field per step)
    const scalarField& A = projection_.cellArea();
    area.setSize(alpha.size());
    forAll(area, i)
    {
        area[i] = alpha[i]*A[i];
    }
}


void Foam::immersedBodyCoupling::setCellStateEnd()
{
    // A cell the outline crosses neither at the start nor at the end is
    // all solid or all gas at both; a face of it that no outline edge
    // reaches in the step (faceApertures::reachedFaces) is covered all the
    // step or open all the step and lies in the cell's closure at both
    // ends: the cell's state at the end is its state at the start. (Faces
    // of length 0, on empty patches, tell nothing.) Such a face exists
    // where fewer of the cell's faces were reached than it has: counted
    // over the reached faces, not over every cell's faces
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    const labelList& reached = apertures_->reachedFaces();
    if (nActiveFaces_.size() != mesh_.nCells())
    {
        nActiveFaces_.setSize(mesh_.nCells());
        nActiveFaces_ = 0;
        nReachedFaces_.setSize(mesh_.nCells());
        nReachedFaces_ = 0;
        for (const label f : apertures_->activeFaces())
        {
            ++nActiveFaces_[own[f]];
            if (f < nei.size()) ++nActiveFaces_[nei[f]];
        }
    }
    for (const label f : reached)
    {
        ++nReachedFaces_[own[f]];
        if (f < nei.size()) ++nReachedFaces_[nei[f]];
    }
    cellStateEnd_.setSize(mesh_.nCells());
    forAll(cellStateEnd_, c)
    {
        cellStateEnd_[c] =
            !boundaryCell_[c] && nReachedFaces_[c] < nActiveFaces_[c]
          ? cellStateStart_[c] : -1;
    }
    for (const label f : reached)
    {
        nReachedFaces_[own[f]] = 0;
        if (f < nei.size()) nReachedFaces_[nei[f]] = 0;
    }
}


void Foam::immersedBodyCoupling::markBoundaryCells
(
    const UList<vector2D>& x,
    boolList* near
)
{
    // The cells whose widened boxes an edge reaches (near) are the ones
    // clipped against it (a cheap rejection of most candidates)
    boundaryCell_ = false;
    if (near)
    {
        near->setSize(boundaryCell_.size());
        *near = false;
    }
    for (const edge& e : outlineEdges_)
    {
        const vector2D& a = x[e.start()];
        const vector2D& b = x[e.end()];
        projection_.forEachCellNear
        (
            a, b, regions_.tol(),
            [&](const label celli)
            {
                if (near) (*near)[celli] = true;
                scalar s0, s1;
                if (projection_.clipSegment(celli, a, b, s0, s1))
                {
                    boundaryCell_[celli] = true;
                }
            }
        );
    }
}


void Foam::immersedBodyCoupling::addWallPieces(const continuousView& view)
{
    // The force of a cell acts on the wall pieces in it, weighted as the
    // cell's wall vector W_i = -sum_f a_f S_f averages the wall over the
    // step. The pieces' sum must be W_i: the force p_i w of the pieces
    // then balances the wall impulse for a uniform pressure, and only a
    // true pressure difference goes through the remainder
    // I_i/dt - p_i sum w (spread by length). With the pieces at the start
    // and the end of the step, half each, the sum missed W_i wherever a
    // wall vertex crossed a face line within the step (the time the wall
    // spends in each of the two cells is not a half): the remainder,
    // a fraction of p_i times the wall's length in the cell, went along
    // every piece of the cell (the sliding top and bottom of the barrel's
    // projectile), a nodal pattern that made a translating elastic body
    // ring in proportion to p (barrel at 20 MPa: max |p/p0 - 1| 1.4e-6,
    // 0.1 J/m damped). So each edge is clipped at sample times of its own events: its
    // ends crossing a cell face (the cells along their paths) and a cell
    // vertex crossing its line (a quadratic in t). Between events a
    // piece's end parameters are linear in t in translation, so its area
    // vector is linear and its nodal moment quadratic: 2-point Gauss per
    // interval is exact (rotation, deformation: the remainder takes what
    // the quadrature misses). Away from events: 2 samples, as before
    const edgeList& edges = view.boundaryEdges();
    const labelList& edgeTriangle = view.boundaryEdgeTriangle();
    const labelList& edgeLocal = view.boundaryEdgeLocalEdge();
    static const scalar g = 0.5/Foam::sqrt(3.0);
    // An edge along a cell face (the projectile's top and bottom on the
    // barrel's walls) within 1e-5 of the face length, as for the face
    // apertures, lies in the cell: a node that round-off put just
    // outside dropped the edge's pieces from the cell, whose remainder
    // (p_i times the missing area vector) went to its other pieces
    static const scalar onLineTol = 1e-5;
    DynamicList<scalar>& events = events_;
    forAll(edges, e)
    {
        const label i0 = edges[e].start(), i1 = edges[e].end();
        const vector2D& a0 = xStart_[i0];
        const vector2D& b0 = xStart_[i1];
        const vector2D& a1 = xEnd_[i0];
        const vector2D& b1 = xEnd_[i1];
        const label t = edgeTriangle[e], k = edgeLocal[e];
        const label na = 3*t + k, nb = 3*t + (k + 1) % 3;

        events.clear();
        events.append(0);
        events.append(1);
        // The ends crossing cell faces: the parameters of their paths'
        // pieces are the times
        for (const vector2D* ab : {&a0, &b0})
        {
            const vector2D& x0 = *ab;
            const vector2D& x1 = ab == &a0 ? a1 : b1;
            if (x0 == x1) continue;
            projection_.forEachSegmentPiece
            (
                x0, x1,
                [&](const label, const scalar s0, const scalar s1)
                {
                    events.append(s0);
                    events.append(s1);
                }
            );
        }
        // A cell vertex v on the edge's line: cross(d(t), v - a(t))
        // = 0 with d = b - a, a quadratic A t^2 + B t + C
        const vector2D da = a1 - a0, d0 = b0 - a0;
        const vector2D dd = (b1 - b0) - da;
        const auto cross = [](const vector2D& u, const vector2D& w)
        {
            return u.x()*w.y() - u.y()*w.x();
        };
        const scalar A = -cross(dd, da);
        const vector2D lo = min(min(a0, b0), min(a1, b1));
        const vector2D hi = max(max(a0, b0), max(a1, b1));
        if (mag(da) > 0 || mag(dd) > 0)
        {
            projection_.forEachVertexIn
            (
                lo, hi,
                [&](const vector2D& v)
                {
                    const vector2D r0 = v - a0;
                    const scalar C = cross(d0, r0);
                    const scalar B = cross(dd, r0) - cross(d0, da);
                    scalar roots[2];
                    label nRoots = 0;
                    const scalar size =
                        mag(B) + mag(C) + VSMALL;
                    if (mag(A) <= 1e-12*size)
                    {
                        if (mag(B) > 1e-12*(mag(C) + VSMALL))
                        {
                            roots[nRoots++] = -C/B;
                        }
                    }
                    else
                    {
                        const scalar disc = B*B - 4*A*C;
                        if (disc >= 0)
                        {
                            const scalar q =
                                -0.5*(B + (B < 0 ? -1 : 1)*Foam::sqrt(disc));
                            roots[nRoots++] = q/A;
                            if (mag(q) > 0) roots[nRoots++] = C/q;
                        }
                    }
                    for (label j = 0; j < nRoots; ++j)
                    {
                        const scalar tj = roots[j];
                        if (tj <= 0 || tj >= 1) continue;
                        // Only where v meets the segment itself
                        const vector2D at = a0 + tj*da;
                        const vector2D dj = d0 + tj*dd;
                        const scalar s = ((v - at) & dj)/(dj & dj);
                        if (s >= -1e-9 && s <= 1 + 1e-9)
                        {
                            events.append(tj);
                        }
                    }
                }
            );
        }
        // (std::sort: no work buffer per edge, as Foam::sort's stable
        // sort would take)
        std::sort(events.begin(), events.end());

        // Samples: 2-point Gauss in every interval
        const auto addSample = [&](const scalar ts, const scalar weight)
        {
            const vector2D a = a0 + ts*(a1 - a0);
            const vector2D b = b0 + ts*(b1 - b0);
            const vector2D d = b - a;
            // The fragment is on the left: outward normal (dy, -dx); the
            // pressure pushes along the inward one
            const vector2D inward(-weight*d.y(), weight*d.x());
            const scalar L = weight*mag(d);
            projection_.forEachSegmentPiece
            (
                a, b,
                [&](const label celli, const scalar s0, const scalar s1)
                {
                    pieceCell_.append(celli);
                    pieceNodes_.append(FixedList<label, 2>({na, nb}));
                    pieceMid_.append(0.5*(s0 + s1));
                    pieceArea_.append((s1 - s0)*inward);
                    pieceAreaSum_[celli] += (s1 - s0)*inward;
                    pieceLength_[celli] += (s1 - s0)*L;
                },
                onLineTol
            );
        };
        scalar tPrev = 0;
        for (const scalar te : events)
        {
            const scalar h = min(te, 1) - tPrev;
            if (h > 1e-12)
            {
                addSample(tPrev + (0.5 - g)*h, 0.5*h);
                addSample(tPrev + (0.5 + g)*h, 0.5*h);
                tPrev += h;
            }
        }
        if (tPrev < 1)
        {
            // What the rounding of the events left (below 1e-12)
            const scalar h = 1 - tPrev;
            addSample(tPrev + 0.5*h, h);
        }
    }
}


template<class Visitor>
void Foam::immersedBodyCoupling::forEachWallForce(const Visitor& visit) const
{
    forAll(pieceCell_, k)
    {
        const label c = pieceCell_[k];
        const scalar len = mag(pieceArea_[k]);
        const vector2D f =
            wallPressure_[c]*pieceArea_[k]
          + (len/pieceLength_[c])
           *(wallForce_[c] - wallPressure_[c]*pieceAreaSum_[c]);
        visit(c, pieceNodes_[k][0], (1 - pieceMid_[k])*f);
        visit(c, pieceNodes_[k][1], pieceMid_[k]*f);
    }
    // Cells with a wall force but no piece (the wall is in them only in
    // part of the step): over the solid in them (vertex k of triangle t
    // of the view is discontinuous node 3t + k). The cells the solid
    // covers with no gas (most overlaps) have no wall force: skipped
    // before their weights are computed
    auto forceWithoutPiece = [&](const label c)
    {
        return pieceLength_[c] <= 0 && wallForce_[c] != vector2D::zero;
    };
    solidProjection::forEachPointWeight
    (
        overlapsStart_, solidAreaStart_, xStart_, *viewTriangles_,
        forceWithoutPiece,
        [&](const label c, const label t, const label k, const scalar w)
        {
            visit(c, 3*t + k, (w*shareStart_[c])*wallForce_[c]);
        }
    );
    solidProjection::forEachPointWeight
    (
        overlapsEnd_, solidAreaEnd_, xEnd_, *viewTriangles_,
        forceWithoutPiece,
        [&](const label c, const label t, const label k, const scalar w)
        {
            visit(c, 3*t + k, (w*(1 - shareStart_[c]))*wallForce_[c]);
        }
    );
}


void Foam::immersedBodyCoupling::wallForces
(
    const vectorField& wallImpulse,
    const scalarField& wallPressureImpulse,
    const scalar dt,
    List<vector2D>& nodeForces
)
{
    const scalar scale = 1/(dt*depth_);
    wallForce_.setSize(wallImpulse.size());
    wallPressure_.setSize(wallImpulse.size());
    forAll(wallForce_, i)
    {
        wallForce_[i] =
            vector2D(scale*wallImpulse[i].x(), scale*wallImpulse[i].y());
        wallPressure_[i] = wallPressureImpulse[i]/dt;
    }
    nodeForces.setSize(nNodes_);
    nodeForces = Zero;
    if (!Pstream::parRun())
    {
        forEachWallForce
        (
            [&](const label, const label n, const vector2D& f)
            {
                nodeForces[n] += f;
            }
        );
        return;
    }

    // The same solid on every rank: each rank's cells push a few nodes
    // (their walls), whose forces every rank adds in rank order (the
    // message O(the nodes at this rank's walls), not O(the solid))
    pushed_.setSize(nNodes_, false);
    pushedNodes_.clear();
    forEachWallForce
    (
        [&](const label, const label n, const vector2D& f)
        {
            if (!pushed_[n])
            {
                pushed_[n] = true;
                pushedNodes_.append(n);
            }
            nodeForces[n] += f;
        }
    );
    const label me = Pstream::myProcNo();
    List<scalarList> all(Pstream::nProcs());
    scalarList& mine = all[me];
    mine.setSize(3*pushedNodes_.size());
    forAll(pushedNodes_, k)
    {
        const label n = pushedNodes_[k];
        // (a node number is exact in a double)
        mine[3*k] = n;
        mine[3*k + 1] = nodeForces[n].x();
        mine[3*k + 2] = nodeForces[n].y();
        pushed_[n] = false;
        nodeForces[n] = Zero;
    }
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    for (const scalarList& from : all)
    {
        for (label k = 0; 3*k < from.size(); ++k)
        {
            vector2D& F = nodeForces[label(from[3*k])];
            F.x() += from[3*k + 1];
            F.y() += from[3*k + 2];
        }
    }
}


void Foam::immersedBodyCoupling::wallWork
(
    const UList<vector2D>& workDisplacement,
    scalarField& cellWork
) const
{
    // The same nodal shares as wallForces times the displacements
    cellWork.setSize(wallForce_.size());
    cellWork = 0;
    forEachWallForce
    (
        [&](const label c, const label n, const vector2D& f)
        {
            cellWork[c] += f & workDisplacement[n];
        }
    );
    cellWork *= depth_;
}


// ************************************************************************* //
