// A 10:1 ellipse (semi-axes 0.5, 0.05; nose radius 0.005) in a box, meshed with Gmsh's own
// BoundaryLayer field (first cell 1e-4, ratio 1.2, triangles; quadrilaterals with Quads = 1,
// as ellipse_bl_quads.geo sets it): a mesh homesh did not make,
// whose 0.015 wall edges turn 90 degrees round the nose (issue 16's ellipse10_bl_1e-4).
SetFactory("OpenCASCADE");
DefineConstant[
  First = {1e-4, Name "Layers/First"},
  Ratio = {1.2, Name "Layers/Ratio"},
  Thickness = {0.004, Name "Layers/Thickness"},
  LcWall = {0.015, Name "Mesh size/LcWall"},
  LcFar = {0.3, Name "Mesh size/LcFar"},
  Quads = {0, Choices{0, 1}, Name "Layers/Quads", Label "Quadrilaterals in the layers"}
];
Rectangle(1) = {-1, -0.75, 0, 2.5, 1.5};
Disk(2) = {0.5, 0, 0, 0.5, 0.05};
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
wall[] = Abs(Boundary{ Surface{3}; });
// The ellipse is the last curve of the boundary (OCC lists the outer loop first).
Physical Curve("wall") = {wall[#wall[] - 1]};
Physical Curve("farfield") = {wall[{0 : #wall[] - 2}]};
Physical Surface("fluid") = {3};

Field[1] = Distance;
Field[1].CurvesList = {wall[#wall[] - 1]};
Field[1].NumPointsPerCurve = 400;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = LcWall;
Field[2].SizeMax = LcFar;
Field[2].DistMin = Thickness;
Field[2].DistMax = 1.0;
Background Field = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm = 6;

Field[3] = BoundaryLayer;
Field[3].CurvesList = {wall[#wall[] - 1]};
Field[3].Size = First;
Field[3].Ratio = Ratio;
Field[3].Thickness = Thickness;
Field[3].Quads = Quads;
BoundaryLayer Field = 3;
