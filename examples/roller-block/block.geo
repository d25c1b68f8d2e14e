// Aluminium block of roller-block-gmsh.yaml: [0, W] x [-H, 0], the roller touching its top at
// S = (0, 0), symmetry line x = 0, held on its bottom. Four transfinite quad patches around the
// corner square [0, c] x [-c, 0] at S, coarse: the hp loop refines where the zone is.
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
Line(1) = {1, 2};   // top
Line(2) = {2, 3};   // top
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};   // bottom
Line(6) = {6, 7};   // bottom
Line(7) = {7, 8};   // symmetry
Line(8) = {8, 1};   // symmetry
Line(9) = {2, 9};
Line(10) = {9, 8};
Line(11) = {9, 4};
Line(12) = {9, 6};
Curve Loop(1) = {1, 9, 10, 8};      Plane Surface(1) = {1};  // the corner square at S
Curve Loop(2) = {2, 3, -11, -9};    Plane Surface(2) = {2};
Curve Loop(3) = {11, 4, 5, -12};    Plane Surface(3) = {3};
Curve Loop(4) = {-10, 12, 6, 7};    Plane Surface(4) = {4};
Transfinite Curve{1, 10, 6, 9, 8, 3, 12, 7, 11, 2, 4, 5} = 2;
Transfinite Surface{1, 2, 3, 4};
Mesh.RecombineAll = 1;
Physical Curve("top") = {1, 2};
Physical Curve("symmetry") = {7, 8};
Physical Curve("bottom") = {5, 6};
Physical Surface("block") = {1, 2, 3, 4};
