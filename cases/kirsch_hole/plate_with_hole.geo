// Quarter model of a square plate with a circular hole (Kirsch problem; thesis Fig. 2.9).
// Origin at the hole centre; hole radius a = 0.5 m; quarter square of side 2 m.
//
//   D (0,2) ------------- C (2,2)
//   |          top            |
//   symmetry_x (x = 0)      right (x = 2)
//   E (0,0.5)                 |
//     \ hole                  |
//      A (0.5,0) ----------- B (2,0)
//          symmetry_y (y = 0)
//
// Mesh: unstructured triangles (Frontal-Delaunay). The characteristic length h is set from
// the command line:  gmsh -setnumber h 0.1 -2 -format msh41 plate_with_hole.geo -o out.msh
// Every size is proportional to h, so halving h refines the whole plate by a factor 2.
// The hole gets h/3: the stress concentration sits there, and the chords must follow the arc
// closely (8+ segments on the quarter circle even at h = 0.2).

DefineConstant[ h = {0.2, Name "Parameters/Characteristic length h [m]"} ];
a = 0.5;       // hole radius
L = 2.0;       // side of the quarter square
h_hole = h / 3;

Point(1) = {0, 0, 0, h};         // O: hole centre (arc centre only, not meshed)
Point(2) = {a, 0, 0, h_hole};    // A
Point(3) = {L, 0, 0, h};         // B
Point(4) = {L, L, 0, h};         // C
Point(5) = {0, L, 0, h};         // D
Point(6) = {0, a, 0, h_hole};    // E

Line(1) = {2, 3};                // AB, y = 0
Line(2) = {3, 4};                // BC, x = L
Line(3) = {4, 5};                // CD, y = L
Line(4) = {5, 6};                // DE, x = 0
Circle(5) = {6, 1, 2};           // EA, the hole

Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Physical Curve("hole") = {5};
Physical Curve("symmetry_y") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("symmetry_x") = {4};
Physical Surface("plate") = {1};

Mesh.Algorithm = 6;                          // Frontal-Delaunay
Mesh.MeshSizeFromCurvature = 0;              // sizes come from h only
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.ElementOrder = 1;
