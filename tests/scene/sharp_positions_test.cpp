// `sharp` statements by where they put the subdivided points: a mesh's weighted chain, a top-level
// infinitely sharp chain over an instance's vertices and a top-level corner weight, on a grid mesh written
// in the scene, checked against the crease rules by hand after one Catmull-Clark level.
#include <catch2/catch.hpp>

#include <string>

#include <glm/geometric.hpp>

#include "nome/mesh/mesh.hpp"
#include "nome/ops/subdivide.hpp"
#include "nome/scene/scene.hpp"

using namespace nome;

namespace {

// A 4 x 4 grid of quads p{i}{j} at (i, j, a bumpy z), a mesh `g` instanced as k.
Vec3 sharp_grid_point(int i, int j) {
  return Vec3(i, j, 0.1 * ((i * 7 + j * 3) % 5) - 0.05 * i * j);
}

std::string sharp_grid_text(const std::string& inside_mesh, const std::string& after) {
  std::string text;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) {
      const Vec3 p = sharp_grid_point(i, j);
      text += "point p" + std::to_string(i) + std::to_string(j) + " (" + std::to_string(p.x) + " " +
              std::to_string(p.y) + " " + std::to_string(p.z) + ") endpoint\n";
    }
  text += "mesh g\n";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const auto name = [](int a, int b) { return "p" + std::to_string(a) + std::to_string(b); };
      text += "  face q" + std::to_string(i) + std::to_string(j) + " (" + name(i, j) + " " + name(i + 1, j) +
              " " + name(i + 1, j + 1) + " " + name(i, j + 1) + ") endface\n";
    }
  return text + inside_mesh + "endmesh\ninstance k g endinstance\n" + after;
}

struct SharpGridLevel {
  PolygonSoup soup;
  Mesh base, child;

  Index id(int i, int j) const {
    const std::string name = "k_p" + std::to_string(i) + std::to_string(j);
    for (Index v = 0; v < soup.vertex_names.size(); ++v)
      if (soup.vertex_names[v] == name) return v;
    FAIL("no vertex " << name);
    return no_index;
  }
  Vec3 p(int i, int j) const { return soup.positions[id(i, j)]; }
  Vec3 face(int i, int j) const { return (p(i, j) + p(i + 1, j) + p(i + 1, j + 1) + p(i, j + 1)) / 4.0; }
  Vec3 smooth_along_row(int i, int j) const {
    return (p(i, j) + p(i + 1, j) + face(i, j - 1) + face(i, j)) / 4.0;
  }
  Vec3 smooth_vertex(int i, int j) const {
    const Vec3 edges = p(i - 1, j) + p(i + 1, j) + p(i, j - 1) + p(i, j + 1);
    const Vec3 diagonals = p(i - 1, j - 1) + p(i + 1, j - 1) + p(i - 1, j + 1) + p(i + 1, j + 1);
    return (36.0 * p(i, j) + 6.0 * edges + diagonals) / 64.0;
  }
  Vec3 crease_vertex(int i, int j) const { return (6.0 * p(i, j) + p(i - 1, j) + p(i + 1, j)) / 8.0; }
  Vec3 edge_point_along_row(int i, int j) const {
    const Index a = id(i, j), b = id(i + 1, j);
    for (Index e : base.vertex_edges(a))
      if (base.edge(e).other_vertex(a) == b) return child.position(base.num_faces() + e);
    FAIL("no edge");
    return {};
  }
  Vec3 vertex_point(int i, int j) const {
    return child.position(base.num_faces() + base.num_edges() + id(i, j));
  }
};

SharpGridLevel sharp_grid_subdivided(const std::string& text) {
  SharpGridLevel level;
  level.soup = scene::Scene::from_text(text, "t.nome").combined_soup();
  level.base = build_mesh(level.soup);
  level.child = subdivide(level.base, {});
  return level;
}

void check_sharp_point(const Vec3& got, const Vec3& expected) {
  INFO("got " << got.x << " " << got.y << " " << got.z << ", expected " << expected.x << " " << expected.y
              << " " << expected.z);
  CHECK(glm::length(got - expected) < 1e-12);
}

}  // namespace

TEST_CASE("a mesh's weighted sharp chain, a top-level chain and a top-level corner subdivide by the rules",
          "[scene]") {
  const SharpGridLevel m = sharp_grid_subdivided(
      sharp_grid_text("  sharp 0.5 (p01 p11 p21 p31 p41) endsharp\n",
                      "sharp (k_p03 k_p13 k_p23 k_p33 k_p43) endsharp\nsharp 0.25 (k_p22) endsharp\n"));
  REQUIRE(m.soup.sharp_edges.size() == 8);
  for (int i = 0; i < 4; ++i) {
    INFO("column " << i);
    // Row 1, weight 0.5: half the midpoint, half the smooth point; row 3, infinitely sharp: the midpoint.
    check_sharp_point(m.edge_point_along_row(i, 1),
                      0.5 * (m.p(i, 1) + m.p(i + 1, 1)) / 2.0 + 0.5 * m.smooth_along_row(i, 1));
    check_sharp_point(m.edge_point_along_row(i, 3), (m.p(i, 3) + m.p(i + 1, 3)) / 2.0);
    // Row 2 has no crease.
    check_sharp_point(m.edge_point_along_row(i, 2), m.smooth_along_row(i, 2));
  }
  for (int i = 1; i <= 3; ++i) {
    INFO("column " << i);
    check_sharp_point(m.vertex_point(i, 1), 0.5 * m.crease_vertex(i, 1) + 0.5 * m.smooth_vertex(i, 1));
    check_sharp_point(m.vertex_point(i, 3), m.crease_vertex(i, 3));
  }
  check_sharp_point(m.vertex_point(2, 2), 0.25 * m.p(2, 2) + 0.75 * m.smooth_vertex(2, 2));
  check_sharp_point(m.vertex_point(1, 2), m.smooth_vertex(1, 2));
}

TEST_CASE("a sharp chain without a weight is infinitely sharp, a lone vertex without one a fixed corner",
          "[scene]") {
  const SharpGridLevel m =
      sharp_grid_subdivided(sharp_grid_text("  sharp (p12 p22 p32) endsharp\n", "sharp (k_p21) endsharp\n"));
  check_sharp_point(m.edge_point_along_row(1, 2), (m.p(1, 2) + m.p(2, 2)) / 2.0);
  check_sharp_point(m.edge_point_along_row(2, 2), (m.p(2, 2) + m.p(3, 2)) / 2.0);
  check_sharp_point(m.edge_point_along_row(0, 2), m.smooth_along_row(0, 2));
  check_sharp_point(m.vertex_point(2, 2), m.crease_vertex(2, 2));
  // The chain's ends have one sharp edge each: darts, smooth.
  check_sharp_point(m.vertex_point(1, 2), m.smooth_vertex(1, 2));
  check_sharp_point(m.vertex_point(3, 2), m.smooth_vertex(3, 2));
  check_sharp_point(m.vertex_point(2, 1), m.p(2, 1));
}
