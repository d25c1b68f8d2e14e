// Steel roller of roller-block-friction.yaml: the lower half of the disc of radius R = 15
// centred at O = (0, 15), touching the block at S = (0, 0). A full model (no symmetry line: the
// shear breaks the symmetry). Six transfinite quad patches, an O-grid around the inner corners
// PL, PR, as ../roller.geo mirrored about x = 0; the centre line y = 15 carries the load.
//   gmsh -2 -order 2 -format msh41 roller.geo -o roller.msh      (9-node quads: arcs recovered)
R = 15;
ri = 6;       // inner patches: O to A = (0, R - ri) and to BL, BR = (-+ri, R)
a = 0.8;      // inner corners PL, PR = (-+a ri, R - a ri)
Point(1) = {0, R, 0};                                // O, centre
Point(2) = {0, 0, 0};                                // S, first contact point
Point(3) = {R * Sin(Pi/4), R - R * Cos(Pi/4), 0};    // MR, arc at 45 degrees
Point(4) = {R, R, 0};                                // ER, end of the arc on the centre line
Point(5) = {0, R - ri, 0};                           // A
Point(6) = {a * ri, R - a * ri, 0};                  // PR
Point(7) = {ri, R, 0};                               // BR
Point(8) = {-R * Sin(Pi/4), R - R * Cos(Pi/4), 0};   // ML
Point(9) = {-R, R, 0};                               // EL
Point(10) = {-a * ri, R - a * ri, 0};                // PL
Point(11) = {-ri, R, 0};                             // BL
// right half
Line(1) = {1, 5};
Line(2) = {5, 2};
Circle(3) = {2, 1, 3};
Circle(4) = {3, 1, 4};
Line(5) = {4, 7};
Line(6) = {7, 1};
Line(7) = {5, 6};
Line(8) = {6, 7};
Line(9) = {6, 3};
// left half
Circle(13) = {8, 1, 2};
Circle(14) = {9, 1, 8};
Line(15) = {11, 9};
Line(16) = {1, 11};
Line(17) = {10, 5};
Line(18) = {11, 10};
Line(19) = {8, 10};
Curve Loop(1) = {1, 7, 8, 6};     Plane Surface(1) = {1};  // O A PR BR
Curve Loop(2) = {2, 3, -9, -7};   Plane Surface(2) = {2};  // A S MR PR
Curve Loop(3) = {9, 4, 5, -8};    Plane Surface(3) = {3};  // PR MR ER BR
Curve Loop(4) = {16, 18, 17, -1}; Plane Surface(4) = {4};  // O BL PL A
Curve Loop(5) = {-17, -19, 13, -2}; Plane Surface(5) = {5};  // A PL ML S
Curve Loop(6) = {19, -18, 15, 14}; Plane Surface(6) = {6};  // ML PL BL EL
Transfinite Curve{2, 9, 5, 19, 15} = 3;
Transfinite Curve{3, 7, 6, 13, 17, 16} = 3;
Transfinite Curve{1, 8, 4, 18, 14} = 2;
Transfinite Surface{1, 2, 3, 4, 5, 6};
Mesh.RecombineAll = 1;
Physical Curve("contact") = {13, 3};
Physical Curve("outer") = {14, 4};
Physical Curve("centre") = {15, 16, 6, 5};
Physical Surface("roller") = {1, 2, 3, 4, 5, 6};
