// Test data of tests/cli/test_gmsh_profile.py; the .msh beside it is made by
//   gmsh -1 -format msh41 groove-housing.geo -o groove-housing.msh
// "housing": the housing of examples/o-ring/o-ring-profile-groove.yaml as Gmsh lines — a
// 1 mm x 45 degree chamfer at each edge of the groove's mouth, walls x = +-10.3, bottom y = 0
// (two lines meeting at x = 0, the second drawn right to left) — in elements of at most 2 mm.
// "box": a closed square loop; "branched": the housing with a stub at the bottom's middle;
// "walls": two lines that do not meet; "drawn back": the housing's lines drawn from right to left.
Point(1) = {-14, 20, 0};
Point(2) = {-11.3, 20, 0};
Point(3) = {-10.3, 19, 0};
Point(4) = {-10.3, 0, 0};
Point(5) = {0, 0, 0};
Point(6) = {10.3, 0, 0};
Point(7) = {10.3, 19, 0};
Point(8) = {11.3, 20, 0};
Point(9) = {14, 20, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {6, 5};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 9};
Point(10) = {-30, -30, 0};
Point(11) = {30, -30, 0};
Point(12) = {30, 30, 0};
Point(13) = {-30, 30, 0};
Line(9) = {10, 11};
Line(10) = {11, 12};
Line(11) = {12, 13};
Line(12) = {13, 10};
Point(14) = {0, -5, 0};
Line(13) = {5, 14};
// The housing drawn again from its right end to its left: its first line runs from (14, 20).
Line(14) = {9, 8};
Line(15) = {8, 7};
Line(16) = {7, 6};
Line(17) = {6, 4};
Line(18) = {4, 3};
Line(19) = {3, 2};
Line(20) = {2, 1};
Physical Curve("housing") = {1, 2, 3, 4, 5, 6, 7, 8};
Physical Curve("walls") = {3, 6};
Physical Curve("box") = {9, 10, 11, 12};
Physical Curve("branched") = {1, 2, 3, 4, 5, 6, 7, 8, 13};
Physical Curve("drawn back") = {14, 15, 16, 17, 18, 19, 20};
Mesh.CharacteristicLengthMax = 2;
