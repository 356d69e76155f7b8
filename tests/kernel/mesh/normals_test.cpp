#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>

#include "nome/error.hpp"
#include "nome/mesh/normals.hpp"
#include "nome/ops/offset.hpp"
#include "support/shapes.hpp"

using namespace nome;

namespace {

// A torus large enough that the normals split over two threads, with faces reversed at random (corners
// of both signs), two faces folded flat (degenerate), and the faces around vertex 40000 shrunk to its
// point (all degenerate: its normal vanishes).
PolygonSoup folded_torus() {
  std::mt19937 rng{7};
  PolygonSoup soup = test::reverse_random_faces(test::torus(320, 256), 0.3, rng);
  for (Index f : {Index(5), Index(70000)}) {
    const Index* corners = soup.face_vertices.data() + soup.face_offsets[f];
    soup.positions[corners[2]] = soup.positions[corners[1]];
    soup.positions[corners[3]] = soup.positions[corners[0]];
  }
  const Index pinched = 40000;
  for (Index f = 0; f + 1 < soup.face_offsets.size(); ++f) {
    const auto corners = std::span(soup.face_vertices).subspan(soup.face_offsets[f], 4);
    if (std::ranges::find(corners, pinched) != corners.end())
      for (const Index v : corners) soup.positions[v] = soup.positions[pinched];
  }
  return soup;
}

// Two tori's faces taken in turn: two components whose faces interleave (no split into halves).
PolygonSoup interleaved_tori() {
  const PolygonSoup both = test::disjoint_union(test::torus(256, 128), test::torus(256, 128, 2.0));
  const Index half = both.num_faces() / 2;
  PolygonSoup out;
  out.positions = both.positions;
  for (Index f = 0; f < half; ++f)
    for (const Index g : {f, half + f})
      out.add_face(std::span(both.face_vertices.data() + both.face_offsets[g], 4));
  return out;
}

}  // namespace

TEST_CASE("Möbius-aware vertex normals agree with every signed face normal of their fan", "[kernel]") {
  std::mt19937 rng{42};
  for (const PolygonSoup& soup : {test::mobius_band(24, 3), test::klein_bottle(24, 12),
                                  test::reverse_random_faces(test::torus(16, 8), 0.5, rng)}) {
    const Mesh m = build_mesh(soup);
    const Normals n = compute_normals(m);
    CHECK(n.degenerate_faces.empty());
    CHECK(n.degenerate_vertices.empty());
    CHECK(degeneracy_warning(m, n).empty());
    for (Index v = 0; v < m.num_vertices(); ++v) {
      CHECK(glm::length(n.vertices[v]) == Approx(1.0));
      for (Index c : m.vertex_corners(v))
        CHECK(glm::dot(n.vertices[v], double(m.corner_sign(c)) * n.faces[m.corner_face(c)]) > 0.2);
    }
  }
}

TEST_CASE("Newell's face normal is the area vector of a non-planar polygon too", "[kernel]") {
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0.3}, {0, 1, -0.3}};
  s.add_face({0, 1, 2, 3});
  const Mesh m = build_mesh(s);
  const Vec3 n = face_area_normal(m, 0);
  CHECK(n.z == Approx(2.0 * 2.0));  // twice the projected area on z = 0
  // Computed as the cross product of the diagonals: the same vector, other roundings.
  CHECK(glm::length(compute_normals(m).faces[0] - glm::normalize(n)) < 1e-15);
}

TEST_CASE("degenerate faces give zero normals and a warning that names them, never NaN", "[kernel]") {
  PolygonSoup s = test::grid(2, 1);
  // Face 1 = (v1 v2 v5 v4): fold its far side onto its near side, so that it has no area.
  s.positions[4] = s.positions[1];
  s.positions[5] = s.positions[2];
  s.face_names = {"left", "flat"};
  const Mesh m = build_mesh(s);
  const Normals n = compute_normals(m);
  REQUIRE(n.degenerate_faces == std::vector<Index>{1});
  CHECK(n.faces[1] == Vec3(0.0));
  for (const Vec3& v : n.vertices) CHECK_FALSE((std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z)));
  const std::string warning = degeneracy_warning(m, n);
  CHECK_THAT(warning, Catch::Contains("1 degenerate faces") && Catch::Contains("flat"));
  CHECK_THAT(warning, Catch::Contains("v2") && Catch::Contains("v5"));
}

TEST_CASE("normals on two threads are those of one, degenerate elements listed in order", "[kernel]") {
  const Mesh m = build_mesh(folded_torus());
  REQUIRE(m.num_faces() > 2 * (1u << 15));
  const Normals one = compute_normals(m);
  REQUIRE(one.degenerate_faces.size() >= 2);
  Normals two;
  compute_normals(m, two, 2);
  CHECK(two.faces == one.faces);
  CHECK(two.vertices == one.vertices);
  CHECK(two.degenerate_faces == one.degenerate_faces);
  CHECK(two.degenerate_vertices == one.degenerate_vertices);
}

namespace {

// The packed vertex normal the test expects of v: the signed sum over its fan of the packed face normals,
// and its length (zero where the sum is shorter than 0.01).
std::pair<Vec3, double> expected_packed_normal(const Mesh& m, std::span<const PackedNormal> faces, Index v) {
  Vec3 sum(0.0);
  for (Index i = m.fan_corner_offsets()[v]; i < m.fan_corner_offsets()[v + 1]; ++i) {
    const Index c = m.fan_corners()[i];
    sum += double(m.corner_sign(c)) * Vec3(unpack_normal(faces[m.corner_face(c)]));
  }
  const double length = glm::length(sum);
  return {length > 1e-2 ? sum / length : Vec3(0.0), length};
}

// The largest distance of the unpacked vertex normals from those expected, skipping vertices whose sum is
// too near the threshold to tell float from double; 1 where one is zero and the other not.
double largest_packed_error(const Mesh& m, std::span<const PackedNormal> faces,
                            std::span<const PackedNormal> vertices) {
  double largest = 0.0;
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const auto [expected, length] = expected_packed_normal(m, faces, v);
    if (std::abs(length - 1e-2) < 1e-4) continue;
    const glm::vec3 got = unpack_normal(vertices[v]);
    if ((expected == Vec3(0.0)) != (got == glm::vec3(0.0f))) return 1.0;
    largest = std::max(largest, glm::length(Vec3(got) - expected));
  }
  return largest;
}

}  // namespace

TEST_CASE("packed normals: face normals packed, vertex normals summed from them", "[kernel]") {
  const Mesh m = build_mesh(folded_torus());
  const Normals one = compute_normals(m);
  Buffer<PackedNormal> faces, vertices;
  compute_packed_normals(m, faces, vertices, 2);
  REQUIRE(faces.size() == m.num_faces());
  REQUIRE(vertices.size() == m.num_vertices());
  bool same = true;
  for (Index f = 0; f < m.num_faces(); ++f) same = same && faces[f] == pack_normal(glm::vec3(one.faces[f]));
  CHECK(same);
  // Within a packing step (1/511 a component) of the sums of the packed face normals.
  CHECK(largest_packed_error(m, faces, vertices) < 2e-3);
  // Zero where the exact ones are (the vertex whose faces all shrank to it).
  REQUIRE_FALSE(one.degenerate_vertices.empty());
  for (const Index v : one.degenerate_vertices) CHECK(vertices[v] == 0u);
  // The same on one thread, bit for bit.
  Buffer<PackedNormal> faces_one, vertices_one;
  compute_packed_normals(m, faces_one, vertices_one, 1);
  CHECK((faces_one == faces && vertices_one == vertices));
}

TEST_CASE("packed normals of a smooth surface are its exact ones within a packing step", "[kernel]") {
  const Mesh m = build_mesh(test::torus(64, 32));
  const Normals exact = compute_normals(m);
  Buffer<PackedNormal> faces, vertices;
  compute_packed_normals(m, faces, vertices, 1);
  double largest = 0.0;
  for (Index v = 0; v < m.num_vertices(); ++v)
    largest = std::max(largest, glm::length(Vec3(unpack_normal(vertices[v])) - exact.vertices[v]));
  CHECK(largest < 3e-3);
}

TEST_CASE("packed normals of faces that are not quads, on a Möbius band", "[kernel]") {
  PolygonSoup soup = test::mobius_band(24, 3);
  PolygonSoup mixed;
  mixed.positions = soup.positions;
  // Each quad split into two triangles, and one left whole: the quad and the other polygons' paths.
  for (Index f = 0; f + 1 < soup.face_offsets.size(); ++f) {
    const Index* c = soup.face_vertices.data() + soup.face_offsets[f];
    if (f == 0) {
      mixed.add_face({c[0], c[1], c[2], c[3]});
    } else {
      mixed.add_face({c[0], c[1], c[2]});
      mixed.add_face({c[0], c[2], c[3]});
    }
  }
  const Mesh m = build_mesh(mixed);
  const Normals one = compute_normals(m);
  Buffer<PackedNormal> faces, vertices;
  compute_packed_normals(m, faces, vertices, 1);
  for (Index f = 0; f < m.num_faces(); ++f) CHECK(faces[f] == pack_normal(glm::vec3(one.faces[f])));
  CHECK(largest_packed_error(m, faces, vertices) < 2e-3);
  CHECK_THROWS_AS(compute_packed_vertex_normals(m, std::span(faces).first(1), vertices), InvalidInputError);
}

TEST_CASE("vertex normals of meshes of several pieces, on two threads", "[kernel]") {
  // An offset's two copies, pieces whose faces interleave, and the offset of a surface with faces
  // reversed at random (corners of both signs): each thread's vertices gather from faces anywhere.
  std::mt19937 rng{42};
  const Mesh surface = build_mesh(test::reverse_random_faces(test::torus(256, 128), 0.3, rng));
  for (const Mesh& m : {offset(build_mesh(test::torus(256, 128)), {.distance = 0.01}),
                        build_mesh(interleaved_tori()), offset(surface, {.distance = 0.01})}) {
    REQUIRE(m.num_faces() >= (1u << 16));
    Buffer<PackedNormal> faces, one, two;
    compute_packed_normals(m, faces, one, 1);
    compute_packed_normals(m, faces, two, 2);
    CHECK(one == two);
    const Normals exact = compute_normals(m);
    Normals split;
    compute_normals(m, split, 2);
    CHECK(split.vertices == exact.vertices);
    CHECK(split.degenerate_vertices == exact.degenerate_vertices);
    CHECK(largest_packed_error(m, faces, two) < 2e-3);
  }
}
