// Two bars, 1 x 0.2 x 0.2 m each, meshed separately: no shared nodes at x = 1, and different
// axial divisions (5 and 3 elements). railfe ties them with multi-point constraints.
// Regenerate with:  gmsh -3 -format msh41 -o tied_bar.msh tied_bar.geo
// Sets: left_end (x = 0), right_end (x = 2), interface_left and interface_right (x = 1 on each
// bar), y0_left and z0_left (the faces y = 0 and z = 0 of the left bar); blocks left and right.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.2, 0.2};
Box(2) = {1, 0, 0, 1, 0.2, 0.2};  // no BooleanFragments: the bars stay separate
e = 1e-6;
Transfinite Curve{:} = 3;  // 2 elements across y and z, the same on both bars
// Edges along x: 5 elements on the left bar, 3 on the right one.
Transfinite Curve{Curve In BoundingBox{-e, -e, -e, 1 + e, e, e}} = 6;
Transfinite Curve{Curve In BoundingBox{-e, 0.2 - e, -e, 1 + e, 0.2 + e, e}} = 6;
Transfinite Curve{Curve In BoundingBox{-e, -e, 0.2 - e, 1 + e, e, 0.2 + e}} = 6;
Transfinite Curve{Curve In BoundingBox{-e, 0.2 - e, 0.2 - e, 1 + e, 0.2 + e, 0.2 + e}} = 6;
Transfinite Curve{Curve In BoundingBox{1 - e, -e, -e, 2 + e, e, e}} = 4;
Transfinite Curve{Curve In BoundingBox{1 - e, 0.2 - e, -e, 2 + e, 0.2 + e, e}} = 4;
Transfinite Curve{Curve In BoundingBox{1 - e, -e, 0.2 - e, 2 + e, e, 0.2 + e}} = 4;
Transfinite Curve{Curve In BoundingBox{1 - e, 0.2 - e, 0.2 - e, 2 + e, 0.2 + e, 0.2 + e}} = 4;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{:};
Physical Volume("left") = {1};
Physical Volume("right") = {2};
Physical Surface("left_end") = {Surface In BoundingBox{-e, -e, -e, e, 0.2 + e, 0.2 + e}};
Physical Surface("right_end") = {Surface In BoundingBox{2 - e, -e, -e, 2 + e, 0.2 + e, 0.2 + e}};
interface[] = Surface In BoundingBox{1 - e, -e, -e, 1 + e, 0.2 + e, 0.2 + e};
Physical Surface("interface_left") = {interface[0]};
Physical Surface("interface_right") = {interface[1]};
Physical Surface("y0_left") = {Surface In BoundingBox{-e, -e, -e, 1 + e, e, 0.2 + e}};
Physical Surface("z0_left") = {Surface In BoundingBox{-e, -e, -e, 1 + e, 0.2 + e, e}};
