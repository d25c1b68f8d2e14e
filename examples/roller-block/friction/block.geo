// Aluminium block of roller-block-friction.yaml: [-W, W] x [-H, 0], the roller touching its top
// at S = (0, 0), held on its bottom (ux = uy = 0). A full model: ../block.geo mirrored about
// x = 0, eight transfinite quad patches around the corner squares [-c, c] x [-c, 0] at S, coarse:
// the hp loop refines where the zone is.
//   gmsh -2 -order 2 -format msh41 block.geo -o block.msh
W = 20;
H = 20;
c = 4;
Point(1) = {0, 0, 0};     // S
Point(2) = {c, 0, 0};
Point(3) = {W, 0, 0};
Point(4) = {W, -c, 0};
Point(5) = {W, -H, 0};
Point(6) = {c, -H, 0};
Point(7) = {0, -H, 0};
Point(8) = {0, -c, 0};
Point(9) = {c, -c, 0};
Point(12) = {-c, 0, 0};
Point(13) = {-W, 0, 0};
Point(14) = {-W, -c, 0};
Point(15) = {-W, -H, 0};
Point(16) = {-c, -H, 0};
Point(19) = {-c, -c, 0};
// right half
Line(1) = {1, 2};   // top
Line(2) = {2, 3};   // top
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};   // bottom
Line(6) = {6, 7};   // bottom
Line(7) = {7, 8};   // x = 0, inside
Line(8) = {8, 1};   // x = 0, inside
Line(9) = {2, 9};
Line(10) = {9, 8};
Line(11) = {9, 4};
Line(12) = {9, 6};
// left half
Line(21) = {12, 1};   // top
Line(22) = {13, 12};  // top
Line(23) = {14, 13};
Line(24) = {15, 14};
Line(25) = {16, 15};  // bottom
Line(26) = {7, 16};   // bottom
Line(29) = {19, 12};
Line(30) = {8, 19};
Line(31) = {14, 19};
Line(32) = {16, 19};
Curve Loop(1) = {1, 9, 10, 8};       Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, -11, -9};     Plane Surface(2) = {2};
Curve Loop(3) = {11, 4, 5, -12};     Plane Surface(3) = {3};
Curve Loop(4) = {-10, 12, 6, 7};     Plane Surface(4) = {4};
Curve Loop(5) = {-8, 30, 29, 21};    Plane Surface(5) = {5};
Curve Loop(6) = {22, -29, -31, 23};  Plane Surface(6) = {6};
Curve Loop(7) = {31, -32, 25, 24};   Plane Surface(7) = {7};
Curve Loop(8) = {-30, -7, 26, 32};   Plane Surface(8) = {8};
Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 21, 22, 23, 24, 25, 26, 29, 30, 31, 32} = 2;
Transfinite Surface{1, 2, 3, 4, 5, 6, 7, 8};
Mesh.RecombineAll = 1;
Physical Curve("top") = {22, 21, 1, 2};
Physical Curve("bottom") = {25, 26, 6, 5};
Physical Surface("block") = {1, 2, 3, 4, 5, 6, 7, 8};
