// A mesh of 8 x 8 squares (128 triangles), which lumen traces through its own BVH (mesh.pov).
#declare N = 8;
#include "mesh.pov"
