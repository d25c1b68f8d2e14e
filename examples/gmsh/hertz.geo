// Hertz quarter cylinder (examples/hertz): a quarter of the circle of radius R = 10 centred at
// O = (0, 10), contact at S = (0, 0), symmetry line x = 0, centre line y = 10. Three transfinite
// quad patches (an O-grid around the inner corner P), graded towards S along the contact arc.
//   gmsh -2 -order 2 -format msh41 hertz.geo -o hertz.msh      (9-node quads: arcs recovered)
//   gmsh -2 -format msh41 hertz.geo -o hertz-linear.msh        (4-node quads: arcs named)
R = 10;
ri = 4;       // inner patch: O to A = (0, 10 - ri) and to B = (ri, 10)
a = 0.8;      // inner corner P = (a ri, 10 - a ri)
grade = 1.4;  // element length ratio along the contact arc S -> M
Point(1) = {0, 10, 0};                             // O, centre
Point(2) = {0, 0, 0};                              // S, first contact point
Point(3) = {R * Sin(Pi/4), 10 - R * Cos(Pi/4), 0};  // M, arc at 45 degrees
Point(4) = {R, 10, 0};                             // E, end of the arc on the centre line
Point(5) = {0, 10 - ri, 0};                        // A
Point(6) = {a * ri, 10 - a * ri, 0};               // P
Point(7) = {ri, 10, 0};                            // B
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
// Opposite sides of a patch have as many elements: 3 from the centre towards S, 5 along the
// contact arc, 2 elsewhere.
Transfinite Curve{2} = 4 Using Progression 1 / grade;
Transfinite Curve{9} = 4 Using Progression grade;
Transfinite Curve{5} = 4;
Transfinite Curve{3, 7} = 6 Using Progression grade;
Transfinite Curve{6} = 6;
Transfinite Curve{1, 8, 4} = 3;
Transfinite Surface{1, 2, 3};
Mesh.RecombineAll = 1;
Physical Curve("symmetry") = {1, 2};
Physical Curve("contact") = {3};
Physical Curve("outer") = {4};
Physical Curve("centre") = {5, 6};
Physical Surface("cylinder") = {1, 2, 3};
