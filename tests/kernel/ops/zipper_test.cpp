#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "nome/error.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/zipper.hpp"
#include "support/greedy_zipper.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// An open cylinder: `around` vertices per ring, `rings` rings from z = 0 to z = 1.
PolygonSoup cylinder(Index around, Index rings) {
  PolygonSoup s;
  for (Index r = 0; r < rings; ++r)
    for (Index k = 0; k < around; ++k) {
      const double angle = 6.283185307179586 * k / around;
      s.add_vertex(Vec3(std::cos(angle), std::sin(angle), double(r) / (rings - 1)));
    }
  for (Index r = 0; r + 1 < rings; ++r)
    for (Index k = 0; k < around; ++k)
      s.add_face({r * around + k, r * around + (k + 1) % around, (r + 1) * around + (k + 1) % around,
                  (r + 1) * around + k});
  return s;
}

// +1 if the boundary loop through v runs towards v + 1 (mod around), -1 if towards v - 1.
int loop_sense(const Mesh& mesh, Index v, Index around) {
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l) {
    const auto loop = mesh.loop_vertices(l);
    for (size_t k = 0; k < loop.size(); ++k)
      if (loop[k] == v) return loop[(k + 1) % loop.size()] % around == (v + 1) % around ? 1 : -1;
  }
  return 0;
}

std::vector<Vec3> scaled(std::vector<Vec3> chain, double factor) {
  for (Vec3& p : chain) p *= factor;
  return chain;
}

Mesh with_faces(const Mesh& mesh, const ZipperFaces& strip) {
  PolygonSoup soup = to_soup(mesh);
  for (const auto& face : strip.faces) soup.add_face(face);
  return build_mesh(std::move(soup));
}

}  // namespace

TEST_CASE("zippering equal chains gives only quads", "[kernel]") {
  std::vector<Vec3> a, b;
  for (int k = 0; k < 9; ++k) {
    a.emplace_back(k, 0.0, 0.0);
    b.emplace_back(k, 1.0, 0.2);
  }
  const ZipperStrip strip = zipper_strip(a, b);
  CHECK(strip.quads == 8);
  CHECK(strip.triangles == 0);
  CHECK(strip.cost == Approx(8 * std::sqrt(1.04)));
}

TEST_CASE("zippering chains of 5 and 8 points needs 3 triangles at least, and gets exactly that",
          "[kernel]") {
  std::vector<Vec3> a, b;
  for (int k = 0; k < 5; ++k) a.emplace_back(k * 7.0 / 4.0, 0.0, 0.0);
  for (int k = 0; k < 8; ++k) b.emplace_back(k, 1.0, 0.0);
  const ZipperStrip strip = zipper_strip(a, b);
  CHECK(strip.quads == 4);
  CHECK(strip.triangles == 3);
  CHECK(strip.num_faces() == 7);
}

TEST_CASE("a larger triangle penalty never gives more triangles", "[kernel]") {
  std::mt19937 rng{42};
  std::uniform_int_distribution<Index> size(2, 14);
  const double penalties[] = {0.5, 1.0, 1.3, 1.5, 2.0, 4.0};
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<Vec3> a = test::random_chain(rng, size(rng), 0.0),
                            b = test::random_chain(rng, size(rng), 1.0);
    Index previous = std::numeric_limits<Index>::max();
    for (double penalty : penalties) {
      ZipperOptions options;
      options.triangle_penalty = penalty;
      const Index triangles = zipper_strip(a, b, options).triangles;
      CHECK(triangles <= previous);
      previous = triangles;
    }
  }
}

TEST_CASE("the exact strip never costs more than the report's greedy strip", "[kernel]") {
  std::mt19937 rng{42};
  std::uniform_int_distribution<Index> size(2, 20);
  int cheaper = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<Vec3> a = test::random_chain(rng, size(rng), 0.0),
                            b = test::random_chain(rng, size(rng), 1.0);
    const ZipperOptions options;
    const double exact = zipper_strip(a, b, options).cost;
    const double greedy = test::greedy_zipper(a, b, options).cost;
    CHECK(exact <= greedy + 1e-9);
    if (exact < greedy - 1e-9) ++cheaper;
  }
  CHECK(cheaper > 0);  // the greedy strip is not optimal on random chains
}

TEST_CASE("the strip never puts three faces on an edge and uses every chain edge once", "[kernel]") {
  std::mt19937 rng{42};
  std::uniform_int_distribution<Index> size(2, 12);
  for (int trial = 0; trial < 100; ++trial) {
    const std::vector<Vec3> a = test::random_chain(rng, size(rng), 0.0),
                            b = test::random_chain(rng, size(rng), 1.0);
    const ZipperStrip strip = zipper_strip(a, b);
    std::map<std::pair<Index, Index>, int> uses;
    for (Index f = 0; f < strip.num_faces(); ++f) {
      const Index begin = strip.face_offsets[f], end = strip.face_offsets[f + 1];
      for (Index c = begin; c < end; ++c) {
        const Index u = strip.face_vertices[c], w = strip.face_vertices[c + 1 == end ? begin : c + 1];
        ++uses[{std::min(u, w), std::max(u, w)}];
      }
    }
    const Index first_b = Index(a.size());
    for (const auto& [edge, count] : uses) {
      const bool is_chain_edge =
          edge.second == edge.first + 1 && (edge.second < first_b || edge.first >= first_b);
      CHECK(count == (is_chain_edge ? 1
                                    : (edge == std::pair<Index, Index>{0, first_b} ||
                                               edge == std::pair<Index, Index>{first_b - 1,
                                                                               Index(a.size() + b.size() - 1)}
                                           ? 1
                                           : 2)));
    }
    CHECK(uses.size() == (a.size() - 1) + (b.size() - 1) + strip.num_faces() + 1);
    // Built into a mesh (the two chains as borders), the strip is one disk.
    PolygonSoup soup;
    for (const Vec3& p : a) soup.add_vertex(p);
    for (const Vec3& p : b) soup.add_vertex(p);
    soup.face_offsets.assign(strip.face_offsets.begin(), strip.face_offsets.end());
    soup.face_vertices.assign(strip.face_vertices.begin(), strip.face_vertices.end());
    const TopologyReport r = topology_report(build_mesh(soup));
    CHECK(r.chi == 1);
    CHECK(r.orientable);
    CHECK(r.mobius_edges == 0);
  }
}

TEST_CASE("zippering a cylinder's two border circles: same direction a torus, opposite a Klein bottle",
          "[kernel]") {
  const Mesh tube = build_mesh(cylinder(8, 4));
  REQUIRE(tube.num_boundary_loops() == 2);
  const Index bottom = 0, top = 3 * 8;

  BorderSelection a{bottom, bottom, false};
  BorderSelection b{top, top, false};
  // Same direction around the axis: each loop walked in the same sense.
  const bool loops_agree = loop_sense(tube, bottom, 8) == loop_sense(tube, top, 8);
  b.backwards = !loops_agree;
  const ZipperFaces same = zipper_borders(tube, a, b);
  CHECK(same.triangles == 0);
  CHECK(same.quads == 8);
  const TopologyReport torus = topology_report(with_faces(tube, same));
  CHECK(torus.orientable);
  CHECK(torus.chi == 0);
  CHECK(torus.borders == 0);
  CHECK(torus.components.size() == 1);

  b.backwards = loops_agree;
  const ZipperFaces opposite = zipper_borders(tube, a, b);
  const TopologyReport klein = topology_report(with_faces(tube, opposite));
  CHECK_FALSE(klein.orientable);
  CHECK(klein.chi == 0);
  CHECK(klein.borders == 0);
  CHECK(klein.components[0].genus == 2);
}

TEST_CASE("the strip is oriented like the faces along the first border", "[kernel]") {
  const Mesh tube = build_mesh(cylinder(6, 3));
  const ZipperFaces strip = zipper_borders(tube, {0, 0, false}, {12, 12, true});
  const Mesh closed = with_faces(tube, strip);
  // No new face disagrees with the tube along the bottom circle.
  for (Index k = 0; k < 6; ++k)
    for (Index e : closed.vertex_edges(k))
      if (closed.edge(e).other_vertex(k) < 6) CHECK_FALSE(closed.edge(e).is_mobius);
}

TEST_CASE("partial segments zip between their end vertices", "[kernel]") {
  // Two parallel strips of quads; zip the facing halves of their borders.
  PolygonSoup lower = test::grid(6, 1), upper = test::grid(4, 1);
  for (Vec3& p : upper.positions) p = Vec3(p.x * 1.5, p.y + 2.0, 0.0);
  const Mesh both = build_mesh(test::disjoint_union(lower, upper));
  // Lower's top row is vertices 7..13, upper's bottom row 14..18, both walked towards +x.
  const ZipperFaces strip =
      zipper_borders(both, {7, 13, loop_sense(both, 7, 1000) < 0}, {14, 18, loop_sense(both, 14, 1000) < 0});
  CHECK(strip.quads + strip.triangles == strip.faces.size());
  CHECK(strip.triangles == 2);
  const TopologyReport r = topology_report(with_faces(both, strip));
  CHECK(r.components.size() == 1);
  CHECK(r.borders == 1);
  CHECK(r.chi == 1);
  CHECK(r.orientable);
  CHECK(r.mobius_edges == 0);
}

TEST_CASE("zipper refuses mismatched or overlapping selections", "[kernel]") {
  const Mesh tube = build_mesh(cylinder(6, 3));
  CHECK_THROWS_AS(zipper_borders(tube, {0, 0, false}, {12, 14, false}), InvalidInputError);
  CHECK_THROWS_AS(zipper_borders(tube, {0, 3, false}, {2, 5, false}), InvalidInputError);
  CHECK_THROWS_AS(zipper_borders(tube, {6, 6, false}, {0, 0, false}), InvalidInputError);  // 6 is inside
}

// The cost model's lengths are all relative to the model: a model in millimetres or in kilometres zips as
// it does in units.
TEST_CASE("the zipper pairs the same rungs on a model a thousand times larger or smaller", "[kernel]") {
  std::mt19937 rng{42};
  std::uniform_int_distribution<Index> size(2, 12);
  int penalty_matters = 0, skew_matters = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const std::vector<Vec3> a = test::random_chain(rng, size(rng), 0.0),
                            b = test::random_chain(rng, size(rng), 1.0);
    std::map<std::pair<double, double>, std::vector<Index>> faces;
    for (const double skew : {0.0, 1.0, 3.0})
      for (const double penalty : {0.5, 1.0, 1.3, 2.0, 4.0}) {
        INFO("trial " << trial << ", skew weight " << skew << ", triangle penalty " << penalty);
        ZipperOptions options;
        options.triangle_penalty = penalty;
        options.skew_weight = skew;
        const ZipperStrip unit = zipper_strip(a, b, options);
        faces[{skew, penalty}] = std::vector<Index>(unit.face_vertices.begin(), unit.face_vertices.end());
        for (const double factor : {1000.0, 0.001}) {
          INFO("scaled by " << factor);
          const ZipperStrip strip = zipper_strip(scaled(a, factor), scaled(b, factor), options);
          CHECK(strip.face_offsets == unit.face_offsets);
          CHECK(strip.face_vertices == unit.face_vertices);
          CHECK(strip.cost == Approx(factor * unit.cost).epsilon(1e-9));
        }
      }
    penalty_matters += faces[{1.0, 0.5}] != faces[{1.0, 4.0}];
    skew_matters += faces[{0.0, 1.0}] != faces[{3.0, 1.0}];
  }
  // The chains are such that both terms change the strip: the checks above compare choices, not defaults.
  CHECK(penalty_matters > 10);
  CHECK(skew_matters > 10);
}

TEST_CASE("zipping borders of a model scaled by 1000 or 0.001 gives the same faces", "[kernel]") {
  // Two strips of quads of different lengths whose facing borders (7 and 5 vertices) need triangles.
  PolygonSoup lower = test::grid(6, 1), upper = test::grid(4, 1);
  for (Vec3& p : upper.positions) p = Vec3(p.x * 1.5, p.y + 2.0, 0.3 * p.x);
  const PolygonSoup both = test::disjoint_union(lower, upper);
  const Mesh unit_mesh = build_mesh(both);
  const BorderSelection a{7, 13, loop_sense(unit_mesh, 7, 1000) < 0},
      b{14, 18, loop_sense(unit_mesh, 14, 1000) < 0};
  for (const double penalty : {1.0, 1.3, 3.0}) {
    ZipperOptions options;
    options.triangle_penalty = penalty;
    const ZipperFaces unit = zipper_borders(unit_mesh, a, b, options);
    for (const double factor : {1000.0, 0.001}) {
      INFO("penalty " << penalty << ", scaled by " << factor);
      PolygonSoup soup = both;
      for (Vec3& p : soup.positions) p *= factor;
      const ZipperFaces strip = zipper_borders(build_mesh(std::move(soup)), a, b, options);
      CHECK(strip.faces == unit.faces);
      CHECK(strip.triangles == unit.triangles);
      CHECK(strip.cost == Approx(factor * unit.cost).epsilon(1e-9));
    }
  }
}
