#pragma once

#include <optional>

#include "nome/mesh/ids.hpp"
#include "nome/query/screen_projection.hpp"
#include "nome/query/triangle_bvh.hpp"

namespace nome {

// The corner of face f nearest to the cursor on screen, if it lies within max_pixels of it (report
// 7.3.2: vertex selection extends face selection).
std::optional<VertexId> nearest_corner_on_screen(const Mesh& mesh, FaceId face,
                                                 const ScreenProjection& projection, glm::dvec2 cursor,
                                                 double max_pixels);

// A click's vertex: the nearest corner of the frontmost face under the cursor within max_pixels.
std::optional<VertexId> pick_vertex(const Mesh& mesh, const TriangleBvh& bvh,
                                    const ScreenProjection& projection, glm::dvec2 cursor, double max_pixels);

// A click's face: the frontmost face under the cursor.
std::optional<FaceId> pick_face(const TriangleBvh& bvh, const ScreenProjection& projection,
                                glm::dvec2 cursor);

}  // namespace nome
