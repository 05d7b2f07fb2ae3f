// A unit ball cut out of the box [-2, 2]^3 (OpenCASCADE): the fluid volume round a
// sphere, the first case of the 3D corpus (issue 24; scripts/bench/corpus3d.py builds
// the others). homesh meshes it in tetrahedra (the model has a volume) and curves them:
//   homesh geo/ball_in_box.geo -m curve:p=3 -m quality ball.msh
SetFactory("OpenCASCADE");
DefineConstant[ size = {0.5, Name "Parameters/size"} ];
Box(1) = {-2, -2, -2, 4, 4, 4};
Sphere(2) = {0, 0, 0, 1};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Physical Volume("fluid") = {3};
ball() = Surface In BoundingBox{-1.01, -1.01, -1.01, 1.01, 1.01, 1.01};
Physical Surface("ball") = {ball()};
Mesh.MeshSizeMax = size;
