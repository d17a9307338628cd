// A mesh that liftoff refuses: a cube of hexahedra, a 3D mesh
// (tests/bad_input/mesh_file_3d.prm).
//   gmsh -3 -format msh22 cube.geo -o cube.msh
Point(1) = {-0.5, -0.5, 0};
west[] = Extrude {0, 1, 0} { Point{1}; Layers{2}; };
plate[] = Extrude {1, 0, 0} { Curve{west[1]}; Layers{2}; Recombine; };
cube[] = Extrude {0, 0, 1} { Surface{plate[1]}; Layers{2}; Recombine; };
Physical Surface("Bottom") = {plate[1]};
Physical Volume("Cube") = {cube[1]};
