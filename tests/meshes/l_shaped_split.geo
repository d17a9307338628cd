// prm/l-shaped-slab.geo with its re-entrant edges tagged apart: ReX (y = 0,
// along x) and ReY (x = 0, along y), each held by components, against
// the one tag Re-entrant along neither axis (rotated_square.py).
//   gmsh -2 -format msh22 l_shaped_split.geo -o l_shaped_split.msh
n = 9; // nodes along each block's side
Point(1) = {-0.5, -0.5, 0};
Point(2) = {0, -0.5, 0};
Point(3) = {0.5, -0.5, 0};
Point(4) = {0.5, 0, 0};
Point(5) = {0, 0, 0};
Point(6) = {0, 0.5, 0};
Point(7) = {-0.5, 0.5, 0};
Point(8) = {-0.5, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 7};
Line(7) = {7, 8};
Line(8) = {8, 1};
Line(9) = {2, 5};
Line(10) = {5, 8};
Curve Loop(1) = {1, 9, 10, 8};
Curve Loop(2) = {2, 3, 4, -9};
Curve Loop(3) = {-10, 5, 6, 7};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Plane Surface(3) = {3};
Transfinite Curve {1:10} = n;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};
Physical Curve("Wall") = {7, 8};
Physical Curve("ReX") = {4};
Physical Curve("ReY") = {5};
Physical Curve("Free") = {1, 2, 3, 6};
Physical Surface("Slab") = {1, 2, 3};
