#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>

#include "app/cli_support.hpp"
#include "nome/error.hpp"
#include "support/shared_examples.hpp"
#include "viewer/session/session.hpp"

using namespace nome;
using nome::viewer::Session;

TEST_CASE("a bad edit of the open file keeps the last good geometry and the edits", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("session_reload");
  const std::string file = dir + "/square.obj";
  const std::string squares = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\n";
  std::ofstream(file) << squares << "f 1 2 3 4\nf 5 6 7 8\n";
  Session session = Session::open(file);
  REQUIRE(session.polygons().num_faces() == 2);
  const Mesh shown = build_mesh(session.polygons());
  auto id = [&](const std::string& name) {
    const auto& names = shown.vertex_names();
    return Index(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const std::vector<Index> corners{id("v2"), id("v5"), id("v8"), id("v3")};  // a quad between the squares
  REQUIRE(session.add_polygon(shown, corners).applied);
  CHECK(session.face_parts().temporary == 1);
  CHECK(session.is_modified());

  std::ofstream(file) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  const auto version = session.version();
  CHECK_THROWS_AS(session.reload(), IoError);
  CHECK(session.version() == version);
  CHECK(session.polygons().num_faces() == 3);

  // A good edit comes in and the added face follows it by name.
  std::ofstream(file) << squares << "f 1 2 3 4\nf 5 6 7 8\n"
                      << "v 9 9 9\n";
  session.reload();
  CHECK(session.version() > version);
  CHECK(session.polygons().num_faces() == 3);
  CHECK(session.face_parts().temporary == 1);
}

TEST_CASE("an .anom file applies its saved sliders and working mesh to the open scene, not to flat files",
          "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const std::string original = nome::test::shared_examples_dir("original");
  Session session = Session::open(original + "kleinbottle.nom");
  REQUIRE(session.polygons().num_faces() == 80);
  CHECK_FALSE(session.is_modified());
  session.apply_anom(original + "kleinbottle_s1.anom");
  // Its eight zipped faces join the five tunnels' 80.
  CHECK(session.polygons().num_faces() == 88);
  CHECK(session.document().consolidated_faces().size() == 8);
  CHECK(session.is_modified());

  // A value outside its slider's range is refused and changes nothing.
  const std::string dir = nome::test::private_scratch_dir("session_anom");
  std::ofstream(dir + "/bad.anom") << "savedparameter\n    tp1_n 99.000000\nendsavedparameter\n";
  const auto version = session.version();
  CHECK_THROWS_WITH(session.apply_anom(dir + "/bad.anom"), Catch::Contains("bad.anom:2:5"));
  CHECK(session.version() == version);

  Session flat = Session::open(std::string(NOME_SOURCE_DIR) + "/assets/cube.obj");
  CHECK_THROWS_WITH(flat.apply_anom(original + "kleinbottle_s1.anom"),
                    Catch::Contains("open its .nome first"));
}

// A reload of a scene changed on disk (another program's write, the text pane's Apply) keeps the values
// the user moved the sliders to where the file still has the slider and its range holds the value; a
// slider the user left, a new one, and one whose new range excludes the user's value take the file's
// value. Read on the sliders and on the positions the scene is evaluated at.
TEST_CASE("reloading a changed scene keeps the sliders the user moved, where they still are and fit",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("session_reload_sliders");
  const std::string file = dir + "/s.nome";
  const std::string geometry =
      "point p ({expr $b_keep} {expr $b_edge} {expr $b_narrowed}) endpoint\n"
      "point q ({expr $b_untouched} 2 0) endpoint\n"
      "point r (0 3 {expr $b_%s}) endpoint\n"
      "mesh m face f (p q r) endface endmesh\ninstance i m endinstance\n";
  auto scene_text = [&](const std::string& bank, const std::string& last) {
    std::string text = geometry;
    text.replace(text.find("%s"), 2, last);
    return "bank b\n" + bank + "endbank\n" + text;
  };
  std::ofstream(file) << scene_text(
      "  set keep 0.5 0 1 0.1\n  set edge 0.5 0 1 0.1\n  set narrowed 0.5 0 1 0.1\n"
      "  set untouched 0.5 0 1 0.1\n  set gone 0.5 0 1 0.1\n  set back 0.5 0 1 0.1\n",
      "gone");
  Session session = Session::open(file);
  auto value = [&](const std::string& name) {
    const auto id = session.scene()->find_parameter(name);
    REQUIRE(id);
    return session.scene()->parameters()[*id].value;
  };
  auto position = [&](const std::string& vertex) {
    const auto& names = session.polygons().vertex_names;
    const auto at = std::find(names.begin(), names.end(), vertex);
    REQUIRE(at != names.end());
    return session.positions()[Index(at - names.begin())];
  };
  session.set_parameter("b_keep", 0.7);
  session.set_parameter("b_edge", 0.9);
  session.set_parameter("b_narrowed", 0.8);
  session.set_parameter("b_gone", 0.1);
  session.set_parameter("b_back", 0.2);
  session.set_parameter("b_back", 0.5);  // moved and put back: the file's value
  REQUIRE(position("i_p") == Vec3(0.7, 0.9, 0.8));

  // The file narrows two ranges to 0.9 and 0.6, gives `untouched` and `back` new values, drops `gone`
  // and adds `fresh`.
  std::ofstream(file) << scene_text(
      "  set keep 0.5 0 1 0.1\n  set edge 0.5 0 0.9 0.1\n  set narrowed 0.3 0 0.6 0.1\n"
      "  set untouched 0.2 0 1 0.1\n  set fresh 0.4 0 1 0.1\n  set back 0.6 0 1 0.1\n",
      "fresh");
  session.reload();
  CHECK(value("b_keep") == 0.7);       // moved, still in range
  CHECK(value("b_edge") == 0.9);       // moved to what is now the top of the range: still in it
  CHECK(value("b_narrowed") == 0.3);   // moved past the new top: the file's value
  CHECK(value("b_untouched") == 0.2);  // never moved: the file's new value
  CHECK(value("b_back") == 0.6);       // moved back to the file's value: the file's new value
  CHECK(value("b_fresh") == 0.4);      // new: the file's value
  CHECK_FALSE(session.scene()->find_parameter("b_gone"));
  CHECK(position("i_p") == Vec3(0.7, 0.9, 0.3));
  CHECK(position("i_q") == Vec3(0.2, 2, 0));
  CHECK(position("i_r") == Vec3(0, 3, 0.4));

  // Another change: the file's own value of a slider the user moved does not take it back.
  std::ofstream(file) << scene_text(
      "  set keep 0.6 0 1 0.1\n  set edge 0.5 0 0.9 0.1\n  set narrowed 0.3 0 0.6 0.1\n"
      "  set untouched 0.25 0 1 0.1\n  set fresh 0.45 0 1 0.1\n  set back 0.6 0 1 0.1\n",
      "fresh");
  session.reload();
  CHECK(value("b_keep") == 0.7);
  CHECK(value("b_untouched") == 0.25);
  CHECK(value("b_fresh") == 0.45);
  CHECK(position("i_p") == Vec3(0.7, 0.9, 0.3));
  CHECK(position("i_r") == Vec3(0, 3, 0.45));
}
