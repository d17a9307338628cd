// A convex quadrilateral plate in 5 x 4 skewed quadrilaterals (transfinite,
// recombined), for the clipping of loads by cells that are not rectangles
// (test clipped_cells). Physical curves: "Bottom" (y from -0.4 to -0.5),
// "Others" (the other three edges).
//   gmsh -2 -format msh22 skewed.geo -o skewed.msh
Point(1) = {-0.5, -0.4, 0};
Point(2) = {0.5, -0.5, 0};
Point(3) = {0.4, 0.5, 0};
Point(4) = {-0.45, 0.35, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 6;
Transfinite Curve{2, 4} = 5;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("Bottom") = {1};
Physical Curve("Others") = {2, 3, 4};
Physical Surface("Plate") = {1};
