#include "nome/query/pick.hpp"

#include <glm/geometric.hpp>

namespace nome {

std::optional<VertexId> nearest_corner_on_screen(const Mesh& mesh, FaceId face,
                                                 const ScreenProjection& projection, glm::dvec2 cursor,
                                                 double max_pixels) {
  std::optional<VertexId> best;
  double best_distance = max_pixels;
  for (Index v : mesh.face_vertices(face.index())) {
    const auto pixel = project_to_pixel(projection, mesh.position(v));
    if (!pixel) continue;
    const double distance = glm::length(glm::dvec2(*pixel) - cursor);
    if (distance <= best_distance) {
      best_distance = distance;
      best = VertexId(v);
    }
  }
  return best;
}

std::optional<VertexId> pick_vertex(const Mesh& mesh, const TriangleBvh& bvh,
                                    const ScreenProjection& projection, glm::dvec2 cursor,
                                    double max_pixels) {
  const auto hit = bvh.cast_nearest(ray_through_pixel(projection, cursor));
  if (!hit) return std::nullopt;
  return nearest_corner_on_screen(mesh, FaceId(hit->face), projection, cursor, max_pixels);
}

std::optional<FaceId> pick_face(const TriangleBvh& bvh, const ScreenProjection& projection,
                                glm::dvec2 cursor) {
  const auto hit = bvh.cast_nearest(ray_through_pixel(projection, cursor));
  if (!hit) return std::nullopt;
  return FaceId(hit->face);
}

}  // namespace nome
