// NACA 4-digit aerofoil in a rectangular far-field box (default NACA-7526, the
// aerofoil of thesis Sections 4.3 and 4.4.2: camber 7 % at 50 % chord, thickness 26 %).
//
// Aerofoil (Abbott & von Doenhoff, "Theory of Wing Sections", 1959), x in [0, 1]:
//   yt = 5 t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 - 0.1036 x^4)
//        (-0.1036 instead of -0.1015 closes the trailing edge: yt(1) = 0, a sharp TE);
//   yc = m/p^2 (2 p x - x^2)                     for x <  p,
//   yc = m/(1-p)^2 (1 - 2 p + 2 p x - x^2)       for x >= p;
//   theta = atan(dyc/dx); the thickness is laid perpendicular to the camber line:
//   upper (x - yt sin theta, yc + yt cos theta), lower (x + yt sin theta, yc - yt cos theta).
// Sampling: cosine spacing x = (1 - cos beta)/2, beta = i pi/N, i = 0..N, N = NPoints - 1.
//
// Geometry: two cubic B-splines, upper and lower, each from the leading edge (LE) to the
// trailing edge (TE), sharing both end vertices. Each interpolates its N + 1 samples at the
// uniform knots u = i of Gmsh's default clamped knot vector (u = beta / (pi/N)); the control
// points come from the tridiagonal interpolation system solved below. In beta the contour is
// analytic through the LE (sqrt(x) = sin(beta/2)), and both splines get the exact LE
// derivative dQ/du = (pi/N) (5 t 0.2969 / 2) (-s sin theta0, s cos theta0), s = +1 upper,
// -1 lower, so the contour is C1 at the LE vertex. At the TE the splines use the natural end
// condition (zero second derivative) and meet at an angle: a sharp TE corner.
// A single closed spline is not used: Gmsh makes any closed spline periodic, which rounds the TE.
//
// Angle of attack AoA (degrees, nose up) rotates the aerofoil clockwise about the quarter-chord
// point (Chord/4, 0). Box [BoxXMin, BoxXMax] x [-BoxYMax, BoxYMax] in chords; the default
// 5 x 5 chords square matches the "square domain" of thesis Section 4.4.2.
//
// Mesh size: LcAerofoil on the aerofoil growing linearly to LcFarfield at distance
// GrowthDistance (chords), LcTrailingEdge at the TE growing to LcAerofoil within 0.1 chord, and
// NCurvature elements per 2 pi of curvature radius along the aerofoil (refines the LE).
//
// Physical groups: Curve "aerofoil", Curve "farfield", Surface "fluid".

SetFactory("OpenCASCADE");

DefineConstant[
  M = {7, Min 0, Max 9, Step 1, Name "NACA/M", Label "Max camber M (percent chord)"},
  P = {5, Min 1, Max 9, Step 1, Name "NACA/P", Label "Max camber position P (tenths of chord)"},
  T = {26, Min 1, Max 40, Step 1, Name "NACA/T", Label "Thickness T (percent chord)"},
  Chord = {1, Min 0.01, Max 100, Name "NACA/Chord", Label "Chord length"},
  NPoints = {61, Min 4, Max 1000, Step 1, Name "NACA/NPoints",
             Label "Sampling points per surface, LE and TE included"},
  AoA = {0, Min -90, Max 90, Name "NACA/AoA", Label "Angle of attack (degrees, nose up)"},
  BoxXMin = {-2, Name "Box/BoxXMin", Label "Box x min (chords)"},
  BoxXMax = {3, Name "Box/BoxXMax", Label "Box x max (chords)"},
  BoxYMax = {2.5, Name "Box/BoxYMax", Label "Box half height (chords)"},
  LcAerofoil = {0.02, Name "Mesh size/LcAerofoil", Label "At the aerofoil (chords)"},
  LcTrailingEdge = {0.005, Name "Mesh size/LcTrailingEdge", Label "At the trailing edge (chords)"},
  LcFarfield = {0.4, Name "Mesh size/LcFarfield", Label "At the far field (chords)"},
  GrowthDistance = {1.5, Name "Mesh size/GrowthDistance",
                    Label "Distance from the aerofoil to reach LcFarfield (chords)"},
  NCurvature = {40, Min 0, Name "Mesh size/NCurvature",
                Label "Elements per 2 pi of curvature radius on the aerofoil (0: off)"}
];

If (NPoints < 4)
  Error("NPoints = %g: at least 4 sampling points per surface are needed", NPoints);
  Abort;
EndIf

N = Round(NPoints) - 1;
m = M / 100;
p = P / 10;
t = T / 100;
dBeta = Pi / N;
a0 = 0.2969;
theta0 = 0;
If (m > 0)
  theta0 = Atan(2 * m / p);
EndIf

pLE = newp; Point(pLE) = {0, 0, 0};
pTE = newp; Point(pTE) = {Chord, 0, 0};

For side In {0:1}
  s = 1 - 2 * side;  // +1 upper surface, -1 lower surface

  // Samples Q_i, i = 0..N, from LE to TE.
  For i In {0:N}
    x = (1 - Cos(i * dBeta)) / 2;
    yt = 5 * t * (a0 * Sqrt(x) - 0.1260 * x - 0.3516 * x^2 + 0.2843 * x^3 - 0.1036 * x^4);
    yc = 0;
    dyc = 0;
    If (m > 0 && x < p)
      yc = m / p^2 * (2 * p * x - x^2);
      dyc = 2 * m / p^2 * (p - x);
    EndIf
    If (m > 0 && x >= p)
      yc = m / (1 - p)^2 * (1 - 2 * p + 2 * p * x - x^2);
      dyc = 2 * m / (1 - p)^2 * (p - x);
    EndIf
    theta = Atan(dyc);
    qx[i] = x - s * yt * Sin(theta);
    qy[i] = yc + s * yt * Cos(theta);
  EndFor

  // Control points P_0..P_{N+2} of the clamped cubic B-spline with knots 0..N:
  // C(0) = P_0 = Q_0, C'(0) = 3 (P_1 - P_0) = exact LE derivative, C(N) = P_{N+2} = Q_N,
  // C''(N) = 0 <=> P_{N+1} = (2 P_{N+2} + P_N) / 3, and C(k) = Q_k at the inner knots:
  //   k = 1:          P_1/4 + 7 P_2/12 + P_3/6 = Q_1,
  //   2 <= k <= N-2:  P_k/6 + 2 P_{k+1}/3 + P_{k+2}/6 = Q_k,
  //   k = N-1:        P_{N-1}/6 + 2 P_N/3 = Q_{N-1} - Q_N/6.
  // Unknowns P_2..P_N (row k solves for P_{k+1}) by the Thomas algorithm.
  dLE = dBeta * 5 * t * a0 / 2;
  px[0] = qx[0];
  py[0] = qy[0];
  px[1] = qx[0] - s * dLE * Sin(theta0) / 3;
  py[1] = qy[0] + s * dLE * Cos(theta0) / 3;
  For k In {1:N-1}
    lo = 1 / 6; di = 2 / 3; up = 1 / 6; rx = qx[k]; ry = qy[k];
    If (k == 1)
      lo = 0; di = 7 / 12; rx = qx[1] - px[1] / 4; ry = qy[1] - py[1] / 4;
    EndIf
    If (k == N - 1)
      up = 0; rx = rx - qx[N] / 6; ry = ry - qy[N] / 6;
    EndIf
    den = di;
    If (k > 1)
      den = di - lo * cp[k - 1];
      rx = rx - lo * dx[k - 1];
      ry = ry - lo * dy[k - 1];
    EndIf
    cp[k] = up / den;
    dx[k] = rx / den;
    dy[k] = ry / den;
  EndFor
  px[N] = dx[N - 1];
  py[N] = dy[N - 1];
  For k In {N-2:1:-1}
    px[k + 1] = dx[k] - cp[k] * px[k + 2];
    py[k + 1] = dy[k] - cp[k] * py[k + 2];
  EndFor
  px[N + 1] = (2 * qx[N] + px[N]) / 3;
  py[N + 1] = (2 * qy[N] + py[N]) / 3;

  ctrl[] = {};
  For k In {1:N+1}
    ctrl[] += newp;
    Point(ctrl[k - 1]) = {Chord * px[k], Chord * py[k], 0};
  EndFor
  surfaceCurve[side] = newc;
  BSpline(surfaceCurve[side]) = {pLE, ctrl[], pTE};
  Delete { Point{ctrl[]}; }
EndFor

aerofoilLoop = newll;
Curve Loop(aerofoilLoop) = {surfaceCurve[0], -surfaceCurve[1]};
aerofoil = news;
Plane Surface(aerofoil) = {aerofoilLoop};
Rotate { {0, 0, 1}, {Chord / 4, 0, 0}, -AoA * Pi / 180 } { Surface{aerofoil}; }

box = news;
Rectangle(box) = {BoxXMin * Chord, -BoxYMax * Chord, 0,
                  (BoxXMax - BoxXMin) * Chord, 2 * BoxYMax * Chord};
bb[] = BoundingBox Surface{aerofoil};
fluid = news;
BooleanDifference(fluid) = { Surface{box}; Delete; }{ Surface{aerofoil}; Delete; };

// Boolean operations renumber curves: find the aerofoil again by its bounding box.
eps = 1e-6 * Chord;
aerofoilCurves[] = Curve In BoundingBox {bb[0] - eps, bb[1] - eps, -eps,
                                         bb[3] + eps, bb[4] + eps, eps};
farfieldCurves[] = Abs(Boundary{ Surface{fluid}; });
farfieldCurves[] -= aerofoilCurves[];
teVertex[] = Point In BoundingBox {
  Chord / 4 + 0.75 * Chord * Cos(AoA * Pi / 180) - eps,
  -0.75 * Chord * Sin(AoA * Pi / 180) - eps, -eps,
  Chord / 4 + 0.75 * Chord * Cos(AoA * Pi / 180) + eps,
  -0.75 * Chord * Sin(AoA * Pi / 180) + eps, eps};

Physical Curve("aerofoil") = {aerofoilCurves[]};
Physical Curve("farfield") = {farfieldCurves[]};
Physical Surface("fluid") = {fluid};

Field[1] = Distance;
Field[1].CurvesList = {aerofoilCurves[]};
Field[1].NumPointsPerCurve = 400;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = LcAerofoil * Chord;
Field[2].SizeMax = LcFarfield * Chord;
Field[2].DistMin = 0;
Field[2].DistMax = GrowthDistance * Chord;
Field[3] = Distance;
Field[3].PointsList = {teVertex[]};
Field[4] = Threshold;
Field[4].InField = 3;
Field[4].SizeMin = LcTrailingEdge * Chord;
Field[4].SizeMax = LcAerofoil * Chord;
Field[4].DistMin = 0;
Field[4].DistMax = 0.1 * Chord;
Field[4].StopAtDistMax = 1;
Field[5] = Min;
Field[5].FieldsList = {2, 4};
Background Field = 5;

Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 1;
Mesh.MeshSizeFromCurvature = NCurvature;
