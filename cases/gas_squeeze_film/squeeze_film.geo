// Squeeze-film damping of a beam over a substrate (thesis sec. 5.5.3): half domain, the beam's
// symmetry plane at x = 0. Beam 18 um wide (half width 9 um), 2.25 um thick, 1.4 um above the
// substrate; domain 27 um x 12 um.
//
//   y = Y  +---------------- top (pressure) ----------------+
//          |                                                |
// symmetry |                                                | right (pressure)
//   y=g+t  +--- beam top ---+                               |
//          |     beam       | beam side                     |
//   y = g  +--- beam bottom +                               |
// symmetry |    gap                                         |
//   y = 0  +---------------- substrate ---------------------+
//          x=0             x=b                            x=X
//
// Structured quads in 8 transfinite blocks (the 3 x 3 block grid without the beam). Cell
// counts per block edge scale with `refine` (1: 50 x 50 cells across, as the thesis's coarse
// mesh):  gmsh -setnumber refine 2 -2 squeeze_film.geo -o out.msh
DefineConstant[ refine = {1, Name "Parameters/refinement factor"} ];
um = 1e-6;
b = 9 * um;      // half width of the beam
g = 1.4 * um;    // gap
t = 2.25 * um;   // beam thickness
X = 27 * um;
Y = 12 * um;
nx1 = Round(20 * refine); nx2 = Round(30 * refine);
ny1 = Round(10 * refine); ny2 = Round(10 * refine); ny3 = Round(30 * refine);

xs[] = {0, b, X};
ys[] = {0, g, g + t, Y};
For j In {0:3}
  For i In {0:2}
    Point(1 + i + 3 * j) = {xs[i], ys[j], 0};
  EndFor
EndFor
// Horizontal lines: h(i, j) from point (i, j) to (i+1, j); vertical v(i, j) from (i, j) to (i, j+1).
For j In {0:3}
  For i In {0:1}
    Line(100 + i + 2 * j) = {1 + i + 3 * j, 2 + i + 3 * j};
  EndFor
EndFor
For j In {0:2}
  For i In {0:2}
    Line(200 + i + 3 * j) = {1 + i + 3 * j, 4 + i + 3 * j};
  EndFor
EndFor
nx[] = {nx1, nx2};
ny[] = {ny1, ny2, ny3};
For j In {0:3}
  For i In {0:1}
    Transfinite Curve{100 + i + 2 * j} = nx[i] + 1;
  EndFor
EndFor
For j In {0:2}
  For i In {0:2}
    Transfinite Curve{200 + i + 3 * j} = ny[j] + 1;
  EndFor
EndFor
// Blocks (i, j), all but the beam (0, 1).
s = 0;
For j In {0:2}
  For i In {0:1}
    If (!(i == 0 && j == 1))
      Curve Loop(300 + i + 2 * j) = {100 + i + 2 * j, 201 + i + 3 * j, -(100 + i + 2 * (j + 1)), -(200 + i + 3 * j)};
      Plane Surface(300 + i + 2 * j) = {300 + i + 2 * j};
      Transfinite Surface{300 + i + 2 * j};
      Recombine Surface{300 + i + 2 * j};
      blocks[s] = 300 + i + 2 * j; s += 1;
    EndIf
  EndFor
EndFor

Physical Curve("substrate") = {100, 101};
Physical Curve("top") = {106, 107};
Physical Curve("right") = {202, 205, 208};
Physical Curve("symmetry") = {200, 206};
Physical Curve("beam") = {102, 204, 104};
Physical Surface("gas") = {blocks[]};
