// ellipse_bl.geo with Gmsh's boundary layer made of quadrilaterals (BoundaryLayer field,
// Quads = 1), triangles outside: the mixed mesh a CFD user brings (issue 21).
Quads = 1;
Include "ellipse_bl.geo";
