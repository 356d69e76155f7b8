#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "nome/id.hpp"
#include "nome/mesh/types.hpp"
#include "nome/query/ray.hpp"
#include "nome/query/screen_projection.hpp"
#include "nome/query/triangle_bvh.hpp"

namespace nome {

// A vertex of the rim lines (into RimLines::positions): no mesh vertex.
using RimVertexId = Id<struct RimVertexKind>;

// Rim lines (report 6.3: `polyline`, `circle`; vertices that no face uses) as picking sees them: the
// positions and names of their vertices, each line a run of them, open or closed.
struct RimLines {
  std::vector<Vec3> positions;
  std::vector<std::string> names;
  std::vector<Index> offsets{0};  // line l holds vertices [offsets[l], offsets[l + 1])
  std::vector<unsigned char> is_closed;
  std::vector<std::optional<Color>> colors;  // per line: its surface's colour, if it has one

  Index num_lines() const { return Index(offsets.size() - 1); }
  Index num_vertices() const { return Index(positions.size()); }
  // Appends a line; returns its index.
  Index add_line(std::span<const Vec3> points, std::span<const std::string> point_names, bool closed,
                 std::optional<Color> color = std::nullopt);
};

// Half the edge of each rim vertex's cube: the report draws "a cube around every vertex, proportional
// to the average length of edges connected to this vertex" so that a line can be clicked. A line of one
// vertex takes the mean edge length of all lines (1 when there is none).
std::vector<double> rim_cube_half_sizes(const RimLines& rims, double fraction = 0.2);

// Where a ray enters a rim vertex's cube.
struct RimHit {
  RimVertexId vertex;
  double depth = 0.0;  // ray parameter t, comparable with RayHit::depth
};

// The rim vertex whose cube (axis-aligned, centred on the vertex) the ray enters first, by the slab
// test on each cube in turn: rim lines have few vertices, so no tree is built.
std::optional<RimHit> pick_rim_vertex(const RimLines& rims, std::span<const double> half_sizes,
                                      const Ray& ray);

// A click's rim vertex: the one whose cube the ray through the cursor enters first, unless the surface
// drawn with `bvh` lies in front of it.
std::optional<RimVertexId> pick_rim_vertex(const RimLines& rims, std::span<const double> half_sizes,
                                           const TriangleBvh& bvh, const ScreenProjection& projection,
                                           glm::dvec2 cursor);

}  // namespace nome
