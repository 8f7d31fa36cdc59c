// Rock block with a borehole and a steel inclusion: two materials, named
// boundaries. Mesh headless: gmsh -2 -format msh22 (or msh41) -o out.msh
SetFactory("Built-in");
h = 0.04;
Point(1) = {0, 0, 0, h};
Point(2) = {1, 0, 0, h};
Point(3) = {1, 0.5, 0, h};
Point(4) = {0, 0.5, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};

// Borehole at (0.3, 0.25), radius 0.03
Point(5) = {0.3, 0.25, 0, h/4};
Point(6) = {0.33, 0.25, 0, h/4};
Point(7) = {0.3, 0.28, 0, h/4};
Point(8) = {0.27, 0.25, 0, h/4};
Point(9) = {0.3, 0.22, 0, h/4};
Circle(5) = {6, 5, 7};
Circle(6) = {7, 5, 8};
Circle(7) = {8, 5, 9};
Circle(8) = {9, 5, 6};

// Steel inclusion: square [0.6, 0.8] x [0.15, 0.35]
Point(10) = {0.6, 0.15, 0, h/2};
Point(11) = {0.8, 0.15, 0, h/2};
Point(12) = {0.8, 0.35, 0, h/2};
Point(13) = {0.6, 0.35, 0, h/2};
Line(9) = {10, 11};
Line(10) = {11, 12};
Line(11) = {12, 13};
Line(12) = {13, 10};

Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(1) = {1, 2, 3};
Plane Surface(2) = {3};

Physical Surface("granite") = {1};
Physical Surface("steel") = {2};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("borehole") = {5, 6, 7, 8};
Physical Curve("interface") = {9, 10, 11, 12};   // inside: dropped
