#include "nome/query/pick_edge.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace nome {
namespace {

double pixel_distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double length_squared = glm::dot(ab, ab);
  const double t = length_squared > 0 ? std::clamp(glm::dot(p - a, ab) / length_squared, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

}  // namespace

std::optional<EdgeId> nearest_edge_on_screen(const Mesh& mesh, FaceId face,
                                             const ScreenProjection& projection, glm::dvec2 cursor,
                                             double max_pixels) {
  std::optional<EdgeId> best;
  double best_distance = max_pixels;
  for (Index e : mesh.face_edges(face.index())) {
    const auto [u, w] = mesh.edge(e).vertices;
    const auto a = project_to_pixel(projection, mesh.position(u));
    const auto b = project_to_pixel(projection, mesh.position(w));
    if (!a || !b) continue;
    const double distance = pixel_distance_to_segment(cursor, glm::dvec2(*a), glm::dvec2(*b));
    if (distance <= best_distance) {
      best_distance = distance;
      best = EdgeId(e);
    }
  }
  return best;
}

std::optional<EdgeId> pick_edge(const Mesh& mesh, const TriangleBvh& bvh, const ScreenProjection& projection,
                                glm::dvec2 cursor, double max_pixels) {
  const auto hit = bvh.cast_nearest(ray_through_pixel(projection, cursor));
  if (!hit) return std::nullopt;
  return nearest_edge_on_screen(mesh, FaceId(hit->face), projection, cursor, max_pixels);
}

}  // namespace nome
