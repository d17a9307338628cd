// The plate [-1/2, 1/2]^2 meshed as the built-in rectangle by default
// (10 x 10 equal quadrilaterals) turned by 30 degrees about the origin:
// its edges lie along no axis, so hard simple support on them holds a
// projection of the rotation (tests/verification/rotated_square.py). The
// physical curves West, East, South and North are the turned Left,
// Right, Bottom and Top.
//   gmsh -2 -format msh22 square_rotated.geo -o square_rotated.msh
a = Pi / 6;
c = Cos(a);
s = Sin(a);
Point(1) = {-0.5 * c + 0.5 * s, -0.5 * s - 0.5 * c, 0};
Point(2) = {0.5 * c + 0.5 * s, 0.5 * s - 0.5 * c, 0};
Point(3) = {0.5 * c - 0.5 * s, 0.5 * s + 0.5 * c, 0};
Point(4) = {-0.5 * c - 0.5 * s, -0.5 * s + 0.5 * c, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 11;
Transfinite Surface{1} = {1, 2, 3, 4};
Recombine Surface{1};
Physical Curve("South") = {1};
Physical Curve("East") = {2};
Physical Curve("North") = {3};
Physical Curve("West") = {4};
Physical Surface("Plate") = {1};
