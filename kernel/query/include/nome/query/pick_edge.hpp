#pragma once

#include <optional>

#include "nome/mesh/ids.hpp"
#include "nome/query/screen_projection.hpp"
#include "nome/query/triangle_bvh.hpp"

namespace nome {

// The edge of face f nearest to the cursor on screen (distance to the projected segment), if within
// max_pixels of it.
std::optional<EdgeId> nearest_edge_on_screen(const Mesh& mesh, FaceId face,
                                             const ScreenProjection& projection, glm::dvec2 cursor,
                                             double max_pixels);

// A click's edge: the nearest edge of the frontmost face under the cursor, within max_pixels.
std::optional<EdgeId> pick_edge(const Mesh& mesh, const TriangleBvh& bvh, const ScreenProjection& projection,
                                glm::dvec2 cursor, double max_pixels);

}  // namespace nome
