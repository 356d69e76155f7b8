#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "nome/mesh/topology_report.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/query/print_check.hpp"
#include "nome/query/triangle_proximity.hpp"
#include "scene/scene_support.hpp"
#include "support/shapes.hpp"
#include "support/shared_examples.hpp"

using namespace nome;

namespace {

PrintCheck check_surface(const Mesh& surface, double distance, double wall = 0.0, int threads = 1) {
  PrintCheckOptions options;
  options.offset_distance = distance;
  options.min_wall = wall;
  options.threads = threads;
  return check_printability(surface, options);
}

// Two tori (major radius 1) linked like chain links: their centre circles stay exactly 1 apart, so the
// tubes of minor radius r leave a gap of 1 - 2r everywhere.
Mesh linked_tori(double minor) {
  const Mesh a = build_mesh(test::torus(48, 24, 1.0, minor));
  const glm::dmat4 place =
      glm::rotate(glm::translate(glm::dmat4(1.0), Vec3(1, 0, 0)), glm::radians(90.0), Vec3(1, 0, 0));
  PolygonSoup both = test::disjoint_union(to_soup(a), to_soup(transformed(a, place)));
  return build_mesh(std::move(both));
}

}  // namespace

TEST_CASE("two triangles cross along the segment where each cuts the other", "[kernel]") {
  const Triangle flat{Vec3(-1, -1, 0), Vec3(2, -1, 0), Vec3(-1, 2, 0)};
  const Triangle standing{Vec3(0, 0, -1), Vec3(0.5, 0, 1), Vec3(0, 0.5, 1)};
  CrossingSegment segment;
  REQUIRE(triangles_cross(flat, standing, segment));
  CHECK(segment.from.z == Approx(0.0).margin(1e-12));
  CHECK(segment.to.z == Approx(0.0).margin(1e-12));
  CHECK(glm::distance(segment.from, segment.to) == Approx(0.25 * std::sqrt(2.0)));
  const Triangle above{Vec3(0, 0, 0.5), Vec3(1, 0, 1), Vec3(0, 1, 1)};
  CHECK_FALSE(triangles_cross(flat, above, segment));
  CHECK(closest_point_on_triangle(Vec3(0, 0, 3), flat) == Vec3(0, 0, 0));
  CHECK(closest_point_on_triangle(Vec3(-2, -2, 1), flat) == Vec3(-1, -1, 0));
}

TEST_CASE("a torus offset at a safe distance is printable", "[kernel]") {
  const Mesh torus = build_mesh(test::torus(48, 24));
  const PrintCheck result = check_surface(torus, 0.05);
  CHECK(result.min_wall == 0.1);
  CHECK(result.fold_over_faces.empty());
  CHECK(result.crossings.pairs.empty());
  CHECK(result.near_misses.empty());
  CHECK(result.places.empty());
  CHECK(result.is_printable());
}

TEST_CASE("a torus offset by more than its minor radius folds over", "[kernel]") {
  const Mesh torus = build_mesh(test::torus(48, 24));
  const PrintCheck result = check_surface(torus, 0.35);
  // The inner copy of every face turns inside out: the tube's radius would be negative.
  CHECK(result.fold_over_faces.size() == torus.num_faces());
  CHECK_FALSE(result.is_printable());
  REQUIRE_FALSE(result.places.empty());
  CHECK(result.places[0].kind == FindingKind::fold_over);
  CHECK(result.places[0].size == torus.num_faces());
}

TEST_CASE("offset faces that pass through their neighbour across a narrow crease fold over", "[kernel]") {
  // Two unit squares meeting at a 20 degree V: inside the V, copies offset by more than tan(10 degrees)
  // have passed through each other (the angle between them closed through zero), long before either
  // copy's normal turns over (at 1 / cos(10 degrees)), which the first rule alone would wait for.
  const double c = std::cos(glm::radians(10.0)), s = std::sin(glm::radians(10.0));
  PolygonSoup soup;
  for (const Vec3& p :
       {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(c, s, 1), Vec3(c, s, 0), Vec3(c, -s, 0), Vec3(c, -s, 1)})
    soup.add_vertex(p);
  soup.add_face({0, 1, 2, 3});
  soup.add_face({1, 0, 4, 5});
  const Mesh crease = build_mesh(std::move(soup));
  const PrintCheck safe = check_surface(crease, 0.1);
  CHECK(safe.fold_over_faces.empty());
  const PrintCheck crossed = check_surface(crease, 0.5);
  CHECK(crossed.fold_over_faces == std::vector<Index>{0, 1});
  CHECK_FALSE(crossed.is_printable());
  // Past 1 / cos(10 degrees) the copies' normals turn over as well.
  CHECK(check_surface(crease, 1.2).fold_over_faces == std::vector<Index>{0, 1});
}

TEST_CASE("linked tori closer than the wall are near misses, not crossings", "[kernel]") {
  const Mesh tori = linked_tori(0.45);  // gap 0.1
  const PrintCheck thin = check_surface(tori, 0.08);
  CHECK(thin.fold_over_faces.empty());
  CHECK(thin.crossings.pairs.empty());
  REQUIRE_FALSE(thin.near_misses.empty());
  CHECK_FALSE(thin.is_printable());
  REQUIRE(thin.places[0].kind == FindingKind::near_miss);
  // The vertices sit on the tube; the nearest point of the other tube is a little under the gap away.
  CHECK(thin.places[0].distance == Approx(0.1).margin(0.01));
  CHECK(thin.places[0].other_face != no_index);
  // The same shapes with a thinner wall, and with two threads (the same findings).
  CHECK(check_surface(tori, 0.04).is_printable());
  const PrintCheck threaded = check_surface(tori, 0.08, 0.0, 2);
  CHECK(threaded.near_misses.size() == thin.near_misses.size());
}

TEST_CASE("tori passing through each other cross along curves", "[kernel]") {
  const Mesh tori = linked_tori(0.6);  // the tubes overlap
  const PrintCheck result = check_surface(tori, 0.02);
  CHECK(result.crossings.curves >= 1);
  CHECK_FALSE(result.crossings.faces.empty());
  for (const Crossing& c : result.crossings.pairs)
    CHECK(tori.face_component(c.face) != tori.face_component(c.other_face));
  // Crossings are where the slab fuses by design; away from them nothing is thin.
  CHECK(result.near_misses.empty());
  CHECK(result.is_printable());
}

TEST_CASE("the original closed Klein bottle crosses itself and prints", "[kernel][scene]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const scene::Scene s = test::load_scene_file(test::originals_dir() + "kleinbottle_savework.nom");
  PipelineSettings settings;
  settings.stage = Stage::subdivided;
  settings.should_merge = true;
  settings.subdivision_levels = 2;
  Pipeline pipeline;
  pipeline.set_input(PipelineInput{s.combined_soup(), {}, Joining::manifold});
  const Mesh& surface = pipeline.run(settings);
  const TopologyReport topology = topology_report(surface);
  REQUIRE(topology.borders == 0);
  REQUIRE_FALSE(topology.orientable);
  const PrintCheck result = check_surface(surface, 0.03);
  CHECK(result.crossings.curves >= 1);
  CHECK(result.fold_over_faces.empty());
  CHECK(result.near_misses.empty());
  CHECK(result.is_printable());
}
