// The coarse quadratic plate-with-hole mesh of the rotation benchmark (thesis Section 4.4.1,
// Fig 4.13, Tables 4.1-4.8): geo/plate_hole.geo ([-1, 1]^2, hole radius 0.5) with sizes
// chosen so that about eleven elements surround the hole and one to two element layers
// separate it from the outer edges (71 triangles with Gmsh 4.8's Frontal-Delaunay). Mesh it
// quadratic: `gmsh geo/plate_hole_fig413.geo -2 -order 2`. See geo/README.md.
LcHole = 0.3;
LcFarfield = 0.45;
Include "plate_hole.geo";
