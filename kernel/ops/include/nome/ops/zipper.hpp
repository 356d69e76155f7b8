#pragma once

#include <span>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {

struct ZipperOptions {
  // How much a triangle costs more than a quad: 1 is no penalty, the report's default is 1.3.
  double triangle_penalty = 1.3;
  // Weight of the report's skewness balance: rungs joining points at different fractions of their
  // borders' lengths cost extra.
  double skew_weight = 1.0;
};

// The zipper's cost model (Wang 2016, section 7.3.3), shared by the exact solver and any other strip
// builder so that their costs compare. Chain A has points a[0..m], chain B b[0..n]; a strip is a path
// of rungs (i, j) from (0, 0) to (m, n), each step adding a quad (i+1, j+1), or a triangle (i+1, j) or
// (i, j+1). A step costs the length of its new rung plus skew_weight * L * |t_a(i) - t_b(j)|
// (t the fraction of arc length, L a typical rung length), and a triangle step (penalty - 1) * L more.
// The penalty is per triangle rather than a factor on each triangle's own rung length so that a larger
// penalty can never buy more triangles (with a factor, a long quad rung could be traded for several
// short triangle rungs); for a rung of typical length the two agree.
class ZipperCost {
 public:
  ZipperCost(std::span<const Vec3> a, std::span<const Vec3> b, const ZipperOptions& options);

  Index last_a() const { return Index(a_.size() - 1); }
  Index last_b() const { return Index(b_.size() - 1); }
  // The cost of the step that ends at rung (i, j); is_triangle tells which kind of face it adds.
  double step(Index i, Index j, bool is_triangle) const;
  double typical_rung() const { return typical_rung_; }

 private:
  std::span<const Vec3> a_, b_;
  std::vector<double> t_a_, t_b_;
  double typical_rung_ = 0.0;
  ZipperOptions options_;
};

// A strip of faces joining two chains, as chain positions: a[i] is vertex i, b[j] is vertex
// last_a + 1 + j. Faces run along A forwards: quads (a_i, a_i+1, b_j+1, b_j), triangles
// (a_i, a_i+1, b_j) and (a_i, b_j+1, b_j).
struct ZipperStrip {
  std::vector<Index> face_offsets{0};
  std::vector<Index> face_vertices;
  double cost = 0.0;
  Index quads = 0;
  Index triangles = 0;
  Index num_faces() const { return Index(face_offsets.size() - 1); }
};

// The cheapest strip, by dynamic programming over rungs (i, j) in O(m n): a[0] joins b[0] and a[m]
// joins b[n]. For whole loops pass each loop from its start vertex with the start repeated at the end.
ZipperStrip zipper_strip(std::span<const Vec3> a, std::span<const Vec3> b, const ZipperOptions& options = {});

// Part of a boundary loop: from `start` to `end` along the loop, forwards (loop order) or backwards;
// start == end selects the whole loop from start.
struct BorderSelection {
  Index start = no_index;
  Index end = no_index;
  bool backwards = false;
};

// The border's vertices in selection order (a whole loop ends with its start again). Throws
// InvalidInputError if a vertex is not on a border or the two ends are on different borders.
std::vector<Index> border_chain(const Mesh& mesh, const BorderSelection& selection);

// Zips two borders of `mesh` (both whole loops, or both segments): the strip's faces as polygons of
// mesh vertex ids, oriented to agree with the faces along border a. Throws InvalidInputError if the
// borders overlap or only one is a whole loop.
struct ZipperFaces {
  std::vector<std::vector<Index>> faces;
  double cost = 0.0;
  Index quads = 0;
  Index triangles = 0;
};
ZipperFaces zipper_borders(const Mesh& mesh, const BorderSelection& a, const BorderSelection& b,
                           const ZipperOptions& options = {});

// The first vertex of chain B that chain A holds too, other than a shared end (closing a slit); no_index
// when there is none.
Index chains_overlap(std::span<const Index> chain_a, std::span<const Index> chain_b);

// The strip between two chains of vertex ids into `positions`, faces running along A forwards (the
// caller orients them). A whole loop is passed from its start with the start repeated at the end; both
// chains are loops or both are segments. Throws InvalidInputError if the chains share a vertex other than
// their ends (closing a slit) or only one is a loop. zipper_borders and the document's zipper along rim
// lines (report 6.3) both build on it.
ZipperFaces zipper_chains(std::span<const Vec3> positions, std::span<const Index> chain_a,
                          std::span<const Index> chain_b, const ZipperOptions& options = {});

}  // namespace nome
