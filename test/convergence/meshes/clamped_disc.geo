// A disc of radius a = 1 m, meshed as an O-grid of quadrilaterals: a central square of half-side
// 0.4 m (n x n cells) and four curved blocks between its sides and the rim (n cells along, n/2
// across). With n even the centre is a mesh node shared by four cells. n is set from the
// command line:  gmsh -setnumber n 16 -2 -format msh41 clamped_disc.geo -o out.msh
// Doubling n halves every cell.

DefineConstant[ n = {16, Name "Parameters/Cells along a side of the central square"} ];
a = 1.0;
b = 0.4;
c = a / Sqrt(2);

Point(1) = {0, 0, 0};
Point(2) = {b, b, 0};
Point(3) = {-b, b, 0};
Point(4) = {-b, -b, 0};
Point(5) = {b, -b, 0};
Point(6) = {c, c, 0};
Point(7) = {-c, c, 0};
Point(8) = {-c, -c, 0};
Point(9) = {c, -c, 0};

Line(1) = {2, 3};
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 2};
Circle(5) = {6, 1, 7};
Circle(6) = {7, 1, 8};
Circle(7) = {8, 1, 9};
Circle(8) = {9, 1, 6};
Line(9) = {2, 6};
Line(10) = {3, 7};
Line(11) = {4, 8};
Line(12) = {5, 9};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 5, -10, -1};
Plane Surface(2) = {2};
Curve Loop(3) = {10, 6, -11, -2};
Plane Surface(3) = {3};
Curve Loop(4) = {11, 7, -12, -3};
Plane Surface(4) = {4};
Curve Loop(5) = {12, 8, -9, -4};
Plane Surface(5) = {5};

Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8} = n + 1;
Transfinite Curve{9, 10, 11, 12} = n / 2 + 1;
Transfinite Surface{1, 2, 3, 4, 5};
Recombine Surface{1, 2, 3, 4, 5};

Physical Curve("rim") = {5, 6, 7, 8};
Physical Surface("plate") = {1, 2, 3, 4, 5};
