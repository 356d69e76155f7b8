#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <queue>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "nome/query/near_misses.hpp"
#include "nome/query/triangle_proximity.hpp"
#include "support/random_manifold.hpp"
#include "support/shapes.hpp"

using namespace nome;

// The near-miss search (patches sharing one search, early stops, float distances) against its definition
// computed directly: for each vertex, a full Dijkstra along the edges, then every triangle outside that
// neighbourhood measured.
namespace {

std::vector<double> edge_distances_from(const Mesh& mesh, Index source, double limit) {
  std::vector<double> distance(mesh.num_vertices(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  distance[source] = 0.0;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v] || d >= limit) continue;
    for (const Index e : mesh.vertex_edges(v)) {
      const Index w = mesh.edge(e).other_vertex(v);
      const double through = d + glm::distance(mesh.position(v), mesh.position(w));
      if (through < distance[w]) {
        distance[w] = through;
        queue.push({through, w});
      }
    }
  }
  return distance;
}

// The nearest distances from v to the triangles whose every corner is at least `reach` along the edges
// from v: {with every corner beyond reach x (1 + 1e-5), with every corner beyond reach x (1 - 1e-5)}. The
// search keeps floats, so a triangle in that band may go either way.
std::pair<double, double> nearest_outside(const Mesh& mesh, const TriangleBvh& bvh, Index v, double reach) {
  const std::vector<double> along = edge_distances_from(mesh, v, 2.0 * reach);
  double sure = std::numeric_limits<double>::infinity(), either = sure;
  for (Index t = 0; t < bvh.num_triangles(); ++t) {
    double nearest_corner = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) nearest_corner = std::min(nearest_corner, along[bvh.triangle_vertex(t, i)]);
    if (nearest_corner < reach * (1.0 - 1e-5)) continue;
    const Triangle tri{bvh.triangle_point(t, 0), bvh.triangle_point(t, 1), bvh.triangle_point(t, 2)};
    const double d = glm::distance(mesh.position(v), closest_point_on_triangle(mesh.position(v), tri));
    either = std::min(either, d);
    if (nearest_corner >= reach * (1.0 + 1e-5)) sure = std::min(sure, d);
  }
  return {sure, either};
}

// Every vertex's finding, on one and two threads, agrees with the definition.
void check_against_definition(const Mesh& mesh, double wall) {
  const TriangleBvh bvh(mesh);
  NearMissOptions options;
  options.min_wall = wall;
  const std::vector<NearMiss> found = find_near_misses(mesh, bvh, options);
  options.threads = 2;
  const std::vector<NearMiss> threaded = find_near_misses(mesh, bvh, options);
  REQUIRE(threaded.size() == found.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    CHECK(threaded[i].vertex == found[i].vertex);
    CHECK(threaded[i].distance == found[i].distance);
  }
  std::vector<const NearMiss*> of_vertex(mesh.num_vertices(), nullptr);
  for (const NearMiss& m : found) of_vertex[m.vertex] = &m;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const auto [sure, either] = nearest_outside(mesh, bvh, v, 3.0 * wall);
    INFO("vertex " << v << ", wall " << wall << ", outside " << sure << " (with the band " << either << ")");
    if (sure < wall * (1.0 - 1e-9)) {
      REQUIRE(of_vertex[v] != nullptr);
      CHECK(of_vertex[v]->distance <= sure + 1e-12);
    }
    if (either >= wall) CHECK(of_vertex[v] == nullptr);
    if (of_vertex[v]) {
      CHECK(of_vertex[v]->distance >= either - 1e-12);
      CHECK(glm::distance(of_vertex[v]->point, mesh.position(v)) == Approx(of_vertex[v]->distance));
    }
  }
}

// A strip folded into a U: two flat arms `gap` apart joined by a half cylinder. Along the surface the
// arms are half the circumference apart, so whether they count as another sheet depends on the wall.
Mesh folded_strip(double gap, Index along, Index across) {
  PolygonSoup s;
  const double arm = 1.0, bend = 3.14159265358979 * gap / 2.0, length = 2.0 * arm + bend;
  for (Index i = 0; i <= along; ++i) {
    const double t = length * i / along;
    Vec3 p;
    if (t < arm)
      p = {arm - t, 0.0, 0.0};
    else if (t < arm + bend) {
      const double angle = (t - arm) / (gap / 2.0);
      p = {-std::sin(angle) * gap / 2.0, gap / 2.0 - std::cos(angle) * gap / 2.0, 0.0};
    } else
      p = {t - arm - bend, gap, 0.0};
    for (Index j = 0; j <= across; ++j) s.add_vertex(p + Vec3(0.0, 0.0, 0.5 * j / across));
  }
  for (Index i = 0; i < along; ++i)
    for (Index j = 0; j < across; ++j) {
      const Index a = i * (across + 1) + j, b = (i + 1) * (across + 1) + j;
      s.add_face({a, b, b + 1, a + 1});
    }
  return build_mesh(std::move(s));
}

}  // namespace

TEST_CASE("near misses on a folded strip agree with their definition for walls around its fold", "[kernel]") {
  const Mesh strip = folded_strip(0.1, 60, 4);
  // The arms are 0.1 apart and 0.157 apart along the fold: walls below 0.052 see the other arm outside
  // the neighbourhood but not within the wall, walls above 0.1 see it within the wall but inside.
  for (const double wall : {0.03, 0.05, 0.06, 0.09, 0.12}) check_against_definition(strip, wall);
}

TEST_CASE("near misses between random linked tori agree with their definition", "[kernel]") {
  const unsigned base = test::seed_base();
  for (unsigned run = 0; run < 6; ++run) {
    std::mt19937 rng(base + run);
    INFO("seed " << base + run);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double minor = 0.3 + 0.18 * unit(rng);
    const Mesh a = build_mesh(test::torus(24, 12, 1.0, minor));
    const glm::dmat4 place = glm::rotate(glm::translate(glm::dmat4(1.0), Vec3(1.0, 0.05 * unit(rng), 0.0)),
                                         glm::radians(80.0 + 20.0 * unit(rng)), Vec3(1, 0, 0));
    const Mesh both = build_mesh(test::disjoint_union(to_soup(a), to_soup(transformed(a, place))));
    check_against_definition(both, 0.02 + 0.2 * unit(rng));
  }
}
