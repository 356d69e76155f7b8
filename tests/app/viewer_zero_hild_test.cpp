// The report's other two cases (sections 8.3 and 8.4) walked through the viewer: Perry's "Zero" from
// SLIDE's zero.sif to a printable solid, and Eva Hild's snow sculpture with coloured instances.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/topology_report.hpp"
#include "render/render_support.hpp"
#include "support/face_colors.hpp"
#include "support/shared_examples.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"
#include "viewer/view/picking.hpp"

using namespace nome;
using nome::test::click_line;

namespace {

// Script lines that click vertex `name` of the shown mesh from the first view where it is clickable;
// empty when no view shows it.
std::string click_vertex(const Mesh& mesh, const std::string& name) {
  const auto& names = mesh.vertex_names();
  const Index v = Index(std::find(names.begin(), names.end(), name) - names.begin());
  if (v == names.size()) return {};
  for (const double elevation : {25.0, -25.0, 60.0, -60.0, 0.0, 89.0, -89.0})
    for (double azimuth = 0; azimuth < 360; azimuth += 30) {
      const auto projection = nome::test::viewer_projection(mesh, azimuth, elevation);
      if (const auto at = nome::test::vertex_click(mesh, projection, v))
        return "view " + std::to_string(int(azimuth)) + " " + std::to_string(int(elevation)) + "\n" +
               click_line(*at);
    }
  return {};
}

// Zero's two ribbons (report 8.3) as the loops of the scene stage: the outer ribbon's inner border (all
// its vertices at one distance from the centre) and the twisted inner ribbon's outer border (the other
// loop whose distance varies most).
struct ZeroRims {
  std::vector<Index> inner;  // the inner ribbon's outer border, in loop order
  std::vector<Index> outer;  // the outer ribbon's inner border
};

ZeroRims zero_rims(const Mesh& mesh) {
  struct Loop {
    std::vector<Index> vertices;
    double low, high;
  };
  std::vector<Loop> loops;
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l) {
    Loop loop{{mesh.loop_vertices(l).begin(), mesh.loop_vertices(l).end()}, 1e300, -1e300};
    for (Index v : loop.vertices) {
      loop.low = std::min(loop.low, glm::length(mesh.position(v)));
      loop.high = std::max(loop.high, glm::length(mesh.position(v)));
    }
    loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.high < b.high; });
  // By size: the inner ribbon's rims (0.018, and 0.003 to 0.033), then the outer ribbon's (0.039, 0.054).
  REQUIRE(loops.size() == 4);
  return {loops[1].vertices, loops[2].vertices};
}

Index next_on(const std::vector<Index>& loop, Index v, int step) {
  const auto at = std::find(loop.begin(), loop.end(), v) - loop.begin();
  return loop[(std::size_t(at) + loop.size() + std::size_t(step)) % loop.size()];
}

}  // namespace

namespace {

// The viewer's own state after each step of the Zero walkthrough (script `state`): each polygon's four
// corners selected, then one temporary face more; each zip's two borders selected, then the strip's faces
// added and two open ends joined; the accepted faces consolidated; the merged surface one-sided with three
// borders; the solid closed and orientable with twice its characteristic.
void check_zero_states(const std::vector<nome::test::ViewerState>& states, int zips, std::size_t added,
                       const TopologyReport& merged) {
  REQUIRE(states.size() == std::size_t(8 + 2 * zips + 3));
  for (std::size_t k = 0; k < 4; ++k) {
    INFO("polygon " << k);
    CHECK(states[2 * k].selected_vertices == 4);
    CHECK(states[2 * k + 1].temporary_faces == long(k + 1));
    CHECK(states[2 * k + 1].consolidated_faces == 0);
  }
  for (int z = 0; z < zips; ++z) {
    INFO("zip " << z);
    const auto &before = states[8 + 2 * z], &after = states[8 + 2 * z + 1];
    CHECK(before.selected_borders == 2);
    CHECK(after.temporary_faces > before.temporary_faces);
    CHECK(after.borders < before.borders);
  }
  const auto &accepted = states[8 + 2 * zips], &merged_state = states[9 + 2 * zips],
             &solid = states[10 + 2 * zips];
  CHECK(accepted.temporary_faces == 0);
  CHECK(accepted.consolidated_faces == long(added));
  CHECK(merged_state.stage == "merged");
  CHECK(merged_state.parts == 1);
  CHECK_FALSE(merged_state.orientable);
  CHECK(merged_state.borders == merged.borders);
  CHECK(merged_state.chi == merged.chi);
  CHECK(solid.stage == "offset");
  CHECK(solid.borders == 0);
  CHECK(solid.orientable);
  CHECK(solid.parts == 1);
  CHECK(solid.chi == 2 * merged.chi);
}

}  // namespace

TEST_CASE(
    "Zero walkthrough: zero.sif paired into quads, four polygons, two zips, consolidated, merged, "
    "subdivided and offset into a printable solid",
    "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const std::string file = nome::test::shared_examples_dir("original") + "zero.sif";
  const std::string dir = nome::test::private_scratch_dir("walkthrough_zero");
  // The test follows the session as the viewer runs it, so that each click lands on the mesh on screen.
  viewer::Session session = viewer::Session::open(file, true);
  viewer::StagePipeline pipeline;
  const PipelineSettings scene_stage = viewer::initial_settings();
  auto shown = [&] { return *pipeline.run(session.scene_input(), scene_stage, nome::stop_token{}); };
  const viewer::StageResult start = shown();
  CHECK(start.mesh->num_faces() < 128);  // of 128 triangles, pairs made quads (report 7.1)
  CHECK(start.topology.components.size() == 2);
  const ZeroRims rims = zero_rims(*start.mesh);
  const auto& names = start.mesh->vertex_names();
  auto position = [&](Index v) { return start.mesh->position(v); };

  // Report 8.3: four polygons join the inner ribbon's border where it reaches farthest along y (its
  // 720 degree twist turns it upright four times) to the nearest edge of the outer ribbon's inner border.
  std::vector<Index> peaks = rims.inner;
  std::sort(peaks.begin(), peaks.end(),
            [&](Index a, Index b) { return std::abs(position(a).y) > std::abs(position(b).y); });
  peaks.resize(4);
  std::sort(peaks.begin(), peaks.end(), [&](Index a, Index b) {
    return std::find(rims.inner.begin(), rims.inner.end(), a) <
           std::find(rims.inner.begin(), rims.inner.end(), b);
  });
  struct Bridge {
    Index inner, inner_next, outer, outer_next;
  };
  std::vector<Bridge> bridges;
  std::string script = "mode vertex\n";
  for (Index peak : peaks) {
    Bridge b{peak, next_on(rims.inner, peak, 1), 0, 0};
    b.outer = *std::min_element(rims.outer.begin(), rims.outer.end(), [&](Index x, Index y) {
      return glm::length(position(x) - position(peak)) < glm::length(position(y) - position(peak));
    });
    const Index sides[] = {next_on(rims.outer, b.outer, 1), next_on(rims.outer, b.outer, -1)};
    b.outer_next = glm::length(position(sides[0]) - position(b.inner_next)) <
                           glm::length(position(sides[1]) - position(b.inner_next))
                       ? sides[0]
                       : sides[1];
    const viewer::StageResult now = shown();
    std::vector<Index> corners;
    for (Index v : {b.inner, b.inner_next, b.outer_next, b.outer}) {
      const std::string clicks = click_vertex(*now.mesh, names[v]);
      REQUIRE_FALSE(clicks.empty());
      script += clicks;
      corners.push_back(
          Index(std::find(now.mesh->vertex_names().begin(), now.mesh->vertex_names().end(), names[v]) -
                now.mesh->vertex_names().begin()));
    }
    script += "state\naction add-polygon\nstate\n";
    REQUIRE(session.add_polygon(*now.mesh, corners).applied);
    bridges.push_back(b);
  }
  CHECK(session.document().temporary_faces().size() == 4);

  // Then the inner ribbon's border between two neighbouring bridges is zipped to the outer ribbon's
  // border between the same bridges, where that stretch holds no other bridge: twice.
  script += "mode border-partial\n";
  int zips = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const Bridge &from = bridges[k], &to = bridges[(k + 1) % 4];
    std::vector<Index> outer_path{from.outer_next};
    for (int step : {1, -1}) {
      outer_path.assign(1, from.outer_next);
      while (outer_path.back() != to.outer)
        outer_path.push_back(next_on(rims.outer, outer_path.back(), step));
      const bool is_free = std::none_of(outer_path.begin() + 1, outer_path.end() - 1, [&](Index v) {
        return std::any_of(bridges.begin(), bridges.end(),
                           [&](const Bridge& b) { return b.outer == v || b.outer_next == v; });
      });
      if (is_free) break;
      outer_path.clear();
    }
    if (outer_path.empty()) continue;
    std::vector<Index> inner_path{from.inner_next};
    while (inner_path.back() != to.inner) inner_path.push_back(next_on(rims.inner, inner_path.back(), 1));
    const viewer::StageResult now = shown();
    viewer::Selection selection;
    selection.set_mode(viewer::SelectionMode::border_partial);
    const auto& now_names = now.mesh->vertex_names();
    for (const auto* path : {&inner_path, &outer_path})
      for (Index v : {path->front(), path->back(), (*path)[path->size() / 2]}) {
        script += click_vertex(*now.mesh, names[v]);
        const Index id = Index(std::find(now_names.begin(), now_names.end(), names[v]) - now_names.begin());
        selection.click_border_vertex(*now.borders, id);
      }
    REQUIRE(selection.borders().size() == 2);
    script += "state\naction zip\nstate\n";
    const auto outcome =
        session.zipper(*now.mesh, viewer::zipper_border(*now.borders, selection.borders()[0]),
                       viewer::zipper_border(*now.borders, selection.borders()[1]), {});
    INFO(outcome.message);
    REQUIRE(outcome.applied);
    ++zips;
  }
  CHECK(zips == 2);
  const std::size_t added = session.document().temporary_faces().size();
  REQUIRE(session.accept_temporary().applied);
  PipelineSettings merged = scene_stage;
  merged.stage = Stage::merged;
  const TopologyReport expected =
      topology_report(*pipeline.run(session.scene_input(), merged, nome::stop_token{})->mesh);
  CHECK(expected.components.size() == 1);
  CHECK_FALSE(expected.orientable);
  CHECK(expected.borders == 3);

  script += "action accept\nstate\naction merge\nstate\nview 30 25\nscreenshot " + dir +
            "/merged.png\nexport " + dir + "/merged.obj\nsubdiv 2\noffset 0.002\nstate\nscreenshot " + dir +
            "/solid.png\nexport " + dir + "/solid.stl\nquit\n";
  const auto r =
      nome::test::run_window(file + " --script " + nome::test::write_script(dir, script),
                             nome::test::TestViewer::private_stores(), nome::test::TestRenderer::gl);
  INFO(r.err);
  REQUIRE(r.status == 0);
  // What the viewer drew: the one-sided merged surface shows both sides' colours; its solid, closed and
  // orientable, shows only its outside.
  const nome::test::SideCounts merged_sides = nome::test::count_sides(render::read_png(dir + "/merged.png"));
  CHECK(merged_sides.front > 5000);
  CHECK(merged_sides.back > 5000);
  const render::Image solid_shot = render::read_png(dir + "/solid.png");
  // Back faces show only along contours over other parts (under 0.5 %; sheets swapped would show half).
  const nome::test::SideCounts solid_sides = nome::test::count_sides(solid_shot);
  CHECK(solid_sides.front > 20000);
  CHECK(solid_sides.back * 200 < solid_sides.front);
  CHECK_THAT(r.err,
             Catch::Contains("accept: " + std::to_string(added) + " faces moved into the consolidated mesh"));
  check_zero_states(nome::test::logged_states(r.err), zips, added, expected);
  const TopologyReport zero = topology_report(build_mesh(read_polygons(dir + "/merged.obj")));
  CHECK(zero.components.size() == 1);
  CHECK_FALSE(zero.orientable);
  CHECK(zero.chi == expected.chi);
  CHECK(zero.borders == expected.borders);
  const TopologyReport solid = topology_report(build_mesh(read_polygons(dir + "/solid.stl")));
  CHECK(solid.borders == 0);
  CHECK(solid.orientable);
  CHECK(solid.components.size() == 1);
  CHECK(solid.chi == 2 * zero.chi);
}

namespace {

// Script lines that click, from the first view that shows one, a face whose name starts with `prefix`.
std::string click_face_of(const Mesh& mesh, const std::string& prefix) {
  for (const double elevation : {25.0, -25.0, 60.0, 0.0})
    for (double azimuth = 0; azimuth < 360; azimuth += 30) {
      const auto projection = nome::test::viewer_projection(mesh, azimuth, elevation);
      for (Index f = 0; f < mesh.num_faces(); ++f) {
        if (!mesh.face_names()[f].starts_with(prefix)) continue;
        const auto at = nome::test::face_click(mesh, projection, f);
        if (at && at->x >= 0)
          return "view " + std::to_string(int(azimuth)) + " " + std::to_string(int(elevation)) + "\n" +
                 click_line(*at);
      }
    }
  return {};
}

}  // namespace

TEST_CASE("Hild walkthrough: three instances selected and coloured, saved and reopened the same", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const std::string file = nome::test::shared_examples_dir("original") + "hild.nom";
  const std::string dir = nome::test::private_scratch_dir("walkthrough_hild");
  const scene::Scene original = read_scene(file);
  const Mesh mesh = build_mesh(original.combined_soup());
  const TopologyReport before = topology_report(mesh);
  // Report 8.4 colours instances and groups: three of the sculpture's instances get new colours.
  const std::pair<std::string, Color> coloured[] = {
      {"sh_tun2", {1.0f, 0.0f, 0.0f}}, {"sh_fun1", {0.0f, 0.0f, 1.0f}}, {"sh_fun3", {0.2f, 0.8f, 0.2f}}};
  std::string script = "mode instance\n";
  for (const auto& [path, color] : coloured) {
    const std::string clicks = click_face_of(mesh, path + "_");
    INFO(path);
    REQUIRE_FALSE(clicks.empty());
    char line[64];
    std::snprintf(line, sizeof line, "color %g %g %g\n", color.r, color.g, color.b);
    script += clicks + "state\n" + line + "action clear-selection\nstate\n";
  }
  script += "save " + dir + "/hild.nome\nquit\n";
  const auto r = nome::test::run_window(file + " --script " + nome::test::write_script(dir, script));
  INFO(r.err);
  REQUIRE(r.status == 0);
  for (const auto& [path, color] : coloured)
    CHECK_THAT(r.err, Catch::Contains("instance " + path + " selected"));
  CHECK_THAT(r.err, Catch::Contains("color: 1 instance coloured (1, 0, 0) (surface rgb_ff0000)"));
  // The viewer's own state: one instance selected before each colour, none after; the topology unchanged.
  const std::vector<nome::test::ViewerState> states = nome::test::logged_states(r.err);
  REQUIRE(states.size() == 2 * std::size(coloured));
  for (std::size_t k = 0; k < states.size(); ++k) {
    INFO("state " << k);
    CHECK(states[k].selected_instances == (k % 2 == 0 ? 1 : 0));
    CHECK(states[k].chi == before.chi);
    CHECK(states[k].borders == before.borders);
    CHECK(states[k].faces == before.faces);
  }

  const scene::Scene saved = read_scene(dir + "/hild.nome");
  const PolygonSoup soup = saved.combined_soup();
  for (const auto& [path, color] : coloured) {
    INFO(path);
    Index faces = 0;
    for (Index f = 0; f < soup.num_faces(); ++f)
      if (soup.face_names[f].starts_with(path + "_")) {
        CHECK(glm::length(test::face_colors(soup)[f] - color) < 0.01f);
        ++faces;
      }
    CHECK(faces > 0);
  }
  // The instances not coloured keep theirs.
  const PolygonSoup first = original.combined_soup();
  for (Index f = 0; f < first.num_faces(); ++f)
    if (first.face_names[f].starts_with("sh_tun1_"))
      CHECK(test::face_colors(soup)[f] == test::face_colors(first)[f]);
  const TopologyReport after = topology_report(build_mesh(soup));
  CHECK(after.vertices == before.vertices);
  CHECK(after.faces == before.faces);
  CHECK(after.chi == before.chi);
  CHECK(after.borders == before.borders);
}
