#pragma once

// Where a click lands, worked out in the test from the camera's matrices alone: its own projection and
// a brute-force ray cast over every face, sharing no code with the picking under test. Tests choose the
// pixels they click with these, so a picking bug makes the viewer pick something else and the test fail.

#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "nome/mesh/mesh.hpp"
#include "nome/query/screen_projection.hpp"

namespace nome::test {

// Window pixel position of a world point (origin top-left, y down); none behind the eye.
std::optional<glm::dvec2> pixel_of(const ScreenProjection& projection, const Vec3& point);

// The line of sight through a window position: from the near plane, a unit direction.
struct SightLine {
  Vec3 origin{0.0};
  Vec3 direction{0.0};
};
SightLine sight_line(const ScreenProjection& projection, glm::dvec2 at);

// Whether a point shows at its own pixel: no face lies in front of it by more than `slack`.
bool is_in_sight(const Mesh& mesh, const ScreenProjection& projection, const Vec3& point, double slack);

// The face nearest the eye under a window position and the depth of the hit along its sight line.
struct SeenFace {
  Index face = no_index;
  double depth = 0.0;
};
std::optional<SeenFace> face_seen_at(const Mesh& mesh, const ScreenProjection& projection, glm::dvec2 at);

// Every face whose hit under a window position is as near as the nearest one, up to rounding: a pick
// may take any of them (faces that coincide, or meet where the ray passes).
std::vector<Index> faces_seen_at(const Mesh& mesh, const ScreenProjection& projection, glm::dvec2 at);

// A window pixel (whole coordinates) whose whole square shows face f, near its centre.
std::optional<glm::dvec2> face_click(const Mesh& mesh, const ScreenProjection& projection, Index f);

// A window pixel, about three pixels from where vertex v projects, whose whole square shows a face at v
// with v its nearest corner on screen by at least a pixel.
std::optional<glm::dvec2> vertex_click(const Mesh& mesh, const ScreenProjection& projection, Index v);

// A window pixel beside the midpoint of edge e whose whole square shows a face of e with e its nearest
// edge on screen by at least a pixel.
std::optional<glm::dvec2> edge_click(const Mesh& mesh, const ScreenProjection& projection, Index e);

}  // namespace nome::test
