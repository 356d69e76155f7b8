#pragma once

#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/progress.hpp"
#include "nome/query/crossings.hpp"
#include "nome/query/near_misses.hpp"

namespace nome {

struct PrintCheckOptions {
  double offset_distance = 0.0;  // the slab's half thickness; 0: the surface is not offset (no fold-overs)
  double min_wall = 0.0;         // 0: 2 x offset_distance
  int threads = 1;
  Progress progress;
};

enum class FindingKind { fold_over, near_miss, crossing };

// "fold-over", "near miss", "crossing": for reports and panels.
const char* to_string(FindingKind kind);

// A connected place of findings of one kind: where it is worst.
struct PrintPlace {
  FindingKind kind = FindingKind::fold_over;
  Vec3 position{0.0};
  Index face = no_index;        // the surface's face there
  Index other_face = no_index;  // near miss and crossing: the face of the other sheet
  double distance = 0.0;        // near miss: the gap; otherwise 0
  Index size = 0;               // faces (fold-over, crossing) or vertices (near miss) in the place
};

// What the print check found on a surface, the three kinds kept apart.
struct PrintCheck {
  double offset_distance = 0.0;
  double min_wall = 0.0;
  std::vector<Index> fold_over_faces;
  Crossings crossings;
  std::vector<NearMiss> near_misses;
  // Fold-overs, then near misses (thinnest first), then crossing curves (longest first).
  std::vector<PrintPlace> places;

  // Crossings fuse the slab by design (a Klein bottle must cross itself); the other two break the print.
  bool is_printable() const { return fold_over_faces.empty() && near_misses.empty(); }
};

// Checks whether the offset of `surface` by options.offset_distance prints as meant: faces the
// offset turns over, curves where distant parts of the surface cross, and places where two sheets come
// closer than the minimum wall away from crossings. Uses the picking BVH and up to options.threads
// threads. Throws InvalidInputError for a negative or non-finite distance or wall.
PrintCheck check_printability(const Mesh& surface, const PrintCheckOptions& options);

}  // namespace nome
