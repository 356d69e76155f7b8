#include <catch2/catch.hpp>

#include <numeric>

#include "nome/mesh/glue_faces.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/merge.hpp"
#include "support/face_colors.hpp"
#include "support/same_report.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

std::vector<Mesh> build_parts(const std::vector<PolygonSoup>& soups) {
  std::vector<Mesh> parts;
  for (const PolygonSoup& s : soups) parts.push_back(build_mesh(s));
  return parts;
}

// Quarters (or any number of slices) by the first grid index of the generators in shapes.cpp, whose
// faces are numbered i * v + j.
std::vector<Mesh> slices(const PolygonSoup& soup, Index faces_per_ring, Index rings, Index num_slices) {
  std::vector<Index> part(soup.num_faces());
  for (Index f = 0; f < soup.num_faces(); ++f) part[f] = (f / faces_per_ring) * num_slices / rings;
  return build_parts(test::split_faces(soup, part));
}

}  // namespace

TEST_CASE("two halves of a Möbius band cut across merge back into a Möbius band", "[kernel]") {
  const PolygonSoup band = test::mobius_band(12, 3);
  const std::vector<Mesh> halves = slices(band, 3, 12, 2);
  REQUIRE(halves.size() == 2);
  for (const Mesh& half : halves) CHECK(topology_report(half).orientable);

  const MergeResult merged = merge_meshes(halves);
  const TopologyReport r = topology_report(merged.mesh);
  test::check_same_report(r, topology_report(build_mesh(band)));
  CHECK_FALSE(r.orientable);
  CHECK(r.borders == 1);
  CHECK(r.mobius_edges == 3);  // one seam keeps its orientation, the other glues same-direction faces
  CHECK(merged.glued_edges == 6);
  CHECK(merged.skipped.empty());
}

TEST_CASE("a torus in four pieces merges to a torus", "[kernel]") {
  const PolygonSoup torus = test::torus(8, 6);
  const std::vector<Mesh> quarters = slices(torus, 6, 8, 4);
  REQUIRE(quarters.size() == 4);
  const TopologyReport r = topology_report(merge_meshes(quarters).mesh);
  test::check_same_report(r, topology_report(build_mesh(torus)));
  REQUIRE(r.components.size() == 1);
  CHECK(r.components[0].genus == 1);
  CHECK(r.borders == 0);
  CHECK(r.mobius_edges == 0);
}

// Shapes without self-intersection: where sheets cross along edges (the figure-8 Klein bottle), four
// boundary edges coincide and no merge by position can tell which belong together.
TEST_CASE("an exploded surface merges back to itself, whatever the face orientations", "[kernel]") {
  std::mt19937 rng{42};
  const PolygonSoup shapes[] = {test::torus(9, 5),        test::mobius_band(15, 3, 3),
                                test::mobius_band(11, 2), test::cube(),
                                test::grid(5, 4),         test::projective_plane()};
  for (const PolygonSoup& shape : shapes) {
    const PolygonSoup soup = test::reverse_random_faces(shape, 0.3, rng);
    std::vector<Index> own_part(soup.num_faces());
    std::iota(own_part.begin(), own_part.end(), 0);
    const MergeResult merged = merge_meshes(build_parts(test::split_faces(soup, own_part)));
    const TopologyReport want = topology_report(build_mesh(soup));
    test::check_same_report(topology_report(merged.mesh), want);
    CHECK(topology_report(merged.mesh).mobius_edges == want.mobius_edges);
    CHECK(merged.skipped.empty());
  }
}

TEST_CASE("end points within the tolerance match, farther ones do not", "[kernel]") {
  PolygonSoup left = test::grid(1, 1);
  PolygonSoup right = test::grid(1, 1);
  for (Vec3& p : right.positions) p += Vec3(1.0, 0.0, 0.0);
  right.positions[0].z += 0.004;  // one shared corner is off by 0.004
  const std::vector<Mesh> parts = build_parts({left, right});

  MergeOptions options;
  options.tolerance = 0.005;
  const MergeResult near = merge_meshes(parts, options);
  CHECK(near.glued_edges == 1);
  CHECK(near.mesh.num_vertices() == 6);
  CHECK(near.mesh.position(near.vertex_map[1]).z == Approx(0.002));  // the mean of the two ends

  options.tolerance = 0.003;
  CHECK(merge_meshes(parts, options).glued_edges == 0);

  // The default is 1e-3 of the bounding box diagonal (here sqrt(4 + 1) * 1e-3 < 0.004).
  const MergeResult by_default = merge_meshes(parts);
  CHECK(by_default.tolerance == Approx(std::sqrt(4.0 + 1.0 + 0.004 * 0.004) * 1e-3));
  CHECK(by_default.glued_edges == 0);
}

TEST_CASE("edges match in either direction: opposite faces give a regular edge, same-way faces a Möbius edge",
          "[kernel]") {
  PolygonSoup a = test::grid(1, 1);  // boundary edge 1 -> 3 along x = 1
  PolygonSoup b = test::grid(1, 1);
  for (Vec3& p : b.positions) p += Vec3(1.0, 0.0, 0.0);  // its edge 2 -> 0 runs back along x = 1
  const Mesh regular = merge_meshes(build_parts({a, b})).mesh;
  CHECK(regular.num_edges() == 7);
  CHECK(topology_report(regular).mobius_edges == 0);

  PolygonSoup flipped = b;
  std::reverse(flipped.face_vertices.begin(), flipped.face_vertices.end());
  const Mesh mobius = merge_meshes(build_parts({a, flipped})).mesh;
  CHECK(mobius.num_edges() == 7);
  CHECK(topology_report(mobius).mobius_edges == 1);
}

TEST_CASE("faces touching at a point are not merged until an edge joins them", "[kernel]") {
  PolygonSoup t1, t2, t3;
  t1.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  t1.add_face({0, 1, 2});
  t2.positions = {{0, 0, 0}, {-1, 0, 0}, {-1, -1, 0}};
  t2.add_face({0, 1, 2});
  const MergeResult apart = merge_meshes(build_parts({t1, t2}));
  CHECK(apart.mesh.num_vertices() == 6);
  CHECK(apart.mesh.num_components() == 2);

  // A third triangle sharing an edge with each joins all three at the common corner.
  t3.positions = {{0, 0, 0}, {1, 1, 0}, {-1, 0, 0}};
  t3.add_face({0, 2, 1});
  const MergeResult joined = merge_meshes(build_parts({t1, t2, t3}));
  CHECK(joined.mesh.num_vertices() == 5);
  CHECK(joined.mesh.num_components() == 1);
  CHECK(joined.glued_edges == 2);
  CHECK(joined.skipped.empty());
}

TEST_CASE("a third face on an edge is skipped and reported with names and positions", "[kernel]") {
  // Three pages of a book share the spine from (0,0,0) to (0,0,1).
  std::vector<PolygonSoup> pages;
  for (int k = 0; k < 3; ++k) {
    PolygonSoup page;
    const double a = 2.0944 * k;
    page.positions = {{0, 0, 0}, {std::cos(a), std::sin(a), 0}, {std::cos(a), std::sin(a), 1}, {0, 0, 1}};
    page.add_face({0, 1, 2, 3});
    page.vertex_names = {"p" + std::to_string(k) + "_low", "a", "b", "p" + std::to_string(k) + "_high"};
    pages.push_back(page);
  }
  const MergeResult merged = merge_meshes(build_parts(pages));
  CHECK(merged.glued_edges == 1);
  // The third page matches both glued pages: each pair is reported.
  REQUIRE(merged.skipped.size() == 2);
  for (const SkippedMerge& skip : merged.skipped) {
    CHECK(skip.reason == MergeSkipReason::third_face_on_edge);
    CHECK_THAT(skip.message, Catch::Contains("p2_low (0, 0, 0)") && Catch::Contains("(0, 0, 1)") &&
                                 Catch::Contains("third face"));
  }
  CHECK(merged.mesh.num_components() == 2);
}

TEST_CASE("a sliver whose two long edges match is not folded onto itself", "[kernel]") {
  PolygonSoup sliver;
  sliver.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1e-5, 0}};
  sliver.add_face({0, 1, 2});
  MergeOptions options;
  options.tolerance = 1e-3;
  const MergeResult merged = merge_boundaries(build_mesh(sliver), options);
  CHECK(merged.glued_edges == 0);
  CHECK(merged.mesh.num_vertices() == 3);
  REQUIRE_FALSE(merged.skipped.empty());
  for (const SkippedMerge& s : merged.skipped) CHECK(s.reason != MergeSkipReason::third_face_on_edge);
}

TEST_CASE("two border edges folding at a common end zip a slit", "[kernel]") {
  // A fan of four triangles around the origin, cut open along +x: the two cut edges coincide.
  PolygonSoup fan;
  fan.add_vertex({0, 0, 0});
  for (int k = 0; k <= 4; ++k) fan.add_vertex({std::cos(1.5708 * k), std::sin(1.5708 * k), 0});
  for (Index k = 1; k <= 4; ++k) fan.add_face({0, k, k + 1});
  const MergeResult merged = merge_boundaries(build_mesh(fan));
  CHECK(merged.glued_edges == 1);
  CHECK(merged.mesh.num_vertices() == 5);
  CHECK(topology_report(merged.mesh).borders == 1);
  CHECK_FALSE(merged.mesh.is_boundary_vertex(merged.vertex_map[0]));
}

TEST_CASE("names, colours and sharp marks survive the merge", "[kernel]") {
  PolygonSoup a = test::grid(1, 1), b = test::grid(1, 1);
  for (Vec3& p : b.positions) p += Vec3(1.0, 0.0, 0.0);
  a.vertex_names = {"a0", "a1", "a2", "a3"};
  b.vertex_names = {"b0", "b1", "b2", "b3"};
  a.face_names = {"left"};
  b.face_names = {"right"};
  test::set_face_colors(a.face_attributes, {Color(1, 0, 0)});
  test::set_face_colors(b.face_attributes, {Color(0, 0, 1)});
  b.sharp_edges = {{0, 2}};
  const MergeResult merged = merge_meshes(build_parts({a, b}));
  const Mesh& m = merged.mesh;
  REQUIRE(m.num_faces() == 2);
  CHECK(m.face_names() == std::vector<std::string>{"left", "right"});
  CHECK(test::face_colors(m)[0] == Color(1, 0, 0));
  CHECK(test::face_colors(m)[1] == Color(0, 0, 1));
  // b0 joined a1, b2 joined a3: the merged vertex keeps the lower-numbered member's name.
  CHECK(merged.vertex_map[1] == merged.vertex_map[4 + 0]);
  CHECK(m.vertex_names()[merged.vertex_map[4 + 0]] == "a1");
  CHECK(m.vertex_names()[merged.vertex_map[4 + 1]] == "b1");
  Index sharp = 0;
  for (const Edge& e : m.edges()) sharp += e.is_sharp ? 1 : 0;
  CHECK(sharp == 1);
}

TEST_CASE("merging random exploded patches agrees with joining their faces by vertex id", "[kernel]") {
  // Two independent routes to the same surface: glue_faces joins faces across shared vertex ids,
  // merge_boundaries finds the same edges by position. Random face subsets make pinched vertices,
  // slits and holes, which both must leave apart.
  std::mt19937 rng{42};
  const PolygonSoup shapes[] = {test::torus(10, 6), test::mobius_band(14, 3), test::grid(7, 6)};
  for (int trial = 0; trial < 30; ++trial) {
    const PolygonSoup& shape = shapes[trial % 3];
    std::bernoulli_distribution keep(0.7);
    PolygonSoup subset;
    subset.positions = shape.positions;
    for (Index f = 0; f < shape.num_faces(); ++f)
      if (keep(rng))
        subset.add_face(
            std::span(shape.face_vertices)
                .subspan(shape.face_offsets[f], shape.face_offsets[f + 1] - shape.face_offsets[f]));
    const PolygonSoup oriented = test::reverse_random_faces(subset, 0.3, rng);
    std::vector<Index> own_part(oriented.num_faces());
    std::iota(own_part.begin(), own_part.end(), 0);
    const MergeResult merged = merge_meshes(build_parts(test::split_faces(oriented, own_part)));
    const TopologyReport want = topology_report(glue_faces(oriented).mesh);
    const TopologyReport got = topology_report(merged.mesh);
    test::check_same_report(got, want);
    CHECK(got.mobius_edges == want.mobius_edges);
    CHECK(merged.skipped.empty());
  }
}
