// A mesh that liftoff refuses: the square [-1/2, 1/2]^2 in triangles
// (tests/bad_input/mesh_file_triangles.prm).
//   gmsh -2 -format msh22 triangles.geo -o triangles.msh
Point(1) = {-0.5, -0.5, 0};
west[] = Extrude {0, 1, 0} { Point{1}; Layers{2}; };
plate[] = Extrude {1, 0, 0} { Curve{west[1]}; Layers{2}; };
Physical Curve("West") = {west[1]};
Physical Surface("Plate") = {plate[1]};
