#include "app/screen_oracle.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace nome::test {
namespace {

constexpr double oracle_margin = 1.0;  // pixels by which the clicked element must win

// The corners and centre of the pixel square at p: a click there picks the same under either convention
// (pixel corner or pixel centre).
std::array<glm::dvec2, 5> oracle_samples(glm::dvec2 p) {
  return {p, p + glm::dvec2(1, 0), p + glm::dvec2(0, 1), p + glm::dvec2(1, 1), p + glm::dvec2(0.5)};
}

Vec3 oracle_face_centre(const Mesh& mesh, Index f) {
  Vec3 centre(0.0);
  for (Index v : mesh.face_vertices(f)) centre += mesh.position(v);
  return centre / double(mesh.face_degree(f));
}

double oracle_segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
  return glm::length(p - (a + t * ab));
}

// Möller and Trumbore's ray/triangle test: the ray parameter of the hit, if any.
std::optional<double> oracle_hit(const Vec3& origin, const Vec3& direction, const Vec3& a, const Vec3& b,
                                 const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 p = glm::cross(direction, ac);
  const double det = glm::dot(ab, p);
  if (std::abs(det) < 1e-300) return std::nullopt;
  const Vec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = glm::cross(s, ab);
  const double w = glm::dot(direction, q) / det;
  if (w < 0.0 || u + w > 1.0) return std::nullopt;
  const double t = glm::dot(ac, q) / det;
  return t > 0.0 ? std::optional(t) : std::nullopt;
}

bool oracle_has_vertex(const Mesh& mesh, Index f, Index v) {
  for (Index u : mesh.face_vertices(f))
    if (u == v) return true;
  return false;
}

std::vector<SeenFace> oracle_all_hits(const Mesh& mesh, const ScreenProjection& projection, glm::dvec2 at) {
  const auto [origin, direction] = sight_line(projection, at);
  std::vector<SeenFace> hits;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto corners = mesh.face_vertices(f);
    // Fan triangles from the face's centre: right for the convex and star-shaped faces tests click.
    const Vec3 centre = oracle_face_centre(mesh, f);
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const auto t = oracle_hit(origin, direction, centre, mesh.position(corners[i]),
                                mesh.position(corners[(i + 1) % corners.size()]));
      if (t) hits.push_back({f, *t});
    }
  }
  return hits;
}

// Whether every sample of the pixel at p sees only faces for which `wins` holds.
template <class Wins>
bool oracle_whole_pixel(const Mesh& mesh, const ScreenProjection& projection, glm::dvec2 p, Wins wins) {
  for (const glm::dvec2 s : oracle_samples(p)) {
    const std::vector<Index> seen = faces_seen_at(mesh, projection, s);
    if (seen.empty() || !std::all_of(seen.begin(), seen.end(), [&](Index f) { return wins(f, s); }))
      return false;
  }
  return true;
}

}  // namespace

std::optional<glm::dvec2> pixel_of(const ScreenProjection& projection, const Vec3& point) {
  const glm::dvec4 clip = projection.projection * projection.view * glm::dvec4(point, 1.0);
  if (clip.w <= 0.0) return std::nullopt;
  const double x = clip.x / clip.w, y = clip.y / clip.w;
  return projection.origin + glm::dvec2((x + 1.0) / 2.0, (1.0 - y) / 2.0) * projection.viewport;
}

SightLine sight_line(const ScreenProjection& projection, glm::dvec2 at) {
  const glm::dvec2 ndc =
      glm::dvec2(2.0, -2.0) * (at - projection.origin) / projection.viewport + glm::dvec2(-1.0, 1.0);
  const glm::dmat4 to_world = glm::inverse(projection.projection * projection.view);
  const glm::dvec4 eye_side = to_world * glm::dvec4(ndc, -1.0, 1.0);
  const glm::dvec4 far_side = to_world * glm::dvec4(ndc, 1.0, 1.0);
  const Vec3 origin = Vec3(eye_side) / eye_side.w;
  return {origin, glm::normalize(Vec3(far_side) / far_side.w - origin)};
}

bool is_in_sight(const Mesh& mesh, const ScreenProjection& projection, const Vec3& point, double slack) {
  const auto at = pixel_of(projection, point);
  if (!at) return false;
  const SightLine line = sight_line(projection, *at);
  const auto seen = face_seen_at(mesh, projection, *at);
  return !seen || seen->depth > glm::dot(point - line.origin, line.direction) - slack;
}

std::optional<SeenFace> face_seen_at(const Mesh& mesh, const ScreenProjection& projection, glm::dvec2 at) {
  std::optional<SeenFace> nearest;
  for (const SeenFace& hit : oracle_all_hits(mesh, projection, at))
    if (!nearest || hit.depth < nearest->depth) nearest = hit;
  return nearest;
}

std::vector<Index> faces_seen_at(const Mesh& mesh, const ScreenProjection& projection, glm::dvec2 at) {
  const auto nearest = face_seen_at(mesh, projection, at);
  std::vector<Index> tied;
  if (!nearest) return tied;
  for (const SeenFace& hit : oracle_all_hits(mesh, projection, at))
    if (hit.depth <= nearest->depth * (1 + 1e-7) + 1e-9 &&
        std::find(tied.begin(), tied.end(), hit.face) == tied.end())
      tied.push_back(hit.face);
  return tied;
}

std::optional<glm::dvec2> face_click(const Mesh& mesh, const ScreenProjection& projection, Index f) {
  const auto centre = pixel_of(projection, oracle_face_centre(mesh, f));
  if (!centre) return std::nullopt;
  const glm::dvec2 p = glm::floor(*centre);
  if (!oracle_whole_pixel(mesh, projection, p, [&](Index seen, glm::dvec2) { return seen == f; }))
    return std::nullopt;
  return p;
}

std::optional<glm::dvec2> vertex_click(const Mesh& mesh, const ScreenProjection& projection, Index v) {
  const auto at = pixel_of(projection, mesh.position(v));
  if (!at) return std::nullopt;
  const auto v_wins = [&](Index seen, glm::dvec2 s) {
    if (!oracle_has_vertex(mesh, seen, v)) return false;
    const double mine = glm::length(s - *at);
    for (Index u : mesh.face_vertices(seen)) {
      const auto other = pixel_of(projection, mesh.position(u));
      if (u != v && other && glm::length(s - *other) < mine + oracle_margin) return false;
    }
    return true;
  };
  for (Index c : mesh.vertex_corners(v)) {
    const auto inside = pixel_of(projection, oracle_face_centre(mesh, mesh.corner_face(c)));
    if (!inside || glm::length(*inside - *at) < 1e-9) continue;
    const glm::dvec2 p = glm::floor(*at + 3.0 * glm::normalize(*inside - *at));
    if (oracle_whole_pixel(mesh, projection, p, v_wins)) return p;
  }
  return std::nullopt;
}

std::optional<glm::dvec2> edge_click(const Mesh& mesh, const ScreenProjection& projection, Index e) {
  const auto [u, w] = mesh.edge(e).vertices;
  const auto a = pixel_of(projection, mesh.position(u));
  const auto b = pixel_of(projection, mesh.position(w));
  if (!a || !b) return std::nullopt;
  const auto e_wins = [&](Index seen, glm::dvec2 s) {
    if (!oracle_has_vertex(mesh, seen, u) || !oracle_has_vertex(mesh, seen, w)) return false;
    const double mine = oracle_segment_distance(s, *a, *b);
    const auto corners = mesh.face_vertices(seen);
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Index p = corners[i], q = corners[(i + 1) % corners.size()];
      if ((p == u && q == w) || (p == w && q == u)) continue;
      const auto pa = pixel_of(projection, mesh.position(p));
      const auto pb = pixel_of(projection, mesh.position(q));
      if (pa && pb && oracle_segment_distance(s, *pa, *pb) < mine + oracle_margin) return false;
    }
    return true;
  };
  const glm::dvec2 middle = 0.5 * (*a + *b);
  for (const Index f : mesh.edge(e).faces) {
    if (f == no_index) continue;
    const auto inside = pixel_of(projection, oracle_face_centre(mesh, f));
    if (!inside || glm::length(*inside - middle) < 1e-9) continue;
    const glm::dvec2 p = glm::floor(middle + 2.0 * glm::normalize(*inside - middle));
    if (oracle_whole_pixel(mesh, projection, p, e_wins)) return p;
  }
  return std::nullopt;
}

}  // namespace nome::test
