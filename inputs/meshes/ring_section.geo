// Cross-section of the free thin ring of the modal verification: a circle of diameter d = 0.1 m
// centred at r = R = 1 m, a = 0 (x = r, y = a), meshed with quadrangles only as an O-grid (an
// inner square and four blocks between it and the circle). Mesh/Type revolved turns it into the
// ring (R = 1 m, d = 0.1 m).
// Regenerate with:  gmsh -2 -format msh41 -o ring_section.msh ring_section.geo
// Density: n elements along each quarter of the circle (and across the square), n/2 radially;
// another density:  gmsh -2 -format msh41 -setnumber n 16 -o ring16.msh ring_section.geo
// Sets: block "ring" (the whole section); node set "surface" (the circle: the ring's surface).
DefineConstant[ n = {8, Name "Parameters/elements per quarter circle"} ];
m = Ceil(n / 2);          // radial elements between the square and the circle
R = 1;                    // centre radius (m)
rho = 0.05;               // section radius (m)
c = 0.35 * rho;           // half side of the inner square
s = rho / Sqrt(2);

Point(1) = {R, 0, 0};
Point(2) = {R + c, -c, 0};
Point(3) = {R + c, c, 0};
Point(4) = {R - c, c, 0};
Point(5) = {R - c, -c, 0};
Point(6) = {R + s, -s, 0};
Point(7) = {R + s, s, 0};
Point(8) = {R - s, s, 0};
Point(9) = {R - s, -s, 0};

Line(1) = {2, 3};  // the square, counter-clockwise
Line(2) = {3, 4};
Line(3) = {4, 5};
Line(4) = {5, 2};
Circle(5) = {6, 1, 7};  // the circle, counter-clockwise
Circle(6) = {7, 1, 8};
Circle(7) = {8, 1, 9};
Circle(8) = {9, 1, 6};
Line(9) = {2, 6};  // spokes from the square's corners to the circle
Line(10) = {3, 7};
Line(11) = {4, 8};
Line(12) = {5, 9};

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {9, 5, -10, -1};
Plane Surface(2) = {2};
Curve Loop(3) = {10, 6, -11, -2};
Plane Surface(3) = {3};
Curve Loop(4) = {11, 7, -12, -3};
Plane Surface(4) = {4};
Curve Loop(5) = {12, 8, -9, -4};
Plane Surface(5) = {5};

Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8} = n + 1;
Transfinite Curve{9, 10, 11, 12} = m + 1;
Transfinite Surface{1} = {2, 3, 4, 5};
Transfinite Surface{2} = {2, 6, 7, 3};
Transfinite Surface{3} = {3, 7, 8, 4};
Transfinite Surface{4} = {4, 8, 9, 5};
Transfinite Surface{5} = {5, 9, 6, 2};
Recombine Surface{1, 2, 3, 4, 5};

Physical Surface("ring") = {1, 2, 3, 4, 5};
Physical Curve("surface") = {5, 6, 7, 8};
