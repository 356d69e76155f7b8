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
