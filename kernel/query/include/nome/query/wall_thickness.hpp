#pragma once

#include <optional>

#include "nome/mesh/mesh.hpp"
#include "nome/query/triangle_bvh.hpp"

namespace nome {

// The wall of a closed solid at a point of its surface.
struct WallMeasure {
  double thickness = 0.0;
  Vec3 from{0.0};  // the point measured from
  Vec3 to{0.0};    // where the line through the wall meets the surface again
};

// The local wall thickness at `point` on face `face` of a closed solid (an offset's slab): a ray is cast
// from the point both ways along the face's normal on the picking BVH; the way into the solid is the one
// that crosses the surface an odd number of times (a closed surface is crossed an even number of times
// on the way out), and its first crossing is the opposite wall. None for a mesh with borders (no inside),
// a degenerate face, or when neither way enters (a point not on the mesh).
std::optional<WallMeasure> wall_thickness(const Mesh& mesh, const TriangleBvh& bvh, Index face,
                                          const Vec3& point);

}  // namespace nome
