// Plane-strain steady rolling (inputs/verification/contact_rolling_carter): the lower half of a
// steel cylinder of radius R = 0.1 m (axis along y) on a steel block 0.1 m wide and 0.05 m deep,
// both one element (t = 1 mm) thick along y; drawn in the x-z plane (z up) and extruded along y
// into one layer of hexahedra. It is inputs/meshes/hertz_cylinder.geo with the structured
// contact bands made asymmetric: in the deck the block moves along -x and the cylinder turns
// so that its lowest point moves along -x too, so the material that comes into contact during
// a rolling distance d lies ahead (+x) of the first contact point on both bodies. Each band
// reaches xl behind the contact point and xr ahead of it (xr = d + b + a margin), ds deep,
// square elements of size h, with nodes at x = 0 on both surfaces.
// Outside the bands quadrangles (Frontal-Delaunay, recombined) grow from h by g per metre of
// distance up to H. The cylinder starts gap = 0.1 um above the block (Gmsh would otherwise
// merge the bodies' points at the contact: they share no nodes).
// Regenerate with:  gmsh -3 -format msh41 -o rolling_cylinder.msh rolling_cylinder.geo
// Other densities:  gmsh -3 -format msh41 -setnumber h 0.125e-3 -o r0125.msh rolling_cylinder.geo
// Near zone: the parts of both bodies within rn of the contact point are blocks of their own
// (roller_near, block_near), so that a deck can scale their density; roller_far and block_far
// are the rest.
// Sets: blocks roller_near, roller_far, block_near, block_far; side sets (and node sets)
// "roller_contact" (the arc of the band: the slave surface), "roller_top" (the flat face
// z = R: the hub), "block_top" (the top face of the band: the master surface), "block_bottom"
// (z = -D).
DefineConstant[ h = {0.25e-3, Name "Parameters/contact-zone element size (m)"} ];
DefineConstant[ H = {4.5e-3, Name "Parameters/largest element size (m)"} ];
DefineConstant[ g = {0.15, Name "Parameters/size growth per distance"} ];
DefineConstant[ xl = {3e-3, Name "Parameters/band behind the contact point (m)"} ];
DefineConstant[ xr = {28e-3, Name "Parameters/band ahead of the contact point (m)"} ];
DefineConstant[ ds = {2e-3, Name "Parameters/depth of the structured contact zone (m)"} ];
DefineConstant[ rn = {31e-3, Name "Parameters/radius of the near zone (blocks *_near) (m)"} ];
R = 0.1;     // cylinder radius
t = 1e-3;    // thickness along y
DefineConstant[ L = {0.05, Name "Parameters/block half-width (m)"} ];
DefineConstant[ D = {0.05, Name "Parameters/block depth (m)"} ];
gap = 1e-7;  // initial gap between cylinder and block
nl = Round(xl / h);  // band elements behind x = 0
nr = Round(xr / h);  // band elements ahead of x = 0
nz = Round(ds / h);  // elements through the structured band's depth
ri = R - ds;         // inner radius of the cylinder's band

// Cylinder (points in the x-z plane, y = 0).
Point(1) = {0, 0, gap + R};                                  // centre and middle of the top face
Point(2) = {0, 0, gap};                                      // lowest point
Point(3) = {xr, 0, gap + R - Sqrt(R * R - xr * xr)};         // band corners on the arc
Point(4) = {-xl, 0, gap + R - Sqrt(R * R - xl * xl)};
Point(5) = {xr * ri / R, 0, gap + R - ri * Sqrt(R * R - xr * xr) / R};  // band corners inside
Point(6) = {-xl * ri / R, 0, gap + R - ri * Sqrt(R * R - xl * xl) / R};
Point(7) = {0, 0, gap + ds};
Point(8) = {R, 0, gap + R};
Point(9) = {-R, 0, gap + R};
zq = rn * rn / (2 * R);                                      // near zone: within rn of point 2
Point(21) = {Sqrt(rn * rn - zq * zq), 0, gap + zq};
Point(22) = {-Sqrt(rn * rn - zq * zq), 0, gap + zq};
Point(23) = {0, 0, gap + rn};
Circle(1) = {4, 1, 2};   // band: outer arc
Circle(2) = {2, 1, 3};
Line(3) = {3, 5};        // band: radial sides
Line(4) = {6, 4};
Circle(5) = {5, 1, 7};   // band: inner arc
Circle(6) = {7, 1, 6};
Circle(7) = {3, 1, 21};  // near zone: arc and its inner boundary
Circle(21) = {21, 2, 23};
Circle(22) = {23, 2, 22};
Circle(23) = {22, 1, 4};
Circle(24) = {21, 1, 8}; // rest of the half circle
Circle(8) = {9, 1, 22};
Line(9) = {8, 1};        // top face
Line(10) = {1, 9};
Transfinite Curve{9, 10} = Round(R / H) + 1;  // the hub: evenly spaced nodes
Transfinite Curve{1, 6} = nl + 1;
Transfinite Curve{2, 5} = nr + 1;
Transfinite Curve{3, 4} = nz + 1;
// Loops run clockwise seen from +y, like the block's, so the extruded hexahedra are positive.
Curve Loop(1) = {-4, -6, -5, -3, -2, -1};
Plane Surface(1) = {1};
Transfinite Surface{1} = {4, 6, 5, 3};
Curve Loop(2) = {3, 5, 6, 4, -23, -22, -21, -7};
Plane Surface(2) = {2};
Curve Loop(5) = {24, 9, 10, 8, -22, -21};
Plane Surface(5) = {5};

// Block: top face at z = 0.
Point(11) = {0, 0, 0};
Point(12) = {xr, 0, 0};
Point(13) = {-xl, 0, 0};
Point(14) = {xr, 0, -ds};
Point(15) = {-xl, 0, -ds};
Point(16) = {L, 0, 0};
Point(17) = {-L, 0, 0};
Point(18) = {L, 0, -D};
Point(19) = {-L, 0, -D};
Point(24) = {rn, 0, 0};
Point(25) = {-rn, 0, 0};
Point(26) = {0, 0, -rn};
Line(11) = {13, 11};     // band: top
Line(12) = {11, 12};
Line(13) = {12, 14};     // band: sides and bottom
Line(14) = {14, 15};
Line(15) = {15, 13};
Line(16) = {12, 24};     // near zone: top and its inner boundary
Circle(25) = {24, 11, 26};
Circle(26) = {26, 11, 25};
Line(27) = {25, 13};
Line(28) = {24, 16};     // rest of the block
Line(17) = {16, 18};
Line(18) = {18, 19};
Line(19) = {19, 17};
Line(20) = {17, 25};
Transfinite Curve{18} = Round(2 * L / H) + 1;
Transfinite Curve{11} = nl + 1;
Transfinite Curve{12} = nr + 1;
Transfinite Curve{14} = nl + nr + 1;
Transfinite Curve{13, 15} = nz + 1;
Curve Loop(3) = {11, 12, 13, 14, 15};
Plane Surface(3) = {3};
Transfinite Surface{3} = {13, 12, 14, 15};
Curve Loop(4) = {16, 25, 26, 27, -15, -14, -13};
Plane Surface(4) = {4};
Curve Loop(6) = {28, 17, 18, 19, 20, -26, -25};
Plane Surface(6) = {6};

// Sizes outside the bands: h at the bands' edges, growing with the distance from them.
Field[1] = Distance;
Field[1].EdgesList = {3, 4, 5, 6, 13, 14, 15};
Field[2] = Threshold;
Field[2].IField = 1;
Field[2].LcMin = h;
Field[2].LcMax = H;
Field[2].DistMin = 0;
Field[2].DistMax = (H - h) / g;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.Algorithm = 6;               // Frontal-Delaunay (8, for quadrangles, crashes in Gmsh 4.8.4)
Mesh.RecombinationAlgorithm = 3;  // blossom full-quad: blossom (1) leaves a few triangles here
Mesh.RecombineAll = 1;

Extrude {0, t, 0} { Surface{1, 2, 5, 3, 4, 6}; Layers{1}; Recombine; }
e = 1e-8;
roller[] = Volume In BoundingBox{-R - e, -e, -e, R + e, t + e, R + 1e-6};
roller_near[] = Volume In BoundingBox{-rn - e, -e, -e, rn + e, t + e, gap + rn + e};
roller[] -= roller_near[];
block[] = Volume In BoundingBox{-L - e, -e, -D - e, L + e, t + e, e};
block_near[] = Volume In BoundingBox{-rn - e, -e, -rn - e, rn + e, t + e, e};
block[] -= block_near[];
Physical Volume("roller_near") = {roller_near[]};
Physical Volume("roller_far") = {roller[]};
Physical Volume("block_near") = {block_near[]};
Physical Volume("block_far") = {block[]};
zs = gap + R - Sqrt(R * R - xr * xr);  // the band's arc lies below the height of its +x end
Physical Surface("roller_contact") = {Surface In BoundingBox{-xl - e, -e, gap - e, xr + e, t + e, zs + e}};
Physical Surface("roller_top") = {Surface In BoundingBox{-R - e, -e, gap + R - e, R + e, t + e, gap + R + e}};
Physical Surface("block_top") = {Surface In BoundingBox{-xl - e, -e, -e, xr + e, t + e, e}};
Physical Surface("block_bottom") = {Surface In BoundingBox{-L - e, -e, -D - e, L + e, t + e, -D + e}};
