// Gas damping across regimes: a beam moving normally above a substrate, 2D cross
// section, half domain with the beam's symmetry plane at x = 0. Beam 45 um wide (half width
// b = 22.5 um) and 1.5 um thick (the cantilever switch's beam), gap g = 7 um (so that
// Kn = lambda / g reaches 0.009 at 1e5 Pa in argon at 273.15 K); the open sides (pressure
// boundaries) 3 g from the beam: domain (b + 3 g) x (g + t + 3 g) = 43.5 um x 29.5 um.
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
// Structured quads in 8 transfinite blocks (the squeeze-film case's layout). At refine 1:
// 15 + 10 cells along x (1.5 um under the beam, 2.1 um outside), 8 across the gap (0.875 um;
// gap_refine multiplies these only: the numerical viscosity of first-order upwinding acts
// across the film, mu_num / mu ~ h_y / (2 lambda)), 2 across the beam, 8 above it: 420 cells.
//   gmsh -setnumber refine 1 -setnumber gap_refine 2 -2 damping_regimes.geo -o out.msh
DefineConstant[ refine = {1, Name "Parameters/refinement factor"} ];
DefineConstant[ gap_refine = {1, Name "Parameters/extra refinement across the gap"} ];
um = 1e-6;
b = 22.5 * um;   // half width of the beam
g = 7 * um;      // gap
t = 1.5 * um;    // beam thickness
X = b + 3 * g;   // the open sides 3 gaps from the beam's edge
Y = g + t + 3 * g;
nx1 = Round(15 * refine); nx2 = Round(10 * refine);
ny1 = Round(8 * refine * gap_refine); ny2 = Round(2 * refine); ny3 = Round(8 * refine);

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
