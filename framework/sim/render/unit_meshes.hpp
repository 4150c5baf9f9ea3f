// Triangle meshes of the unit primitives the off-screen renderer scales into boxes,
// cylinders, capsules and spheres (the objects on the simulated table, paper Sec. IV-A,
// and the rope nodes, Sec. IV-C). Tessellated once per renderer and cached on the GPU side.
//
// Every mesh is a triangle list (vertices 3k, 3k+1, 3k+2 form triangle k), wound
// counter-clockwise seen from outside, with one unit normal per vertex: the face
// normal on flat faces, the exact surface normal on curved ones (smooth shading).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace corrmp {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;
};

// Cube [-1, 1]^3: 12 triangles.
TriangleMesh unit_box_mesh();

// Closed cylinder of radius 1 between z = -1 and z = 1 with `segments` sides.
TriangleMesh unit_cylinder_mesh(int segments);

// The side of unit_cylinder_mesh without the caps.
TriangleMesh unit_tube_mesh(int segments);

// Unit sphere: `segments` meridians and max(2, segments / 2) latitude bands.
TriangleMesh unit_sphere_mesh(int segments);

// The z >= 0 half of the unit sphere, open at z = 0: max(1, segments / 4) bands.
TriangleMesh unit_hemisphere_mesh(int segments);

}  // namespace corrmp
