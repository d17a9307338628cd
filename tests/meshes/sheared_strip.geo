// Parallelograms of known aspect ratio: 5 cells with the edges
// a = (0.2, 0) and b = (0.3, 0.01), the strip between y = -0.005 and
// 0.005 sheared by 0.3. The Jacobian of each cell's map from the unit
// square is [a b], whose singular values s1 >= s2 have s1 s2 = 0.002 and
// s1^2 + s2^2 = 0.1301 (tests/unit/cell_aspect_ratio.cc).
//   gmsh -2 -format msh22 sheared_strip.geo -o sheared_strip.msh
Point(1) = {-0.65, -0.005, 0};
west[] = Extrude {0.3, 0.01, 0} { Point{1}; Layers{1}; };
strip[] = Extrude {1, 0, 0} { Curve{west[1]}; Layers{5}; Recombine; };
Physical Curve("West") = {west[1]};
Physical Surface("Strip") = {strip[1]};
