// A slab 5 m x 3 m in metres, centred at the origin, for scenes with
// Units/System = SI: 10 x 6 square cells of 0.5 m, numbered along x first
// as the built-in rectangle numbers them (Units/Length = 5, Width = 3,
// Discretization/Cells along x = 10, y = 6), by two extrusions as in
// square.geo. The edges are the physical curves West, East, South and
// North.
//   gmsh -2 -format msh22 slab_5x3m.geo -o slab_5x3m.msh
Point(1) = {-2.5, -1.5, 0};
west[] = Extrude {0, 3, 0} { Point{1}; Layers{6}; };
plate[] = Extrude {5, 0, 0} { Curve{west[1]}; Layers{10}; Recombine; };
Physical Curve("South") = {plate[3]};
Physical Curve("North") = {plate[2]};
Physical Curve("East") = {plate[0]};
Physical Curve("West") = {west[1]};
Physical Surface("Plate") = {plate[1]};
