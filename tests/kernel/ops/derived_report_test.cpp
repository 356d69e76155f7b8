#include <catch2/catch.hpp>

#include <random>

#include "nome/ops/offset.hpp"
#include "nome/ops/offset_report.hpp"
#include "nome/ops/subdivide.hpp"
#include "nome/ops/subdivided_report.hpp"
#include "support/random_manifold.hpp"
#include "support/same_report.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

std::vector<PolygonSoup> report_shapes() {
  PolygonSoup with_isolated = test::cube();
  with_isolated.add_vertex({5.0, 5.0, 5.0});
  return {test::torus(6, 4),
          test::mobius_band(9, 2),
          test::mobius_band(10, 1, 2),
          test::klein_bottle(8, 6),
          test::projective_plane(),
          test::grid(3, 2),
          test::disjoint_union(test::tetrahedron(), test::mobius_band(7, 1)),
          with_isolated};
}

}  // namespace

TEST_CASE("the report derived over subdivision levels is the subdivided mesh's", "[kernel]") {
  for (const PolygonSoup& soup : report_shapes()) {
    const Mesh mesh = build_mesh(soup);
    for (int levels : {1, 2, 3}) {
      CAPTURE(mesh.num_faces(), levels);
      test::check_same_report(subdivided_topology_report(mesh, levels),
                              topology_report(subdivide(mesh, {levels})));
    }
  }
}

TEST_CASE("the report derived over the offset is the offset solid's", "[kernel]") {
  for (const PolygonSoup& soup : report_shapes()) {
    const Mesh mesh = build_mesh(soup);
    CAPTURE(mesh.num_faces());
    test::check_same_report(offset_topology_report(mesh), topology_report(offset(mesh, {0.05})));
  }
  // Random gluings: handles, cross-caps, borders and several parts, faces reversed at random.
  for (unsigned i = 0; i < 200; ++i) {
    const unsigned seed = test::seed_base() + i;
    INFO("seed " << seed << " (NOME_SEED=" << test::seed_base() << ")");
    std::mt19937 rng{seed};
    const Mesh mesh = build_mesh(test::random_manifold(rng).soup);
    test::check_same_report(offset_topology_report(mesh), topology_report(offset(mesh, {0.05})));
  }
}
