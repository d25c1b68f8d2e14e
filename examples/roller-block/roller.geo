// Steel roller of roller-block-gmsh.yaml: the quarter of the circle of radius R = 20 centred at
// O = (0, 20) below its centre line, contact at S = (0, 0), symmetry line x = 0. Three
// transfinite quad patches (an O-grid around the inner corner P), as examples/gmsh/hertz.geo.
//   gmsh -2 -order 2 -format msh41 roller.geo -o roller.msh      (9-node quads: arcs recovered)
R = 20;
ri = 8;       // inner patch: O to A = (0, R - ri) and to B = (ri, R)
a = 0.8;      // inner corner P = (a ri, R - a ri)
Point(1) = {0, R, 0};                               // O, centre
Point(2) = {0, 0, 0};                               // S, first contact point
Point(3) = {R * Sin(Pi/4), R - R * Cos(Pi/4), 0};   // M, arc at 45 degrees
Point(4) = {R, R, 0};                               // E, end of the arc on the centre line
Point(5) = {0, R - ri, 0};                          // A
Point(6) = {a * ri, R - a * ri, 0};                 // P
Point(7) = {ri, R, 0};                              // B
Line(1) = {1, 5};
Line(2) = {5, 2};
Circle(3) = {2, 1, 3};
Circle(4) = {3, 1, 4};
Line(5) = {4, 7};
Line(6) = {7, 1};
Line(7) = {5, 6};
Line(8) = {6, 7};
Line(9) = {6, 3};
Curve Loop(1) = {1, 7, 8, 6};    Plane Surface(1) = {1};  // O A P B
Curve Loop(2) = {2, 3, -9, -7};  Plane Surface(2) = {2};  // A S M P
Curve Loop(3) = {9, 4, 5, -8};   Plane Surface(3) = {3};  // P M E B
Transfinite Curve{2, 9, 5} = 3;
Transfinite Curve{3, 7, 6} = 3;
Transfinite Curve{1, 8, 4} = 2;
Transfinite Surface{1, 2, 3};
Mesh.RecombineAll = 1;
Physical Curve("symmetry") = {1, 2};
Physical Curve("contact") = {3};
Physical Curve("outer") = {4};
Physical Curve("centre") = {5, 6};
Physical Surface("roller") = {1, 2, 3};
