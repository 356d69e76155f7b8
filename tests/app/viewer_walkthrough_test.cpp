#include <catch2/catch.hpp>

#include <fstream>
#include <limits>

#include "app/viewer_support.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/query/border_lookup.hpp"
#include "render/render_support.hpp"
#include "viewer/session/session.hpp"
#include "viewer/session/stage_pipeline.hpp"

using namespace nome;
using nome::test::run_window;

// The report's walkthroughs (sections 8.1 and 8.2) as scripted sessions in this process, on the null
// renderer: the same clicks a person makes.
namespace {

const std::string examples = std::string(NOME_SOURCE_DIR) + "/assets/";

using nome::test::click_line;

// What the scene stage shows of a scene file (before any edit).
Mesh scene_mesh(const std::string& file) {
  return glue_faces(read_scene(file).combined_soup()).mesh;
}

std::string instance_of(const std::string& vertex) {
  return vertex.substr(0, vertex.rfind('_'));
}

// The script lines that end both walkthroughs (report Fig. 11d, 12d): the merged mesh `merged.obj` is
// subdivided, thickened, framed and exported as `solid.stl`.
std::string subdivide_and_offset(const std::string& dir) {
  return "action merge\nexport " + dir + "/merged.obj\nsubdiv 2\noffset 0.05\nkey F\nexport " + dir +
         "/solid.stl\n";
}

// The thickened surface is a closed orientable solid's skin, twice the merged surface's Euler
// characteristic (two sheets joined along rim strips of characteristic 0; one-sided surfaces give their
// orientable double cover).
void check_solid(const std::string& dir) {
  const TopologyReport merged = topology_report(build_mesh(read_polygons(dir + "/merged.obj")));
  const TopologyReport solid = topology_report(build_mesh(read_polygons(dir + "/solid.stl")));
  CHECK(solid.borders == 0);
  CHECK(solid.orientable);
  CHECK(solid.chi == 2 * merged.chi);
  CHECK(solid.components.size() == merged.components.size());
}

}  // namespace

TEST_CASE("funnel cube walkthrough: three rim vertices become a consolidated polygon that is saved",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("walkthrough_funnel_cube");
  const std::string file = examples + "funnel_cube.nome";
  const Mesh mesh = scene_mesh(file);
  const auto projection = nome::test::viewer_projection(mesh, 30.0, 25.0);
  // Clickable rim vertices (the funnels' high circles), and the closest triple from three funnels.
  std::vector<std::pair<Index, glm::dvec2>> rim;
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    if (mesh.vertex_names()[v].find("_hc") != std::string::npos)
      if (const auto p = nome::test::vertex_click(mesh, projection, v)) rim.emplace_back(v, *p);
  REQUIRE(rim.size() >= 3);
  double best = std::numeric_limits<double>::infinity();
  std::array<std::size_t, 3> triple{};
  auto distance = [&](std::size_t i, std::size_t j) {
    return glm::length(mesh.position(rim[i].first) - mesh.position(rim[j].first));
  };
  for (std::size_t i = 0; i < rim.size(); ++i)
    for (std::size_t j = i + 1; j < rim.size(); ++j)
      for (std::size_t k = j + 1; k < rim.size(); ++k) {
        const auto a = instance_of(mesh.vertex_names()[rim[i].first]),
                   b = instance_of(mesh.vertex_names()[rim[j].first]),
                   c = instance_of(mesh.vertex_names()[rim[k].first]);
        if (a == b || b == c || a == c) continue;
        const double perimeter = distance(i, j) + distance(j, k) + distance(k, i);
        if (perimeter < best) {
          best = perimeter;
          triple = {i, j, k};
        }
      }
  REQUIRE(best < std::numeric_limits<double>::infinity());
  std::string clicks;
  for (std::size_t i : triple) clicks += click_line(rim[i].second);
  const std::string script_path = dir + "/script.txt";
  std::ofstream(script_path) << "view 30 25\nmode vertex\n"
                             << clicks << "action add-polygon\naction accept\n"
                             << "save " << dir << "/saved.nome\nquit\n";
  const auto r = run_window(file + " --script " + script_path);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("add-polygon: "));
  CHECK_THAT(r.err, Catch::Contains("accept: "));
  const scene::Scene saved = read_scene(dir + "/saved.nome");
  REQUIRE(saved.edits().consolidated.size() == 1);
  const auto& face = saved.edits().consolidated[0];
  REQUIRE(face.size() == 3);
  std::vector<std::string> clicked;
  for (std::size_t i : triple) clicked.push_back(mesh.vertex_names()[rim[i].first]);
  for (const std::string& name : face) {
    INFO(name);
    CHECK(std::find(clicked.begin(), clicked.end(), saved.resolve_vertex_name(name)) != clicked.end());
  }
}

TEST_CASE("Klein bottle walkthrough: two neighbouring tunnel rims are zipped, undone and redone", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("walkthrough_klein_bottle");
  const std::string file = examples + "klein_bottle.nome";
  const Mesh mesh = scene_mesh(file);
  const auto projection = nome::test::viewer_projection(mesh, 30.0, 25.0);
  // Each border loop's first clickable vertex, and the two loops (of different tunnels) whose centres
  // are nearest: the rims the report zips first.
  struct Rim {
    Index loop;
    Vec3 centre;
    glm::dvec2 click;
    std::string instance;
  };
  std::vector<Rim> rims;
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l) {
    Vec3 centre(0.0);
    for (Index v : mesh.loop_vertices(l)) centre += mesh.position(v) / double(mesh.loop_vertices(l).size());
    for (Index v : mesh.loop_vertices(l))
      if (const auto p = nome::test::vertex_click(mesh, projection, v)) {
        rims.push_back({l, centre, *p, instance_of(mesh.vertex_names()[v])});
        break;
      }
  }
  double best = std::numeric_limits<double>::infinity();
  std::pair<std::size_t, std::size_t> pair{};
  for (std::size_t i = 0; i < rims.size(); ++i)
    for (std::size_t j = i + 1; j < rims.size(); ++j)
      if (rims[i].instance != rims[j].instance && glm::length(rims[i].centre - rims[j].centre) < best) {
        best = glm::length(rims[i].centre - rims[j].centre);
        pair = {i, j};
      }
  REQUIRE(best < std::numeric_limits<double>::infinity());
  const std::string script_path = dir + "/script.txt";
  // Merged first: showing another stage is a step of the undo history too, and the undo is the zip's.
  // `state` after each step: the viewer's own topology line, selection and face counts.
  std::ofstream(script_path) << "view 30 25\naction merge\nstate\nmode border\n"
                             << click_line(rims[pair.first].click) << click_line(rims[pair.second].click)
                             << "state\naction zip\nstate\nexport " << dir << "/zipped.obj\n"
                             << "action undo\nstate\nexport " << dir << "/undone.obj\n"
                             << "action redo\nstate\n"
                             << subdivide_and_offset(dir) << "state\nscreenshot " << dir
                             << "/solid.png\nquit\n";
  const auto r = run_window(file + " --script " + script_path, nome::test::TestViewer::private_stores(),
                            nome::test::TestRenderer::gl);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("zip: "));
  // The viewer draws the closed orientable solid from outside only.
  const render::Image solid_shot = render::read_png(dir + "/solid.png");
  // Back faces show only along contours over other parts (under 0.5 %; sheets swapped would show half).
  const nome::test::SideCounts solid_sides = nome::test::count_sides(solid_shot);
  CHECK(solid_sides.front > 20000);
  CHECK(solid_sides.back * 200 < solid_sides.front);
  const std::vector<nome::test::ViewerState> states = nome::test::logged_states(r.err);
  REQUIRE(states.size() == 6);
  const auto &merged = states[0], &picked = states[1], &zipped_state = states[2], &undone_state = states[3],
             &redone = states[4], &solid = states[5];
  CHECK(merged.stage == "merged");
  CHECK(merged.selected_borders == 0);
  CHECK(picked.selected_borders == 2);
  CHECK(picked.borders == merged.borders);
  // The zip's strip closes both rims, as new faces of the session; undo takes them away, redo back.
  CHECK(zipped_state.borders + 2 == picked.borders);
  CHECK(zipped_state.temporary_faces + zipped_state.consolidated_faces >
        picked.temporary_faces + picked.consolidated_faces);
  CHECK(undone_state.borders == picked.borders);
  CHECK(undone_state.temporary_faces + undone_state.consolidated_faces ==
        picked.temporary_faces + picked.consolidated_faces);
  CHECK(redone.borders == zipped_state.borders);
  CHECK(redone.faces == zipped_state.faces);
  CHECK(solid.stage == "offset");
  CHECK(solid.borders == 0);
  CHECK(solid.orientable);
  CHECK(solid.chi == 2 * zipped_state.chi);
  // Merged, the strip closes both rims: two borders fewer than without it.
  const Index zipped = topology_report(build_mesh(read_polygons(dir + "/zipped.obj"))).borders;
  const Index undone = topology_report(build_mesh(read_polygons(dir + "/undone.obj"))).borders;
  CHECK(zipped + 2 == undone);
  check_solid(dir);
  CHECK(topology_report(build_mesh(read_polygons(dir + "/merged.obj"))).borders == zipped);
}

TEST_CASE("funnel cube walkthrough, last step: the eight consolidated corners merged, subdivided and offset",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("walkthrough_funnel_cube_solid");
  const std::string script_path = dir + "/script.txt";
  std::ofstream(script_path) << "view 30 25\n" << subdivide_and_offset(dir) << "quit\n";
  const auto r = run_window(examples + "funnel_cube_consolidated.nome --script " + script_path);
  INFO(r.err);
  REQUIRE(r.status == 0);
  check_solid(dir);
  // The corners join the funnels' inner rims: only the six outer rims stay open (report Fig. 11d).
  CHECK(topology_report(build_mesh(read_polygons(dir + "/merged.obj"))).borders == 6);
}

TEST_CASE("a script moves sliders by name and an unknown slider fails the session", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("viewer_sliders");
  const std::string script_path = dir + "/script.txt";
  std::ofstream(script_path) << "set fp_n 6\nexport " << dir << "/six.obj\nset fp_n 8\nexport " << dir
                             << "/eight.obj\nset fp_m 3\nquit\n";
  const auto r = run_window(examples + "funnel_cube.nome --script " + script_path);
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("no slider 'fp_m'"));
  const Index six = build_mesh(read_polygons(dir + "/six.obj")).num_faces();
  const Index eight = build_mesh(read_polygons(dir + "/eight.obj")).num_faces();
  CHECK(six * 8 == eight * 6);
}

TEST_CASE(
    "Klein bottle walkthrough, start to finish: five zips close the tunnels into a Klein bottle, "
    "then a solid",
    "[app]") {
  const std::string dir = nome::test::private_scratch_dir("walkthrough_klein_bottle_all");
  const std::string file = examples + "klein_bottle.nome";
  // The test follows the session as the viewer runs it (same Session, same merged stage), so that each
  // click lands on a vertex of the mesh on screen at that moment.
  viewer::Session session = viewer::Session::open(file);
  viewer::StagePipeline pipeline;
  PipelineSettings merged = viewer::initial_settings();
  merged.stage = Stage::merged;
  auto shown = [&] { return *pipeline.run(session.scene_input(), merged, nome::stop_token{}); };
  // The report's chain of rims: t1 up into t2, across t3, down t4 into the outer t5, whose lower rim
  // turns in to meet t1's (the inverted sock). A rim is named by a vertex of it and its loop's centre.
  const viewer::StageResult start = shown();
  auto rim = [&](const std::string& instance, int axis, bool is_high) {
    std::string best;
    double extreme = is_high ? -1e300 : 1e300;
    for (Index l = 0; l < start.mesh->num_boundary_loops(); ++l) {
      const auto loop = start.borders->loop_vertices(l);
      if (!start.mesh->vertex_names()[loop[0]].starts_with("kb_" + instance + "_")) continue;
      double centre = 0.0;
      for (Index v : loop) centre += start.mesh->position(v)[axis] / double(loop.size());
      if (is_high ? centre > extreme : centre < extreme) {
        extreme = centre;
        best = start.mesh->vertex_names()[loop[0]];
      }
    }
    return best;
  };
  const std::pair<std::string, std::string> zips[] = {{rim("t1", 2, true), rim("t2", 2, false)},
                                                      {rim("t2", 2, true), rim("t3", 0, false)},
                                                      {rim("t3", 0, true), rim("t4", 2, true)},
                                                      {rim("t4", 2, false), rim("t5", 2, true)},
                                                      {rim("t5", 2, false), rim("t1", 2, false)}};
  std::string script = "action merge\nmode border\n";
  const std::pair<double, double> views[] = {{30, 25},  {210, 25}, {30, -25}, {210, -25},
                                             {120, 10}, {300, 10}, {0, 80},   {0, -80}};
  for (const auto& [first, second] : zips) {
    REQUIRE_FALSE(first.empty());
    REQUIRE_FALSE(second.empty());
    const viewer::StageResult now = shown();
    const auto& names = now.mesh->vertex_names();
    auto clickable = [&](const std::string& name,
                         const ScreenProjection& projection) -> std::optional<std::pair<Index, glm::dvec2>> {
      const Index v = Index(std::find(names.begin(), names.end(), name) - names.begin());
      if (v == names.size() || !now.borders->is_on_border(v)) return std::nullopt;
      for (Index u : now.borders->loop_vertices(now.borders->loop_of(v)))
        if (const auto p = nome::test::vertex_click(*now.mesh, projection, u)) return std::pair{u, *p};
      return std::nullopt;
    };
    bool is_zipped = false;
    for (const auto& [azimuth, elevation] : views) {
      const auto projection = nome::test::viewer_projection(*now.mesh, azimuth, elevation);
      const auto a = clickable(first, projection), b = clickable(second, projection);
      if (!a || !b) continue;
      script += "view " + std::to_string(int(azimuth)) + " " + std::to_string(int(elevation)) + "\n" +
                click_line(a->second) + click_line(b->second) + "action zip\n";
      REQUIRE(
          session.zipper(*now.mesh, {a->first, a->first, false}, {b->first, b->first, false}, {}).applied);
      is_zipped = true;
      break;
    }
    INFO(first << " and " << second);
    REQUIRE(is_zipped);
  }
  const TopologyReport expected = topology_report(*shown().mesh);
  CHECK(expected.borders == 0);
  CHECK(expected.chi == 0);
  CHECK_FALSE(expected.orientable);
  std::ofstream(dir + "/script.txt") << script << "view 120 25\n" << subdivide_and_offset(dir) << "quit\n";
  const auto r = run_window(file + " --script " + dir + "/script.txt");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const TopologyReport bottle = topology_report(build_mesh(read_polygons(dir + "/merged.obj")));
  CHECK(bottle.borders == 0);
  CHECK(bottle.chi == 0);
  CHECK_FALSE(bottle.orientable);
  check_solid(dir);
}

TEST_CASE(
    "funnel cube walkthrough, start to finish: the report's sliders and four polygons at a corner, "
    "accepted and saved as the report saved them",
    "[app]") {
  const std::string dir = nome::test::private_scratch_dir("walkthrough_funnel_cube_corner");
  const std::string file = examples + "funnel_cube.nome";
  // The report's slider values are those of the file it saved, and its corner polygons those of the
  // file's `mesh m1` (report Fig. 11b).
  const scene::Scene report = read_scene(examples + "funnel_cube_consolidated.nome");
  const std::vector<std::vector<std::string>> polygons = {{"fun3_hc3", "fun2_hc5", "fun2_hc6", "fun3_hc2"},
                                                          {"fun3_hc3", "fun5_hc3", "fun2_hc5"},
                                                          {"fun3_hc4", "fun5_hc2", "fun5_hc3", "fun3_hc3"},
                                                          {"fun5_hc3", "fun5_hc4", "fun2_hc4", "fun2_hc5"}};
  viewer::Session session = viewer::Session::open(file);
  std::string script;
  for (const char* name : {"fp_ro", "fp_ratio", "fp_h", "fp_z"}) {
    const double value = report.parameters()[*report.find_parameter(name)].value;
    session.set_parameter(name, value);
    script += "set " + std::string(name) + " " + std::to_string(value) + "\n";
  }
  script += "mode vertex\n";
  viewer::StagePipeline pipeline;
  const PipelineSettings scene_stage = viewer::initial_settings();
  std::vector<std::pair<double, double>> views;
  for (const double elevation : {-35.0, 35.0, 0.0})
    for (double azimuth = 0; azimuth < 360; azimuth += 30) views.emplace_back(azimuth, elevation);
  for (const auto& face : polygons) {
    const auto now = pipeline.run(session.scene_input(), scene_stage, nome::stop_token{});
    const auto& names = now->mesh->vertex_names();
    // A view where every corner is clickable (a corner may have copies in earlier temporary faces: any
    // copy carries the name the polygon is made of).
    bool is_added = false;
    for (const auto& [azimuth, elevation] : views) {
      const auto projection = nome::test::viewer_projection(*now->mesh, azimuth, elevation);
      std::vector<Index> corners;
      std::string clicks;
      for (const std::string& corner : face) {
        const std::string full = session.scene()->resolve_vertex_name(corner);
        std::optional<glm::dvec2> at;
        for (Index v = 0; v < names.size() && !at; ++v)
          if (names[v] == full && (at = nome::test::vertex_click(*now->mesh, projection, v)))
            corners.push_back(v);
        if (!at) break;
        clicks += click_line(*at);
      }
      if (corners.size() != face.size()) continue;
      script += "view " + std::to_string(int(azimuth)) + " " + std::to_string(int(elevation)) + "\n" +
                clicks + "action add-polygon\n";
      REQUIRE(session.add_polygon(*now->mesh, corners).applied);
      is_added = true;
      break;
    }
    INFO("face of " << face.size() << " corners, first " << face[0]);
    REQUIRE(is_added);
  }
  std::ofstream(dir + "/script.txt") << script << "action accept\nview 0 -35\nsave " << dir
                                     << "/saved.nome\nquit\n";
  const auto r = run_window(file + " --script " + dir + "/script.txt");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const scene::Scene saved = read_scene(dir + "/saved.nome");
  REQUIRE(saved.edits().consolidated.size() == polygons.size());
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto& got = saved.edits().consolidated[f];
    REQUIRE(got.size() == polygons[f].size());
    for (std::size_t i = 0; i < got.size(); ++i)
      CHECK(saved.resolve_vertex_name(got[i]) == saved.resolve_vertex_name(polygons[f][i]));
  }
  for (const char* name : {"fp_ro", "fp_ratio", "fp_h", "fp_z"})
    CHECK(saved.parameters()[*saved.find_parameter(name)].value ==
          Approx(report.parameters()[*report.find_parameter(name)].value));
}
