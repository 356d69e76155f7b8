#pragma once

#include "nome/scene/piece.hpp"

namespace nome::scene {

// Disk (JIPCAD): the disk of radius `radius` in z = 0, or its wedge from theta = 0 (+x) to theta_max
// degrees, as `theta_segs` triangles around the vertex `centre` (rim vertices v{i}_0, faces f{i}_0
// facing +z). A whole turn shares its seam: one disk, chi 1, one border.
struct DiskParams {
  double radius = 1, theta_max = 360;
  int theta_segs = 16;
};
Piece disk(const DiskParams& p);

}  // namespace nome::scene
