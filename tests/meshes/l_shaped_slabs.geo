// prm/l-shaped-slab.geo as three slabs: its blocks A = [-1/2, 0]^2,
// B = [0, 1/2] x [-1/2, 0] and C = [-1/2, 0] x [0, 1/2] (physical surfaces
// A, B, C: slabs 1, 2, 3), each meshed on its own with 8 x 8 cells, with
// the nodes of both sides of a joint at the same places: J1 (x = 0, A|B)
// and J2 (y = 0, A|C). Wall, Re-entrant and Free as in l-shaped-slab.geo.
//   gmsh -2 -format msh22 l_shaped_slabs.geo -o l_shaped_slabs.msh
Geometry.AutoCoherence = 0;
n = 9; // nodes along each block's side
Point(1) = {-0.5, -0.5, 0};
Point(2) = {0, -0.5, 0};
Point(3) = {0, 0, 0};
Point(4) = {-0.5, 0, 0};
Point(5) = {0, -0.5, 0};
Point(6) = {0.5, -0.5, 0};
Point(7) = {0.5, 0, 0};
Point(8) = {0, 0, 0};
Point(9) = {-0.5, 0, 0};
Point(10) = {0, 0, 0};
Point(11) = {0, 0.5, 0};
Point(12) = {-0.5, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 5};
Line(9) = {9, 10};
Line(10) = {10, 11};
Line(11) = {11, 12};
Line(12) = {12, 9};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Curve Loop(3) = {9, 10, 11, 12};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Plane Surface(3) = {3};
Transfinite Curve {1:12} = n;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};
Physical Curve("Wall") = {4, 12};
Physical Curve("Re-entrant") = {7, 10};
Physical Curve("Free") = {1, 5, 6, 11};
Physical Curve("J1") = {2, 8};
Physical Curve("J2") = {3, 9};
Physical Surface("A") = {1};
Physical Surface("B") = {2};
Physical Surface("C") = {3};
