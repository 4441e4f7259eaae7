// Frogleg RF MEMS varactor (thesis sec. 4.6.2, Table 4.3; Hsu, Koslowski and Peroulis): the
// mid-surface of the nickel top plate and its four legs, for the plate creep model.
// Lengths in micrometres here, written in metres (Mesh.ScalingFactor). Origin at the plate
// centre; x along the plate's length lp, y along its width wp.
//
// One quarter, x > 0 and y > 0 (um; the other three are its mirror images in x = 0, y = 0):
//
//   y = 110  -------------+-------+-----+
//                         | thigh |knee |
//   y =  90               +-------+     |
//              plate      |  gap  |shin |
//                         |       |     |
//   y =  40               |       |     +--------+
//                         |       |     |  foot  |  <- anchor (x = 220, clamped)
//   y =  20               |       +-----+--------+
//   y =   0  .............|
//                     x = 150    170   190      220
//
//   plate   [0, 150] x [0, 110]                       (lp / 2, wp / 2)
//   thigh   [150, 190] x [90, 110]   l1 = 40 along x from the plate's short edge, flush with
//                                    its long edge, wb = 20 wide (the knee square included)
//   shin    [170, 190] x [20, 110]   l2 = 90 along -y (folded back along the short edge)
//   foot    [190, 220] x [20, 40]    l3 = 30 along x; its end x = 220 is the anchor (clamped)
// The table's l1, l2, l3 are read as the outer lengths of the three segments; the extracted
// thesis lost the figure (4.6) that showed them, so this reading is ours (case.yaml).
//
// The plate is cut at x = +-60 and +-110: the edges of the electrodes under it (sensing
// electrode ws = 120 at the centre, actuation electrodes wa = 40 at the ends), so that no cell
// straddles an electrode edge (the parallel-plate areas are then exact).
//
// Mesh: structured quadrilaterals of side h on every rectangle (every length is a multiple of
// 10 um, so h = 10, 5, 2.5 ... fit exactly): h = 10 um gives 772 cells, h = 5 um 3088 (the
// thesis: 3226), h = 2.5 um 12352 (thesis: 12904). From the command line:
//   gmsh -setnumber h 5 -2 -format msh41 frogleg_varactor.geo -o frogleg.msh
// Patches: "anchor" (the four foot ends, clamped) and "edge" (every other edge, free).

DefineConstant[ h = {5, Name "Parameters/Cell size h [um]"} ];
DefineConstant[ hl = {h, Name "Parameters/Cell size along the legs [um]"} ];
DefineConstant[ nb = {0, Name "Parameters/Cells across a leg (0: wb / h)"} ];
DefineConstant[ bump = {1, Name "Parameters/Bump across a leg (1: uniform)"} ];
SetFactory("OpenCASCADE");

lp = 300; wp = 220;   // plate
wb = 20;              // leg width
l1 = 40; l2 = 90; l3 = 30;
wa = 40; ws = 120;    // actuation, sensing electrode widths (along x)

// The plate as five strips: actuation | space | sensing | space | actuation.
cuts[] = {-lp/2, -lp/2 + wa, -ws/2, ws/2, lp/2 - wa, lp/2};
// Each strip in three rows: the bands y in +-[90, 110] that the thighs continue.
rows[] = {-wp/2, -wp/2 + wb, wp/2 - wb, wp/2};
For i In {0:4}
  For j In {0:2}
    Rectangle(newv) = {cuts[i], rows[j], 0, cuts[i+1] - cuts[i], rows[j+1] - rows[j]};
  EndFor
EndFor
// The legs, quadrant by quadrant (sx, sy: the mirror signs).
For sx In {-1:1:2}
  For sy In {-1:1:2}
    x0 = sx * lp/2;                      // the plate's short edge
    // thigh: from the corner, along +-x
    Rectangle(newv) = {(sx > 0 ? x0 : x0 - l1), (sy > 0 ? wp/2 - wb : -wp/2), 0, l1, wb};
    // shin: at the thigh's far end, back along the short edge towards y = 0
    xs = sx > 0 ? x0 + l1 - wb : x0 - l1;
    // (in two: the ankle square where the foot leaves, so that its sides match the foot's)
    Rectangle(newv) = {xs, (sy > 0 ? wp/2 - l2 + wb : -wp/2), 0, wb, l2 - wb};
    Rectangle(newv) = {xs, (sy > 0 ? wp/2 - l2 : -wp/2 + l2 - wb), 0, wb, wb};
    // foot: from the shin's inner end, along +-x to the anchor
    Rectangle(newv) = {(sx > 0 ? x0 + l1 : x0 - l1 - l3), (sy > 0 ? wp/2 - l2 : -wp/2 + l2 - wb),
                       0, l3, wb};
  EndFor
EndFor
BooleanFragments{ Surface{:}; Delete; }{}

// Structured quads: every curve (axis-parallel) gets length / h cells, every rectangle is a
// transfinite surface on its four corners (opposite sides then have equal node counts).
e = 1e-3;
nacross = nb > 0 ? nb : Floor(wb / h + 0.5);
curves[] = Curve{:};
For i In {0:#curves[]-1}
  bb[] = BoundingBox Curve{curves[i]};
  horizontal = (bb[3] - bb[0]) > (bb[4] - bb[1]);
  len = horizontal ? (bb[3] - bb[0]) : (bb[4] - bb[1]);
  xfar = Fabs(bb[0]) > Fabs(bb[3]) ? Fabs(bb[0]) : Fabs(bb[3]);
  leg = xfar > lp/2 + e;                                 // beyond the plate's short edges
  thigh = horizontal && Fabs(Fabs(bb[0] + bb[3]) / 2 - (lp/2 + (l1 - wb)/2)) < e;  // along x
  If (Fabs(len - wb) < e && !thigh)                      // across a leg (or a thigh's band)
    Transfinite Curve{curves[i]} = nacross + 1 Using Bump bump;
  ElseIf (leg)
    Transfinite Curve{curves[i]} = Floor(len / hl + 0.5) + 1;
  Else
    Transfinite Curve{curves[i]} = Floor(len / h + 0.5) + 1;
  EndIf
EndFor
surfaces[] = Surface{:};
For i In {0:#surfaces[]-1}
  bb[] = BoundingBox Surface{surfaces[i]};
  p1[] = Point In BoundingBox{bb[0] - e, bb[1] - e, -e, bb[0] + e, bb[1] + e, e};
  p2[] = Point In BoundingBox{bb[3] - e, bb[1] - e, -e, bb[3] + e, bb[1] + e, e};
  p3[] = Point In BoundingBox{bb[3] - e, bb[4] - e, -e, bb[3] + e, bb[4] + e, e};
  p4[] = Point In BoundingBox{bb[0] - e, bb[4] - e, -e, bb[0] + e, bb[4] + e, e};
  Transfinite Surface{surfaces[i]} = {p1[0], p2[0], p3[0], p4[0]};
  Recombine Surface{surfaces[i]};
EndFor

outer[] = CombinedBoundary{ Surface{:}; };
xa = lp/2 + l1 + l3;   // the anchors' x
anchors[] = Curve In BoundingBox{xa - e, -wp, -e, xa + e, wp, e};
anchors[] += Curve In BoundingBox{-xa - e, -wp, -e, -xa + e, wp, e};
edges[] = outer[];
edges[] -= anchors[];
Physical Curve("anchor") = {anchors[]};
Physical Curve("edge") = {edges[]};
Physical Surface("varactor") = {Surface{:}};

Mesh.ScalingFactor = 1e-6;   // um -> m
Mesh.ElementOrder = 1;
