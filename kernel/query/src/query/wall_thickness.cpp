#include "nome/query/wall_thickness.hpp"

#include <glm/geometric.hpp>

#include "nome/mesh/normals.hpp"

namespace nome {

std::optional<WallMeasure> wall_thickness(const Mesh& mesh, const TriangleBvh& bvh, Index face,
                                          const Vec3& point) {
  if (face >= mesh.num_faces() || mesh.num_boundary_loops() > 0) return std::nullopt;
  const Vec3 area = face_area_normal(mesh, face);
  const double length = glm::length(area);
  if (!(length > 0.0)) return std::nullopt;
  const Vec3 n = area / length;
  // Hits closer than this are the start face itself (or its neighbours at a shared edge).
  const double skip = 1e-9 * (1.0 + glm::length(point)) + 1e-6 * std::sqrt(length);
  for (const double side : {-1.0, 1.0}) {
    Ray ray;
    ray.origin = point;
    ray.direction = side * n;
    ray.t_min = skip;
    const std::vector<RayHit> hits = bvh.cast_all(ray);
    if (hits.size() % 2 == 1)
      return WallMeasure{glm::distance(point, hits.front().point), point, hits.front().point};
  }
  return std::nullopt;
}

}  // namespace nome
