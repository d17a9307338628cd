// The half x >= 0 of the plate [-1/2, 1/2]^2 as the built-in rectangle
// meshes it with Symmetry = half (5 x 10 equal quadrilaterals), turned by
// 30 degrees about the origin: its cut Plane (the turned line x = 0) is a
// symmetry plane along no axis (tests/verification/rotated_square.py).
// The other curves are East, South and North (the turned Right, Bottom
// and Top).
//   gmsh -2 -format msh22 half_rotated.geo -o half_rotated.msh
a = Pi / 6;
c = Cos(a);
s = Sin(a);
Point(1) = {0.5 * s, -0.5 * c, 0};
Point(2) = {0.5 * c + 0.5 * s, 0.5 * s - 0.5 * c, 0};
Point(3) = {0.5 * c - 0.5 * s, 0.5 * s + 0.5 * c, 0};
Point(4) = {-0.5 * s, 0.5 * c, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 6;
Transfinite Curve{2, 4} = 11;
Transfinite Surface{1} = {1, 2, 3, 4};
Recombine Surface{1};
Physical Curve("South") = {1};
Physical Curve("East") = {2};
Physical Curve("North") = {3};
Physical Curve("Plane") = {4};
Physical Surface("Plate") = {1};
