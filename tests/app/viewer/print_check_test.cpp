#include <catch2/catch.hpp>

#include <algorithm>

#include <glm/geometric.hpp>

#include "app/viewer_support.hpp"
#include "nome/mesh/polygon_soup.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/subdivide.hpp"
#include "render/image.hpp"
#include "support/shapes.hpp"
#include "viewer/tools/print_check_job.hpp"
#include "viewer/tools/print_check_tool.hpp"
#include "viewer/window.hpp"

using namespace nome;

namespace {

Vec3 print_face_centroid(const Mesh& mesh, Index f) {
  Vec3 sum(0.0);
  for (const Index v : mesh.face_vertices(f)) sum += mesh.position(v);
  return sum / double(mesh.face_degree(f));
}

// The mean of the centroids of the shown faces in the ranges.
Vec3 mean_centroid(const Mesh& shown, const std::vector<std::array<Index, 2>>& ranges) {
  Vec3 sum(0.0);
  Index count = 0;
  for (const auto& [first, end] : ranges)
    for (Index g = first; g < end; ++g, ++count) sum += print_face_centroid(shown, g);
  return sum / double(count);
}

// Pixels whose colour is mostly the given hue, whatever the shading: red (crossings) or magenta (fold-overs).
int count_marked_pixels(const render::Image& image, bool is_magenta) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      const bool is_red = p[0] > 90 && p[1] * 3 < p[0] && p[2] * 3 < p[0];
      const bool is_purple = p[0] > 90 && p[2] > 90 && p[1] * 3 < std::min(p[0], p[2]);
      count += (is_magenta ? is_purple : is_red) ? 1 : 0;
    }
  return count;
}

viewer::ViewerOptions print_check_options(const std::string& dir, const std::string& file,
                                          const std::string& script) {
  viewer::ViewerOptions options;
  options.file = file;
  options.script = nome::test::write_script(dir, script);
  return options;
}

}  // namespace

TEST_CASE("the faces of the offset stages are found from the checked surface's faces", "[app]") {
  const Mesh surface = build_mesh(test::torus(12, 8));
  OffsetOptions thick;
  thick.distance = 0.05;
  const Mesh solid = offset(surface, thick);
  SubdivisionOptions twice;
  twice.levels = 2;
  const Mesh rounded = subdivide(solid, twice);
  // The surface face whose centroid is nearest to p.
  auto nearest_face = [&](const Vec3& p) {
    Index best = 0;
    for (Index g = 1; g < surface.num_faces(); ++g)
      if (glm::distance(p, print_face_centroid(surface, g)) <
          glm::distance(p, print_face_centroid(surface, best)))
        best = g;
    return best;
  };
  for (Index f = 0; f < surface.num_faces(); ++f) {
    const auto on_solid = viewer::shown_faces_of(surface, f, Stage::offset, 0, solid);
    REQUIRE(on_solid.size() == 2);
    for (const auto& range : on_solid) CHECK(nearest_face(mean_centroid(solid, {range})) == f);
    const auto on_rounded = viewer::shown_faces_of(surface, f, Stage::subdivided_offset, 2, rounded);
    REQUIRE(on_rounded.size() == 2);
    CHECK(on_rounded[0][1] - on_rounded[0][0] == 16);
    for (const auto& range : on_rounded) CHECK(nearest_face(mean_centroid(rounded, {range})) == f);
  }
  CHECK(viewer::shown_faces_of(surface, 0, Stage::subdivided, 0, surface).size() == 1);
  // Not numbered from the surface: nothing to paint.
  CHECK(viewer::shown_faces_of(surface, 0, Stage::scene, 0, rounded).empty());
}

TEST_CASE("the viewer's print check marks a torus offset past its minor radius and frames its worst place",
          "[app][render]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_print_check_fold");
  // The torus's tube has radius 0.35: an offset of 0.5 turns its inside over.
  const std::string script = "offset 0.5\naction print-check\nview 30 60\nscreenshot " + dir +
                             "/folded.png\naction next-print-place\nquit\n";
  nome::test::TestViewer viewer(print_check_options(dir, nome::test::assets + "torus.obj", script), {},
                                nome::test::TestRenderer::gl);
  CHECK(viewer.run() == 0);
  CHECK_THAT(viewer.messages(), Catch::Contains("print check: not printable"));
  const viewer::PrintCheckRun* run = viewer.window().find_tool<viewer::PrintCheckTool>()->job().last();
  REQUIRE(run);
  CHECK(!run->check.fold_over_faces.empty());
  CHECK(!run->check.is_printable());
  // Fold-over faces in magenta on the solid.
  CHECK(count_marked_pixels(render::read_png(dir + "/folded.png"), true) > 200);
  // The place framed: the camera looks at it, closer than the whole torus.
  const Vec3 place = run->check.places[0].position;
  CHECK(glm::distance(viewer.window().camera().target, place) < 1e-6);
}

TEST_CASE("the viewer checks the Klein bottle after an offset change once it rests: crossings in red",
          "[app][render]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_print_check_klein");
  // No check is asked for: the wait lets the automatic one start once the geometry rested.
  std::string script = "subdiv 1\noffset 0.03\n";
  for (int i = 0; i < 40; ++i) script += "view 30 25\n";
  script += "screenshot " + dir + "/klein.png\nquit\n";
  nome::test::TestViewer viewer(print_check_options(dir, nome::test::assets + "klein_bottle.obj", script), {},
                                nome::test::TestRenderer::gl);
  CHECK(viewer.run() == 0);
  const viewer::PrintCheckRun* run = viewer.window().find_tool<viewer::PrintCheckTool>()->job().last();
  REQUIRE(run);
  CHECK(run->check.offset_distance == 0.03);
  CHECK(run->check.crossings.curves > 0);
  CHECK(run->check.fold_over_faces.empty());
  CHECK(count_marked_pixels(render::read_png(dir + "/klein.png"), false) > 200);
}
