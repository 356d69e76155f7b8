#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "fuzz/fuzz_target.hpp"
#include "fuzz/polygon_soup_bytes.hpp"
#include "nome/error.hpp"
#include "nome/query/triangle_bvh.hpp"

// Random rays (the first six bytes: origin and direction) at a polygon soup (the rest): the BVH's nearest
// hit has the smallest depth the ray/triangle test gives over all triangles (to rounding), and its list of
// every hit names the same faces as that brute-force pass.
NOME_FUZZ_TARGET(pick) {
  if (size < 6) return 0;
  nome::Ray ray;
  for (int k = 0; k < 3; ++k) {
    ray.origin[k] = (int(data[k]) - 128) / 16.0;
    ray.direction[k] = (int(data[3 + k]) - 128) / 32.0;
  }
  if (ray.direction == nome::Vec3(0.0)) return 0;
  nome::Mesh mesh;
  try {
    mesh = nome::build_mesh(nome::fuzz::polygon_soup_from_bytes(data + 6, size - 6));
  } catch (const nome::TopologyError&) {
    return 0;
  }
  const nome::TriangleBvh bvh(mesh);
  const nome::ShearedRay sheared(ray);
  std::optional<double> nearest;
  std::set<nome::Index> faces;
  for (nome::Index t = 0; t < bvh.num_triangles(); ++t) {
    nome::TriangleHit hit;
    if (!nome::intersect_triangle(sheared, mesh.position(bvh.triangle_vertex(t, 0)),
                                  mesh.position(bvh.triangle_vertex(t, 1)),
                                  mesh.position(bvh.triangle_vertex(t, 2)), hit))
      continue;
    if (!nearest || hit.depth < *nearest) nearest = hit.depth;
    faces.insert(bvh.triangles().faces[t]);
  }
  const std::optional<nome::RayHit> found = bvh.cast_nearest(ray);
  // The tree may hold a triangle's corners in another order, which can round its depth one ulp apart
  // (coplanar triangles under a grazing ray found it): equal within 1e-12 relative.
  if (found.has_value() != nearest.has_value() ||
      (found && std::abs(found->depth - *nearest) > 1e-12 * std::max(1.0, std::abs(*nearest))))
    std::abort();
  std::set<nome::Index> all_faces;
  for (const nome::RayHit& hit : bvh.cast_all(ray)) all_faces.insert(hit.face);
  if (all_faces != faces) std::abort();
  return 0;
}
