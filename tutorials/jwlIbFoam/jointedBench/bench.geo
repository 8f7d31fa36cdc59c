// jointedBench: the bench of tutorials/jwlIbFoam/benchBlast (plan view,
// sandstone block x in [-0.3, 0.3], y in [-0.4, 0], free face y = 0,
// borehole r = 15 mm at (0, -0.15)) cut by joint traces, meshed headless by
// Allrun (gmsh -2 bench.geo) and read by gmshToFemdem: the physical
// surface is the material, the physical curves on the boundary the patches,
// and the physical curve "joints" (traces embedded in the surface by
// BooleanFragments) the joint set of system/gmshToFemdemDict.
// Keep the geometry in step with system/femdemMeshDict (plot.py reads it).
SetFactory("OpenCASCADE");
h = 0.012;              // element size (benchBlast's targetSize)
hHole = 0.004;          // at the borehole wall (24 sides, as benchBlast)
Rectangle(1) = {-0.3, -0.4, 0, 0.6, 0.4};
Disk(2) = {0, -0.15, 0, 0.015};
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };

// Joint set: parallel traces dipping 60 degrees from the free face,
// 0.1 m apart, the nearest 0.05 m either side of the hole; and one trace
// along the face at y = -0.3 ending inside the rock (it crosses the set)
dip = 60*Pi/180;
spacing = 0.1;
traces[] = {};
For i In {-3:3}
  cx = (i + 0.5)*spacing*Sin(dip);
  cy = -0.15 - (i + 0.5)*spacing*Cos(dip);
  p1 = newp; Point(p1) = {cx - 0.6*Cos(dip), cy - 0.6*Sin(dip), 0};
  p2 = newp; Point(p2) = {cx + 0.6*Cos(dip), cy + 0.6*Sin(dip), 0};
  l = newl; Line(l) = {p1, p2};
  traces[] += l;
EndFor
p1 = newp; Point(p1) = {-0.25, -0.3, 0};
p2 = newp; Point(p2) = {0.1, -0.3, 0};
l = newl; Line(l) = {p1, p2};
traces[] += l;
// Split the traces at the outline and at each other, embed them in the
// rock (the pieces outside it stay free curves, in no physical group)
BooleanFragments{ Surface{3}; Delete; }{ Curve{traces[]}; Delete; }

// Physical groups by position (BooleanFragments renumbers the entities)
e = 1e-6;
back[] = Curve In BoundingBox{-0.3 - e, -0.4 - e, -e, 0.3 + e, -0.4 + e, e};
front[] = Curve In BoundingBox{-0.3 - e, -e, -e, 0.3 + e, e, e};
left[] = Curve In BoundingBox{-0.3 - e, -0.4 - e, -e, -0.3 + e, e, e};
right[] = Curve In BoundingBox{0.3 - e, -0.4 - e, -e, 0.3 + e, e, e};
hole[] = Curve In BoundingBox{-0.015 - e, -0.165 - e, -e, 0.015 + e, -0.135 + e, e};
joints[] = Curve In BoundingBox{-0.3 - e, -0.4 - e, -e, 0.3 + e, e, e};
joints[] -= {back[], front[], left[], right[], hole[]};
rock[] = Surface In BoundingBox{-0.3 - e, -0.4 - e, -e, 0.3 + e, e, e};
Physical Surface("sandstone") = {rock[]};
Physical Curve("back") = {back[]};
Physical Curve("freeFace") = {front[]};
Physical Curve("side") = {left[], right[]};
Physical Curve("borehole") = {hole[]};
Physical Curve("joints") = {joints[]};

// Size: hHole within 10 mm of the hole wall, growing by 0.25 per metre
// of distance to h (benchBlast's refinement)
Field[1] = Distance;
Field[1].CurvesList = {hole[]};
Field[1].NumPointsPerCurve = 100;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hHole;
Field[2].SizeMax = h;
Field[2].DistMin = 0.01;
Field[2].DistMax = 0.01 + (h - hHole)/0.25;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;     // Frontal-Delaunay
