// Square plate with a centred circular hole: the rotation benchmark of thesis Section 4.4.1
// (Fig 4.13, Tables 4.1-4.8: the hole is rotated anticlockwise 1 degree per step until the
// first invalid element) and the hole of Sections 4.2.3 and 4.3 (Figs 4.2-4.4, 4.8).
// The thesis gives no dimensions; the defaults here are the plate [-1, 1]^2 (HalfSide = 1)
// and a hole of radius 0.5, so the ligament between hole and edge equals the radius.
//
// The hole is one closed circle (a single vertex at (Radius, 0)). Mesh size LcHole on the
// hole and LcFarfield on the outer edges, interpolated in between.
//
// Physical groups: Curve "hole", Curve "farfield", Surface "plate".

SetFactory("OpenCASCADE");

DefineConstant[
  Radius = {0.5, Min 0.01, Name "Plate/Radius", Label "Hole radius"},
  HalfSide = {1, Min 0.02, Name "Plate/HalfSide", Label "Half side of the square plate"},
  LcHole = {0.1, Name "Mesh size/LcHole", Label "Mesh size on the hole"},
  LcFarfield = {0.2, Name "Mesh size/LcFarfield", Label "Mesh size on the outer edges"}
];

If (Radius >= HalfSide)
  Error("Radius = %g must be smaller than HalfSide = %g", Radius, HalfSide);
  Abort;
EndIf

square = news;
Rectangle(square) = {-HalfSide, -HalfSide, 0, 2 * HalfSide, 2 * HalfSide};
disk = news;
Disk(disk) = {0, 0, 0, Radius};
plate = news;
BooleanDifference(plate) = { Surface{square}; Delete; }{ Surface{disk}; Delete; };

// Boolean operations renumber curves: find the hole again by its bounding box.
eps = 1e-6 * HalfSide;
holeCurves[] = Curve In BoundingBox {-Radius - eps, -Radius - eps, -eps,
                                     Radius + eps, Radius + eps, eps};
farfieldCurves[] = Abs(Boundary{ Surface{plate}; });
farfieldCurves[] -= holeCurves[];

Physical Curve("hole") = {holeCurves[]};
Physical Curve("farfield") = {farfieldCurves[]};
Physical Surface("plate") = {plate};

MeshSize { PointsOf{ Curve{farfieldCurves[]}; } } = LcFarfield;
MeshSize { PointsOf{ Curve{holeCurves[]}; } } = LcHole;
