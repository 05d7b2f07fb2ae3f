// The coarse NACA-7526 mesh of the rotation cases (thesis Section 4.4.2, Figs 4.18-4.21):
// geo/naca.geo (the aerofoil in a 5 x 5 chords square) with one size, 0.1 chord, all along
// the aerofoil (no trailing-edge refinement), 1 chord at the far field and 20 elements per
// 2 pi of curvature radius: 29 segments on the aerofoil, 337 triangles with Gmsh 4.8.
// The thesis gives no sizes; its Figs 4.18(a) and 4.19(a) show a coarse mesh, and a finer
// trailing edge only makes the elements there smaller, which the sharp corner then folds
// sooner. Layers, order and rotation: scripts/naca_rotation.py and geo/README.md.
LcAerofoil = 0.1;
LcTrailingEdge = 0.1;
LcFarfield = 1;
NCurvature = 20;
Include "naca.geo";
