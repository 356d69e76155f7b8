#include "nome/query/print_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "nome/error.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/query/fold_overs.hpp"
#include "support/union_find.hpp"

namespace nome {
namespace {

Vec3 face_centroid(const Mesh& mesh, Index f) {
  Vec3 sum(0.0);
  for (const Index v : mesh.face_vertices(f)) sum += mesh.position(v);
  return sum / double(mesh.face_degree(f));
}

// Fold-over faces joined across shared edges: one place per patch, at its first face.
void add_fold_over_places(const Mesh& mesh, const std::vector<Index>& faces, std::vector<PrintPlace>& out) {
  std::vector<char> folded(mesh.num_faces(), 0);
  for (const Index f : faces) folded[f] = 1;
  UnionFind sets(mesh.num_faces());
  for (const Index f : faces)
    for (const Index e : mesh.face_edges(f))
      if (const Index g = mesh.edge(e).other_face(f); g != no_index && folded[g]) sets.unite(f, g);
  std::vector<Index> place_of_root(mesh.num_faces(), no_index);
  const std::size_t first = out.size();
  for (const Index f : faces) {
    Index& place = place_of_root[sets.find(f)];
    if (place == no_index) {
      place = Index(out.size() - first);
      out.push_back({FindingKind::fold_over, face_centroid(mesh, f), f, no_index, 0.0, 0});
    }
    ++out[first + place].size;
  }
  std::stable_sort(out.begin() + std::ptrdiff_t(first), out.end(),
                   [](const PrintPlace& a, const PrintPlace& b) { return a.size > b.size; });
}

// Near-miss vertices joined along edges: one place per patch, at its thinnest vertex.
void add_near_miss_places(const Mesh& mesh, const std::vector<NearMiss>& misses,
                          std::vector<PrintPlace>& out) {
  std::vector<Index> miss_of_vertex(mesh.num_vertices(), no_index);
  for (Index i = 0; i < misses.size(); ++i) miss_of_vertex[misses[i].vertex] = i;
  UnionFind sets(Index(misses.size()));
  for (Index i = 0; i < misses.size(); ++i)
    for (const Index e : mesh.vertex_edges(misses[i].vertex))
      if (const Index j = miss_of_vertex[mesh.edge(e).other_vertex(misses[i].vertex)]; j != no_index)
        sets.unite(i, j);
  std::vector<Index> place_of_root(misses.size(), no_index);
  const std::size_t first = out.size();
  for (Index i = 0; i < misses.size(); ++i) {
    const NearMiss& m = misses[i];
    Index& place = place_of_root[sets.find(i)];
    if (place == no_index) {
      place = Index(out.size() - first);
      out.push_back({FindingKind::near_miss, {}, no_index, no_index, m.distance + 1.0, 0});
    }
    PrintPlace& p = out[first + place];
    ++p.size;
    if (m.distance < p.distance) {
      p.position = mesh.position(m.vertex);
      p.face = mesh.corner_face(mesh.vertex_corners(m.vertex)[0]);
      p.other_face = m.face;
      p.distance = m.distance;
    }
  }
  std::stable_sort(out.begin() + std::ptrdiff_t(first), out.end(),
                   [](const PrintPlace& a, const PrintPlace& b) { return a.distance < b.distance; });
}

// One place per crossing curve, at the middle of its first piece, longest (most pairs) first.
void add_crossing_places(const Crossings& crossings, std::vector<PrintPlace>& out) {
  const std::size_t first = out.size();
  std::vector<Index> place_of_curve(crossings.curves, no_index);
  for (Index i = 0; i < crossings.pairs.size(); ++i) {
    const Crossing& c = crossings.pairs[i];
    Index& place = place_of_curve[crossings.curve_of_pair[i]];
    if (place == no_index) {
      place = Index(out.size() - first);
      out.push_back(
          {FindingKind::crossing, (c.segment.from + c.segment.to) / 2.0, c.face, c.other_face, 0.0, 0});
    }
    ++out[first + place].size;
  }
  std::stable_sort(out.begin() + std::ptrdiff_t(first), out.end(),
                   [](const PrintPlace& a, const PrintPlace& b) { return a.size > b.size; });
}

void require_length(const char* what, double value) {
  if (!(value >= 0.0) || !std::isfinite(value))
    throw InvalidInputError(std::string("check_printability: the ") + what +
                            " must be zero or positive and finite, got " + std::to_string(value));
}

}  // namespace

PrintCheck check_printability(const Mesh& surface, const PrintCheckOptions& options) {
  require_length("offset distance", options.offset_distance);
  require_length("minimum wall", options.min_wall);
  PrintCheck check;
  check.offset_distance = options.offset_distance;
  check.min_wall = options.min_wall > 0.0 ? options.min_wall : 2.0 * options.offset_distance;
  const Progress& progress = options.progress;
  progress("print check", 0.0);
  if (check.offset_distance > 0.0)
    check.fold_over_faces =
        find_fold_overs(surface, compute_normals(surface), check.offset_distance, options.threads);
  progress("print check", 0.1);
  BvhOptions bvh_options;
  if (options.threads < 2) bvh_options.parallel_build_threshold = no_index;
  const TriangleBvh bvh(surface, bvh_options);
  progress("print check", 0.25);
  check.crossings = find_crossings(surface, bvh, options.threads);
  progress("print check", 0.5);
  NearMissOptions near;
  near.min_wall = check.min_wall;
  near.threads = options.threads;
  if (!check.crossings.faces.empty())
    near.near_crossing = vertices_near_faces(surface, check.crossings.faces, 3.0 * check.min_wall);
  check.near_misses = find_near_misses(surface, bvh, near);
  progress("print check", 1.0);
  add_fold_over_places(surface, check.fold_over_faces, check.places);
  add_near_miss_places(surface, check.near_misses, check.places);
  add_crossing_places(check.crossings, check.places);
  return check;
}

const char* to_string(FindingKind kind) {
  switch (kind) {
    case FindingKind::fold_over:
      return "fold-over";
    case FindingKind::near_miss:
      return "near miss";
    case FindingKind::crossing:
      break;
  }
  return "crossing";
}

}  // namespace nome
