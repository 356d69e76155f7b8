#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "nome/ops/offset.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/mesh_measures.hpp"
#include "support/random_manifold.hpp"
#include "support/shapes.hpp"

using namespace nome;

// The offset's geometry checked against normals the test computes itself, from face corner lists and
// positions only (Newell per face; the fan's faces signed by how they run along their shared edges), so
// that a solid whose sheets are swapped at a Möbius seam, or whose copies are not where the report puts
// them, fails here whatever the kernel's normals say.
namespace {

Vec3 newell_normal(const Mesh& m, Index f) {
  const auto vs = m.face_vertices(f);
  Vec3 n(0);
  for (size_t i = 0; i < vs.size(); ++i) {
    const Vec3 a = m.position(vs[i]), b = m.position(vs[(i + 1) % vs.size()]);
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

// Vertex normals: the sum of the fan's unit face normals, each face signed relative to the first face
// met, flipping sign across an edge that both faces run the same way (a Möbius edge). Unit length, or
// zero where the sum vanishes.
std::vector<Vec3> independent_vertex_normals(const Mesh& m) {
  struct Side {
    Index face;
    bool forward;  // the face runs from the edge's smaller vertex to its larger one
  };
  std::map<std::pair<Index, Index>, std::vector<Side>> edge_faces;
  std::vector<std::vector<Index>> vertex_faces(m.num_vertices());
  for (Index f = 0; f < m.num_faces(); ++f) {
    const auto vs = m.face_vertices(f);
    for (size_t i = 0; i < vs.size(); ++i) {
      const Index a = vs[i], b = vs[(i + 1) % vs.size()];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back({f, a < b});
      vertex_faces[a].push_back(f);
    }
  }
  std::vector<std::vector<const std::vector<Side>*>> vertex_edges(m.num_vertices());
  for (const auto& [edge, sides] : edge_faces) {
    vertex_edges[edge.first].push_back(&sides);
    vertex_edges[edge.second].push_back(&sides);
  }
  std::vector<Vec3> normals(m.num_vertices(), Vec3(0));
  for (Index v = 0; v < m.num_vertices(); ++v) {
    if (vertex_faces[v].empty()) continue;
    std::map<Index, double> sign{{vertex_faces[v].front(), 1.0}};
    std::vector<Index> todo{vertex_faces[v].front()};
    while (!todo.empty()) {
      const Index f = todo.back();
      todo.pop_back();
      for (const auto& [edge, sides] : edge_faces) {
        if (edge.first != v && edge.second != v) continue;
        const auto here =
            std::find_if(sides.begin(), sides.end(), [&](const Side& s) { return s.face == f; });
        if (here == sides.end()) continue;
        for (const Side& other : sides)
          if (other.face != f && !sign.count(other.face)) {
            sign[other.face] = sign[f] * (other.forward == here->forward ? -1.0 : 1.0);
            todo.push_back(other.face);
          }
      }
    }
    Vec3 sum(0);
    for (const auto& [f, s] : sign) sum += s * glm::normalize(newell_normal(m, f));
    if (glm::length(sum) > 1e-9) normals[v] = glm::normalize(sum);
  }
  return normals;
}

double surface_area(const Mesh& m) {
  double sum = 0.0;
  for (Index f = 0; f < m.num_faces(); ++f) sum += 0.5 * glm::length(newell_normal(m, f));
  return sum;
}

// Each vertex's two copies lie at v +- d n (either order), and each face's positive copy lies on the side
// its own Newell normal points to, its negative copy on the other.
void check_copies(const Mesh& surface, const Mesh& solid, double d) {
  const std::vector<Vec3> normals = independent_vertex_normals(surface);
  REQUIRE(solid.num_vertices() == 2 * surface.num_vertices());
  for (Index v = 0; v < surface.num_vertices(); ++v) {
    INFO("vertex " << v);
    const Vec3 p = surface.position(v), plus = solid.position(2 * v), minus = solid.position(2 * v + 1);
    CHECK(glm::length(0.5 * (plus + minus) - p) < 1e-12);
    CHECK(glm::length(plus - minus) == Approx(2 * d).epsilon(1e-12));
    CHECK(glm::length(glm::cross(glm::normalize(plus - minus), normals[v])) < 1e-9);
  }
  const Index nf = surface.num_faces();
  for (Index f = 0; f < nf; ++f) {
    INFO("face " << f);
    const Vec3 n = newell_normal(surface, f);
    const auto source = surface.face_vertices(f);
    const auto positive = solid.face_vertices(f), negative = solid.face_vertices(nf + f);
    REQUIRE(positive.size() == source.size());
    REQUIRE(negative.size() == source.size());
    for (size_t k = 0; k < source.size(); ++k) {
      CHECK(positive[k] / 2 == source[k]);
      CHECK(glm::dot(solid.position(positive[k]) - surface.position(source[k]), n) > 0.0);
      CHECK(glm::dot(solid.position(negative[k]) - surface.position(negative[k] / 2), n) < 0.0);
    }
  }
}

}  // namespace

TEST_CASE("offset copies sit 2d apart on the test's own normals, positive sheets on each face's side",
          "[kernel]") {
  const double d = 0.02;
  const struct {
    const char* name;
    PolygonSoup soup;
  } cases[] = {
      {"torus", test::torus(12, 8)},
      {"mobius band", test::mobius_band(16, 3)},
      {"mobius band, three half-twists", test::mobius_band(21, 2, 3)},
      {"klein bottle", test::klein_bottle(16, 10)},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    for (int levels : {0, 2}) {
      INFO("subdivided " << levels << " times");
      const Mesh surface = subdivide(build_mesh(c.soup), {levels, SubdivisionRule::classic});
      check_copies(surface, offset(surface, {d}), d);
    }
  }
}

TEST_CASE("an offset solid's volume is the slab's: 2d times the surface's area", "[kernel]") {
  const double d = 0.01;
  const struct {
    const char* name;
    PolygonSoup soup;
  } cases[] = {
      {"torus", test::torus(16, 12)},
      {"mobius band", test::mobius_band(24, 4)},
  };
  for (const auto& c : cases) {
    INFO(c.name);
    const Mesh surface = subdivide(build_mesh(c.soup), {2, SubdivisionRule::classic});
    const double expected = 2 * d * surface_area(surface);
    CHECK(test::signed_volume(offset(surface, {d})) == Approx(expected).epsilon(0.01));
  }
}

TEST_CASE("the two-thread offset equals the one-thread offset bit for bit", "[kernel]") {
  std::mt19937 rng{test::seed_base() + 7};
  INFO("NOME_SEED base " << test::seed_base());
  const test::RandomManifold random = test::random_manifold(rng, {.max_polygons = 200});
  Mesh surface = build_mesh(random.soup);
  while (surface.num_faces() < (1u << 15)) surface = subdivide(surface, {1, SubdivisionRule::classic});
  const Mesh one = offset(surface, {0.01, 0, SubdivisionRule::classic, 1});
  const Mesh two = offset(surface, {0.01, 0, SubdivisionRule::classic, 2});
  REQUIRE(one.num_faces() == two.num_faces());
  CHECK(one.positions() == two.positions());
  bool same_faces = true;
  for (Index f = 0; f < one.num_faces() && same_faces; ++f) {
    const auto a = one.face_vertices(f), b = two.face_vertices(f);
    same_faces = std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  CHECK(same_faces);
}
