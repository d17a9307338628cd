// The plate [-1/2, 1/2]^2 as two slabs 1/2 wide, [-1/2, 0] and [0, 1/2]
// (physical surfaces "West slab" and "East slab", slabs 1 and 2), each of
// 5 x 10 equal quadrilaterals (the rectangle's Cells along x = y = 10),
// meshed on their own: each has its nodes on x = 0, at the same places.
// The two curves on x = 0 are the physical curve "Joint"; the outer edges
// are West, East, South and North.
//   gmsh -2 -format msh22 two_slabs.geo -o two_slabs.msh
Geometry.AutoCoherence = 0;
Point(1) = {-0.5, -0.5, 0};
Point(2) = {0, -0.5, 0};
Point(3) = {0, 0.5, 0};
Point(4) = {-0.5, 0.5, 0};
Point(5) = {0, -0.5, 0};
Point(6) = {0.5, -0.5, 0};
Point(7) = {0.5, 0.5, 0};
Point(8) = {0, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Transfinite Curve {1, 3, 5, 7} = 6;
Transfinite Curve {2, 4, 6, 8} = 11;
Transfinite Surface {1, 2};
Recombine Surface {1, 2};
Physical Curve("West") = {4};
Physical Curve("East") = {6};
Physical Curve("South") = {1, 5};
Physical Curve("North") = {3, 7};
Physical Curve("Joint") = {2, 8};
Physical Surface("West slab") = {1};
Physical Surface("East slab") = {2};
