#include "nome/query/rim_pick.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "nome/error.hpp"

namespace nome {

Index RimLines::add_line(std::span<const Vec3> points, std::span<const std::string> point_names, bool closed,
                         std::optional<Color> color) {
  if (points.size() != point_names.size())
    throw InvalidInputError("RimLines::add_line: " + std::to_string(points.size()) + " points and " +
                            std::to_string(point_names.size()) + " names");
  positions.insert(positions.end(), points.begin(), points.end());
  names.insert(names.end(), point_names.begin(), point_names.end());
  offsets.push_back(Index(positions.size()));
  is_closed.push_back(closed ? 1 : 0);
  colors.push_back(color);
  return num_lines() - 1;
}

std::vector<double> rim_cube_half_sizes(const RimLines& rims, double fraction) {
  std::vector<double> length(rims.num_vertices(), 0.0);
  std::vector<int> count(rims.num_vertices(), 0);
  double total = 0.0;
  int edges = 0;
  for (Index l = 0; l < rims.num_lines(); ++l) {
    const Index first = rims.offsets[l], n = rims.offsets[l + 1] - first;
    const Index segments = rims.is_closed[l] && n > 2 ? n : (n > 0 ? n - 1 : 0);
    for (Index i = 0; i < segments; ++i) {
      const Index a = first + i, b = first + (i + 1) % n;
      const double d = glm::length(rims.positions[a] - rims.positions[b]);
      for (Index v : {a, b}) {
        length[v] += d;
        ++count[v];
      }
      total += d;
      ++edges;
    }
  }
  const double fallback = edges > 0 ? total / edges : 1.0;
  std::vector<double> half(rims.num_vertices());
  for (Index v = 0; v < rims.num_vertices(); ++v)
    half[v] = fraction * (count[v] > 0 ? length[v] / count[v] : fallback);
  return half;
}

std::optional<RimHit> pick_rim_vertex(const RimLines& rims, std::span<const double> half_sizes,
                                      const Ray& ray) {
  if (half_sizes.size() != rims.positions.size())
    throw InvalidInputError("pick_rim_vertex: " + std::to_string(half_sizes.size()) + " sizes for " +
                            std::to_string(rims.positions.size()) + " rim vertices");
  std::optional<RimHit> best;
  for (Index v = 0; v < rims.num_vertices(); ++v) {
    double enter = ray.t_min, leave = ray.t_max;
    bool is_hit = true;
    for (int axis = 0; axis < 3 && is_hit; ++axis) {
      const double lower = rims.positions[v][axis] - half_sizes[v];
      const double upper = rims.positions[v][axis] + half_sizes[v];
      const double o = ray.origin[axis], d = ray.direction[axis];
      if (d == 0.0) {
        is_hit = o >= lower && o <= upper;
        continue;
      }
      double t0 = (lower - o) / d, t1 = (upper - o) / d;
      if (t0 > t1) std::swap(t0, t1);
      enter = std::max(enter, t0);
      leave = std::min(leave, t1);
      is_hit = enter <= leave;
    }
    if (is_hit && (!best || enter < best->depth)) best = RimHit{RimVertexId(v), enter};
  }
  return best;
}

std::optional<RimVertexId> pick_rim_vertex(const RimLines& rims, std::span<const double> half_sizes,
                                           const TriangleBvh& bvh, const ScreenProjection& projection,
                                           glm::dvec2 cursor) {
  if (rims.num_vertices() == 0) return std::nullopt;
  const Ray ray = ray_through_pixel(projection, cursor);
  const auto rim = pick_rim_vertex(rims, half_sizes, ray);
  if (!rim) return std::nullopt;
  if (const auto surface = bvh.cast_nearest(ray); surface && surface->depth < rim->depth) return std::nullopt;
  return rim->vertex;
}

}  // namespace nome
