// Cross-section of the spinning annular disc of the statics verification (centrifugal load):
// r from a = 0.1 m to b = 0.5 m, axial thickness t = 0.01 m (x = r, y = a), structured
// quadrangles. Mesh/Type revolved turns it into the disc.
// Regenerate with:  gmsh -2 -format msh41 -o disc_section.msh disc_section.geo
// Sets: block "disc"; node sets "inner" (r = a) and "middle" (the mid-plane line a = 0, where
// the probes read u_r).
a = 0.1; b = 0.5; t = 0.01;
nr = 40; nt = 2;
Point(1) = {a, -t / 2, 0};
Point(2) = {b, -t / 2, 0};
Point(3) = {b, t / 2, 0};
Point(4) = {a, t / 2, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nr + 1;
Transfinite Curve{2, 4} = nt + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("disc") = {1};
Physical Curve("inner") = {4};
Physical Curve("outer") = {2};
