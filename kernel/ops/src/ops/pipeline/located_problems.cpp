#include "ops/pipeline/located_problems.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <utility>

#include <glm/geometric.hpp>

namespace nome {
namespace {

// "file:line:col: " of the statement that made face f, or "" when unknown.
std::string origin_prefix(const PolygonSoup& soup, Index f) {
  const std::string& where = soup.origin(f);
  return where.empty() ? std::string() : where + ": ";
}

// How close two corners must be to coincide: a billionth of the scene's size (rounding of generated
// points that should be one, not a small feature).
double coincidence_distance(const Mesh& mesh) {
  if (mesh.num_vertices() == 0) return 0;
  Vec3 low = mesh.position(0), high = low;
  for (const Vec3& p : mesh.positions()) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  return 1e-9 * glm::length(high - low);
}

double squared_distance(const Mesh& mesh, Index a, Index b) {
  const Vec3 d = mesh.position(a) - mesh.position(b);
  return glm::dot(d, d);
}

// Two corners of the face closer than sqrt(limit): all pairs in small faces, neighbours only in large ones
// (a sampled circle), to stay linear. Quads, most faces, compare their six pairs without branching.
std::optional<std::pair<Index, Index>> coinciding_pair(const Mesh& mesh, std::span<const Index> corners,
                                                       double limit) {
  const size_t n = corners.size();
  if (n == 4) {
    const Index a = corners[0], b = corners[1], c = corners[2], d = corners[3];
    const double nearest =
        std::min({squared_distance(mesh, a, b), squared_distance(mesh, a, c), squared_distance(mesh, a, d),
                  squared_distance(mesh, b, c), squared_distance(mesh, b, d), squared_distance(mesh, c, d)});
    if (nearest > limit) return std::nullopt;
  }
  for (size_t i = 0; i < n; ++i) {
    if (n > 32) {
      if (squared_distance(mesh, corners[i], corners[(i + 1) % n]) <= limit)
        return std::pair{corners[i], corners[(i + 1) % n]};
      continue;
    }
    for (size_t j = i + 1; j < n; ++j)
      if (squared_distance(mesh, corners[i], corners[j]) <= limit) return std::pair{corners[i], corners[j]};
  }
  return std::nullopt;
}

}  // namespace

std::optional<TopologyError> located_error(const TopologyError& error, const PolygonSoup& soup) {
  bool is_located = false;
  std::string text;
  for (const TopologyError::Problem& p : error.problems()) {
    const std::string where = p.face < soup.num_faces() ? origin_prefix(soup, p.face) : std::string();
    is_located = is_located || !where.empty();
    text += (text.empty() ? "" : "\n") + where + (where.empty() ? "build_mesh: " : "") +
            "not a 2-manifold: " + p.text;
  }
  if (!is_located) return std::nullopt;
  return TopologyError(text, error.problems());
}

std::vector<std::string> coinciding_vertex_warnings(const Mesh& mesh, const PolygonSoup& soup,
                                                    size_t max_listed) {
  const double distance = coincidence_distance(mesh), limit = distance * distance;
  std::vector<std::string> out;
  size_t count = 0;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const std::optional<std::pair<Index, Index>> pair = coinciding_pair(mesh, mesh.face_vertices(f), limit);
    if (!pair) continue;
    if (++count <= max_listed)
      out.push_back((soup.origin(f).empty() ? "scene: " : origin_prefix(soup, f)) + "face " +
                    mesh.face_label(f) + " has coinciding vertices " + mesh.vertex_label(pair->first) +
                    " and " + mesh.vertex_label(pair->second) +
                    " (no normal there: its offset and shading are undefined)");
  }
  if (count > max_listed)
    out.push_back("scene: and " + std::to_string(count - max_listed) +
                  " more faces with coinciding vertices");
  return out;
}

}  // namespace nome
