#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "nome/ops/subdivide.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// Jitters every vertex so that no position is an accident of symmetry.
PolygonSoup moved_off_grid(PolygonSoup soup, double amount) {
  std::mt19937 rng{42};
  std::uniform_real_distribution<double> d(-amount, amount);
  for (Vec3& p : soup.positions) p += Vec3(d(rng), d(rng), d(rng));
  return soup;
}

// The last level's positions with the vector instructions allowed or not, into NaNs (an unwritten output
// stays one).
Buffer<Vec3> refined_with(const Mesh& base, int levels, BoundaryMode boundary, int threads,
                          bool is_vector_allowed) {
  Refinement refinement(base, levels, boundary, threads);
  refinement.allow_vector_instructions(is_vector_allowed);
  Buffer<Vec3> out(refinement.num_vertices(), Vec3(std::nan("")));
  refinement.refine_positions(base, SubdivisionRule::classic, out, threads);
  return out;
}

bool has_same_bits(const Buffer<Vec3>& a, const Buffer<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

}  // namespace

TEST_CASE("the position pass gives the same bits with and without vector instructions", "[kernel]") {
  // The vector steps run the classic rule's tiled pass (level 3 on) where the CPU has AVX2, and hand crease
  // edges and fixed or crease vertices to the baseline steps: shapes with Möbius edges, borders, creases,
  // corners, a pentagon and a vertex of no face.
  PolygonSoup creased = moved_off_grid(test::torus(6, 5), 0.05);
  creased.sharp_edges = {{0, 1}, {1, 2}, {2, 3}, {0, 5}, {5, 10}, {10, 15}};
  PolygonSoup open = moved_off_grid(test::disjoint_union(test::tetrahedron(), test::grid(3, 2)), 0.1);
  open.add_vertex(Vec3(5.0, 5.0, 5.0));
  std::vector<Index> pentagon;
  for (int k = 0; k < 5; ++k)
    pentagon.push_back(open.add_vertex(Vec3(std::cos(1.3 * k), std::sin(1.3 * k), 0.1 * k - 3.0)));
  open.add_face(pentagon);
  const std::vector<PolygonSoup> soups = {
      moved_off_grid(test::mobius_band(9, 2), 0.05),
      moved_off_grid(test::mobius_band(7, 3, 3), 0.05),
      moved_off_grid(test::klein_bottle(8, 6), 0.05),
      test::projective_plane(),
      creased,
      open,
      moved_off_grid(test::disjoint_union(test::cube(), test::torus(5, 4)), 0.1)};
  for (size_t i = 0; i < soups.size(); ++i) {
    const Mesh base = build_mesh(soups[i]);
    for (BoundaryMode boundary : {BoundaryMode::edge_only, BoundaryMode::edge_and_corner})
      for (int levels = 3; levels <= 4; ++levels) {
        INFO("shape " << i << ", " << levels << " levels, boundary " << int(boundary));
        CHECK(has_same_bits(refined_with(base, levels, boundary, 1, true),
                            refined_with(base, levels, boundary, 1, false)));
      }
  }
  // Enough tiles that two threads split them: each thread's last point of a run is written without the
  // spare lane, which would land on the other thread's first.
  const Mesh band = build_mesh(moved_off_grid(test::mobius_band(64, 16), 0.01));
  const Buffer<Vec3> scalar = refined_with(band, 5, BoundaryMode::edge_only, 1, false);
  CHECK(has_same_bits(refined_with(band, 5, BoundaryMode::edge_only, 2, true), scalar));
  CHECK(has_same_bits(refined_with(band, 5, BoundaryMode::edge_only, 1, true), scalar));
}
