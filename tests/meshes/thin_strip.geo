// Deliberately elongated cells of known aspect ratio: the strip
// [-1/2, 1/2] x [-0.004, 0.004] in 5 x 1 rectangles of 0.2 x 0.008, whose
// ratio is 0.2 / 0.008 = 25 (tests/unit/cell_aspect_ratio.cc).
//   gmsh -2 -format msh22 thin_strip.geo -o thin_strip.msh
Point(1) = {-0.5, -0.004, 0};
west[] = Extrude {0, 0.008, 0} { Point{1}; Layers{1}; };
strip[] = Extrude {1, 0, 0} { Curve{west[1]}; Layers{5}; Recombine; };
Physical Curve("West") = {west[1]};
Physical Surface("Strip") = {strip[1]};
