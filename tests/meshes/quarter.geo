// The quarter [0, 1/2]^2 of the plate [-1/2, 1/2]^2 as the built-in
// rectangle meshes it with Discretization/Symmetry = quarter (Cells along
// x = Cells along y = 10): 10 x 10 equal quadrilaterals, numbered along x
// first. Its edges on the symmetry planes are the physical curves "Plane
// x" (x = 0) and "Plane y" (y = 0), its plate edges "Edge x" (x = 1/2)
// and "Edge y" (y = 1/2).
//   gmsh -2 -format msh22 quarter.geo -o quarter.msh
Point(1) = {0, 0, 0};
plane_x[] = Extrude {0, 0.5, 0} { Point{1}; Layers{10}; };
part[] = Extrude {0.5, 0, 0} { Curve{plane_x[1]}; Layers{10}; Recombine; };
// part[]: the curve x = 1/2, the surface, then the curves swept by the
// end points of the curve x = 0 (y = 1/2, then y = 0).
Physical Curve("Plane x") = {plane_x[1]};
Physical Curve("Plane y") = {part[3]};
Physical Curve("Edge x") = {part[0]};
Physical Curve("Edge y") = {part[2]};
Physical Surface("Quarter") = {part[1]};
