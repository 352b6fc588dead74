// A steel can 40 mm across and 60 mm tall, tilted 20 degrees about the y axis, as an
// OpenCASCADE solid; abut meshes it with tetrahedra as it reads can_drop.k (*INCLUDE_GMSH). The
// lowest point of its bottom rim is at z = 0.5 mm. The physical volume "can" is part 1.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 60, 20};
Rotate {{0, 1, 0}, {0, 0, 0}, 20 * Pi / 180} { Volume{1}; }
Translate {0, 0, 0.5 + 20 * Sin(20 * Pi / 180)} { Volume{1}; }
Physical Volume("can", 1) = {1};
