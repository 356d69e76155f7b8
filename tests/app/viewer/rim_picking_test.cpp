// Rim lines (report 6.3) in the viewer: their vertices' cubes are clicked like vertices, and a rim line
// is zipped like a border.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/scene/scene_rim_lines.hpp"

using namespace nome;

namespace {

// A funnel ringed by a closed rim line of eight points at the height of its high circle.
std::string write_funnel_and_rim(const std::string& dir) {
  std::string text = "funnel fun (8 1 0.5 1) endfunnel\n";
  for (int i = 0; i < 8; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 8;
    text += "point p" + std::to_string(i) + " (" + std::to_string(2.5 * std::cos(a)) + " " +
            std::to_string(2.5 * std::sin(a)) + " 1) endpoint\n";
  }
  text += "polyline ring (p0 p1 p2 p3 p4 p5 p6 p7) isloop endpolyline\n";
  text += "instance f fun endinstance\ninstance r ring endinstance\n";
  const std::string path = dir + "/funnel_and_rim.nome";
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("rim vertices are clicked on their cubes, become polygon corners, and a rim line is zipped",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_rim_picking");
  const std::string file = write_funnel_and_rim(dir);
  const scene::Scene scene = read_scene(file);
  const Mesh mesh = glue_faces(scene.combined_soup()).mesh;
  const RimLines rims = scene::scene_rim_lines(scene);
  std::vector<Vec3> points(mesh.positions().begin(), mesh.positions().end());
  points.insert(points.end(), rims.positions.begin(), rims.positions.end());
  const auto projection = nome::test::viewer_projection(points, 30.0, 25.0);
  // The rim vertices whose cubes a click reaches: in front of the funnel, and clicked at their centres.
  std::vector<std::pair<Index, glm::dvec2>> visible;
  for (Index k = 0; k < rims.num_vertices(); ++k) {
    const auto pixel = nome::test::pixel_of(projection, rims.positions[k]);
    if (pixel && nome::test::is_in_sight(mesh, projection, rims.positions[k], -0.05))
      visible.emplace_back(k, glm::round(*pixel));
  }
  REQUIRE(visible.size() >= 2);
  // The funnel vertex on its high circle beside a clickable rim vertex (the zipper matches the two
  // clicked vertices), where a click picks it.
  std::optional<glm::dvec2> high;
  std::size_t ring = 0;
  for (; ring < visible.size() && !high; ++ring) {
    Index nearest = no_index;
    for (Index v = 0; v < mesh.num_vertices(); ++v)
      if (mesh.vertex_names()[v].find("_hc") != std::string::npos &&
          (nearest == no_index ||
           glm::length(mesh.position(v) - rims.positions[visible[ring].first]) <
               glm::length(mesh.position(nearest) - rims.positions[visible[ring].first])))
        nearest = v;
    high = nome::test::vertex_click(mesh, projection, nearest);
  }
  REQUIRE(high);
  const glm::dvec2 ring_click = visible[ring - 1].second;
  const glm::dvec2 other_click = visible[ring == 1 ? 1 : 0].second;

  using nome::test::click_line;
  const std::string script = "view 30 25\nmode vertex\n" + click_line(ring_click) + click_line(other_click) +
                             click_line(*high) + "action add-polygon\naction clear\nmode border\n" +
                             click_line(ring_click) + click_line(*high) +
                             "action zip\naction accept\naction merge\nexport " + dir + "/merged.obj\nquit\n";
  const auto r = nome::test::run_window(file + " --script " + nome::test::write_script(dir, script));
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("rim vertex " + rims.names[visible[ring - 1].first] + " selected"));
  CHECK_THAT(r.err, Catch::Contains("add-polygon: added edit1 to the temporary mesh"));
  CHECK_THAT(r.err, Catch::Contains("rim line of 8 vertices selected"));
  CHECK_THAT(r.err, Catch::Contains("zip: zipper: 8 quads and 0 triangles"));
  // The funnel and the ring are one surface: an annulus, bounded by the base circle and the ring.
  const TopologyReport merged = topology_report(build_mesh(read_polygons(dir + "/merged.obj")));
  CHECK(merged.components.size() == 1);
  CHECK(merged.borders == 2);
  CHECK(merged.orientable);
  CHECK(merged.chi == 0);
}
