#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/query/triangle_bvh.hpp"

namespace nome {

// A vertex closer than the minimum wall to another sheet of the surface.
struct NearMiss {
  Index vertex = no_index;
  Index face = no_index;  // the face of the other sheet holding the nearest point
  Vec3 point{0.0};        // that nearest point
  double distance = 0.0;
};

struct NearMissOptions {
  double min_wall = 0.0;  // 0: no test
  // Vertices within 3 x min_wall (along edges) of a face in a crossing are not tested: there the sheets
  // meet by design (one per vertex, or empty).
  std::vector<char> near_crossing;
  int threads = 1;
};

// For each vertex, the nearest point of the surface outside its neighbourhood (the points closer along the
// surface than 3 x min_wall, by Dijkstra on edges), reported when it is closer than min_wall. The
// vertices are grouped into patches of radius 3/4 min_wall that share one box query and one search from
// their seed; a vertex whose answer the shared search leaves open gets a search of its own.
// In vertex order.
std::vector<NearMiss> find_near_misses(const Mesh& surface, const TriangleBvh& bvh,
                                       const NearMissOptions& options);

// Per vertex: 1 when it lies within `radius` along the edges of a vertex of one of `faces`.
std::vector<char> vertices_near_faces(const Mesh& surface, const std::vector<Index>& faces, double radius);

}  // namespace nome
