// Channel [0, ChannelLength] x [0, ChannelHeight] with a circular-arc bump on its floor
// (the GAMM channel's shape for the defaults, BumpHeight / BumpLength = 0.1): a fixture for
// boundary layers on open walls, which end on the inflow and outflow sides (homesh layers
// stage, walls=wall). BumpHeight = 0 gives a plain rectangle. Built-in kernel, so the
// curve tags are fixed: 1-3 the floor (1 alone without bump), 4 outlet, 5 top, 6 inlet.
//
// The floor runs from (0, 0) to (ChannelLength, 0), the bump spanning
// [BumpStart, BumpStart + BumpLength] as the arc through its ends and
// (BumpStart + BumpLength / 2, BumpHeight). Mesh size LcWall on the floor, Lc elsewhere.
//
// Physical groups: Curve "wall" (the floor), Curve "outlet" (x = ChannelLength), Curve "top"
// (y = ChannelHeight), Curve "inlet" (x = 0), Surface "fluid".

DefineConstant[
  ChannelLength = {3, Min 0.1, Name "Channel/Length", Label "Channel length"},
  ChannelHeight = {1, Min 0.01, Name "Channel/Height", Label "Channel height"},
  BumpStart = {1, Min 0, Name "Channel/BumpStart", Label "x where the bump starts"},
  BumpLength = {1, Min 0.01, Name "Channel/BumpLength", Label "Length of the chord of the bump"},
  BumpHeight = {0.1, Min 0, Name "Channel/BumpHeight", Label "Height of the bump (0: none)"},
  Lc = {0.1, Name "Mesh size/Lc", Label "Mesh size on inlet, outlet and top"},
  LcWall = {0.05, Name "Mesh size/LcWall", Label "Mesh size on the floor"}
];

If (BumpStart <= 0 || BumpStart + BumpLength >= ChannelLength || BumpHeight >= ChannelHeight)
  Error("the bump [%g, %g] x [0, %g] must lie inside the channel [0, %g] x [0, %g]",
        BumpStart, BumpStart + BumpLength, BumpHeight, ChannelLength, ChannelHeight);
  Abort;
EndIf

Point(1) = {0, 0, 0, LcWall};
Point(2) = {ChannelLength, 0, 0, LcWall};
Point(3) = {ChannelLength, ChannelHeight, 0, Lc};
Point(4) = {0, ChannelHeight, 0, Lc};
If (BumpHeight > 0)
  // The arc's centre lies below the chord, radius R = (c^2 / 4 + h^2) / (2 h).
  radius = (BumpLength^2 / 4 + BumpHeight^2) / (2 * BumpHeight);
  Point(5) = {BumpStart, 0, 0, LcWall};
  Point(6) = {BumpStart + BumpLength, 0, 0, LcWall};
  Point(7) = {BumpStart + BumpLength / 2, BumpHeight - radius, 0, LcWall};
  Line(1) = {1, 5};
  Circle(2) = {5, 7, 6};
  Line(3) = {6, 2};
  wall[] = {1, 2, 3};
Else
  Line(1) = {1, 2};
  wall[] = {1};
EndIf
Line(4) = {2, 3};
Line(5) = {3, 4};
Line(6) = {4, 1};
Curve Loop(1) = {wall[], 4, 5, 6};
Plane Surface(1) = {1};

Physical Curve("wall") = {wall[]};
Physical Curve("outlet") = {4};
Physical Curve("top") = {5};
Physical Curve("inlet") = {6};
Physical Surface("fluid") = {1};
