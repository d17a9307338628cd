// The plate [-1/2, 1/2]^2 as the built-in rectangle meshes it by default
// (Discretization/Cells along x = Cells along y = 10): 10 x 10 equal
// quadrilaterals, numbered along x first as deal.II's rectangle numbers
// them, by two extrusions in 10 layers (which place the nodes at the
// rectangle's coordinates to round-off). The edges are the physical
// curves West, East, South and North (Left, Right, Bottom and Top of the
// rectangle).
//   gmsh -2 -format msh22 square.geo -o square.msh
Point(1) = {-0.5, -0.5, 0};
west[] = Extrude {0, 1, 0} { Point{1}; Layers{10}; };
plate[] = Extrude {1, 0, 0} { Curve{west[1]}; Layers{10}; Recombine; };
// plate[]: the east curve, the surface, then the curves swept by the west
// curve's end points (the north and the south edges).
Physical Curve("South") = {plate[3]};
Physical Curve("North") = {plate[2]};
Physical Curve("East") = {plate[0]};
Physical Curve("West") = {west[1]};
Physical Surface("Plate") = {plate[1]};
