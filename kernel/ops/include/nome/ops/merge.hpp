#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

struct MergeOptions {
  // Absolute distance within which two end points match; 0 or less means relative_tolerance times the
  // diagonal of the bounding box of all vertices.
  double tolerance = 0.0;
  double relative_tolerance = 1e-3;
};

enum class MergeSkipReason {
  third_face_on_edge,       // the glued edge, or an edge at a glued vertex, would have three faces
  vertex_repeated_in_face,  // a face would visit the merged vertex twice
  edge_would_collapse,      // both ends of one edge would become one vertex
};

// A pair of matching boundary edges that was left apart because gluing it would not give a 2-manifold.
struct SkippedMerge {
  MergeSkipReason reason;
  std::array<Index, 2> edges;  // the two boundary edges of the input mesh
  std::array<Vec3, 2> ends;    // the end points of the first edge
  std::string message;         // the edges by vertex name and position, and why, for users
};

// Which vertices a merge joins, decided before the merged mesh is built: after a move of the vertices a
// caller holding the merged mesh compares plans, and only a different plan needs a new mesh.
struct MergePlan {
  std::vector<Index> vertex_map;  // input vertex -> merged vertex (numbered by its lowest member)
  Index num_vertices = 0;         // of the merged mesh
  double tolerance = 0.0;         // the absolute tolerance used
  std::vector<SkippedMerge> skipped;
};

struct MergeResult {
  Mesh mesh;
  std::vector<Index> vertex_map;  // input vertex -> vertex of `mesh`
  Index glued_edges = 0;          // pairs of boundary edges that became one edge
  double tolerance = 0.0;         // the absolute tolerance used
  std::vector<SkippedMerge> skipped;
};

// Automatic boundary merge (Wang 2016, section 3.3): boundary edges whose end points lie within the
// tolerance, in either direction, are glued; the vertices so paired form a graph whose connected
// components each become one vertex (at their mean position). A pair whose faces run the same way
// along the edge becomes a Möbius edge. Vertices that only touch at a point are not merged. Pairs are
// glued closest first; one that would break the 2-manifold property is skipped and reported. Names,
// colours and sharp marks are kept; the merged vertex takes the name of its lowest-numbered member.
// Candidate pairs come from a spatial hash grid: O(n) expected in the number of boundary vertices.
MergeResult merge_boundaries(const Mesh& mesh, const MergeOptions& options = {});

// The matching and gluing decisions of merge_boundaries, without the merged mesh.
MergePlan plan_merge(const Mesh& mesh, const MergeOptions& options = {});
// The merged mesh of a plan made for `mesh` (merge_boundaries is plan_merge, then this).
MergeResult merge_by_plan(const Mesh& mesh, MergePlan plan);
// The merged vertices' positions (each the mean of its members) for a plan of `mesh`: what moving the
// vertices changes when the plan stays the same.
void merged_positions(const Mesh& mesh, const MergePlan& plan, Buffer<Vec3>& positions);

// The parts side by side as one mesh (vertex and face ids offset part by part), then merged.
MergeResult merge_meshes(std::span<const Mesh> parts, const MergeOptions& options = {});

}  // namespace nome
