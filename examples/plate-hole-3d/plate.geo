// A plate with a central cylindrical hole under tension (examples/plate-hole-3d): width 2W,
// length 2L, thickness t, hole radius a; the quarter 0 <= x <= L, 0 <= y <= W, 0 <= z <= t with
// the symmetry planes x = 0 and y = 0, meshed with hexahedra (transfinite patches extruded
// through the thickness).
//   gmsh -3 -order 2 -format msh41 plate.geo -o plate.msh      (27-node hexahedra, the hole's
//                                                               nodes on the cylinder)
// Physical surfaces: hole (r = a), x0 and y0 (symmetry), z0 and z1 (the faces z = 0 and z = t),
// end (x = L, loaded), side (y = W); physical volume: plate.
W = 10;       // half width
a = 0.2 * W;  // hole radius
L = 2 * W;    // half length
DefineConstant[ t = 2 ];        // thickness (gmsh -setnumber t 0.2 ... for a thin plate)
DefineConstant[ n_thick = 2 ];  // elements through the thickness
n_arc = 3;    // elements along each half of the hole's quarter arc
n_radial = 4; // elements from the hole to the square x, y <= W
grade = 1.3;  // element length ratio from the hole outwards
n_end = 3;    // elements along x from x = W to x = L
Point(1) = {0, 0, 0};                          // the hole's centre
Point(2) = {a, 0, 0};
Point(3) = {a * Cos(Pi/4), a * Sin(Pi/4), 0};
Point(4) = {0, a, 0};
Point(5) = {W, 0, 0};
Point(6) = {W, W, 0};
Point(7) = {0, W, 0};
Point(8) = {L, 0, 0};
Point(9) = {L, W, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {2, 5};
Line(4) = {3, 6};
Line(5) = {4, 7};
Line(6) = {5, 6};
Line(7) = {6, 7};
Line(8) = {5, 8};
Line(9) = {8, 9};
Line(10) = {9, 6};
Curve Loop(1) = {3, 6, -4, -1};  Plane Surface(1) = {1};  // below the diagonal
Curve Loop(2) = {4, 7, -5, -2};  Plane Surface(2) = {2};  // above it
Curve Loop(3) = {8, 9, 10, -6};  Plane Surface(3) = {3};  // W <= x <= L
Transfinite Curve{1, 2, 6, 7, 9} = n_arc + 1;
Transfinite Curve{3, 4, 5} = n_radial + 1 Using Progression grade;
Transfinite Curve{8, 10} = n_end + 1;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};
v[] = Extrude {0, 0, t} { Surface{1, 2, 3}; Layers{n_thick}; Recombine; };
// Extrude gives per surface six entries: the top, the volume, then the sides on the curves of its
// loop in order: v[2..5] on curves 3, 6, 4, 1; v[8..11] on 4, 7, 5, 2; v[14..17] on 8, 9, 10, 6.
Physical Surface("hole") = {v[5], v[11]};
Physical Surface("x0") = {v[10]};
Physical Surface("y0") = {v[2], v[14]};
Physical Surface("z0") = {1, 2, 3};
Physical Surface("z1") = {v[0], v[6], v[12]};
Physical Surface("end") = {v[15]};
Physical Surface("side") = {v[9], v[16]};
Physical Volume("plate") = {v[1], v[7], v[13]};
