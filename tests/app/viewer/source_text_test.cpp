#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>

#include "app/viewer_support.hpp"
#include "nome/scene/source_text.hpp"
#include "support/missing_point_scene.hpp"
#include "viewer/message_log.hpp"
#include "viewer/session/session_controller.hpp"

using namespace nome;
using nome::scene::SourceLocation;

TEST_CASE("lines and columns of an edited text map to byte offsets and back", "[app]") {
  const std::string text = "bank b\n  set n 4 3 8 1\n\nendbank";
  CHECK(scene::line_count(text) == 4);
  CHECK(scene::line_count("") == 1);
  CHECK(scene::line_count("a\n") == 2);
  CHECK(scene::byte_offset(text, {1, 1}) == 0);
  CHECK(scene::byte_offset(text, {2, 3}) == 9);
  CHECK(text.substr(scene::byte_offset(text, {2, 3}), 3) == "set");
  CHECK(scene::byte_offset(text, {3, 1}) == 23);
  // Past a line's end: its end; past the last line: the text's end.
  CHECK(scene::byte_offset(text, {2, 99}) == 22);
  CHECK(scene::byte_offset(text, {9, 1}) == text.size());
  for (std::size_t offset = 0; offset <= text.size(); ++offset)
    CHECK(scene::byte_offset(text, scene::location_at(text, offset)) == offset);
  CHECK(scene::location_at(text, 9) == SourceLocation{2, 3});
  CHECK(scene::location_at(text, 1000) == SourceLocation{4, 8});
}

TEST_CASE("the log keeps a diagnostic's place, and finds one at the start of an error's text", "[app]") {
  viewer::MessageLog log;
  log.diagnostics({{scene::Severity::error, "a b.nome", {3, 7}, "expected ')'"},
                   {scene::Severity::warning, "a b.nome", {5, 1}, "inexact join"}});
  log.error("/tmp/x.nome:12:4: unknown name 'q'");
  log.info("opened /tmp/x.nome (8 vertices, 6 faces)");
  const auto& m = log.messages();
  REQUIRE(m.size() == 4);
  CHECK(m[0].level == viewer::MessageLevel::error);
  CHECK(m[0].place == scene::SourcePlace{"a b.nome", {3, 7}});
  CHECK(m[1].level == viewer::MessageLevel::warning);
  CHECK(m[1].place == scene::SourcePlace{"a b.nome", {5, 1}});
  CHECK(m[1].text == "a b.nome:5:1: inexact join");  // the level is the log's own column
  CHECK(m[2].place == scene::SourcePlace{"/tmp/x.nome", {12, 4}});
  CHECK_FALSE(m[3].place);
  const scene::SceneError error({{scene::Severity::error, "c.nome", {1, 2}, "first"},
                                 {scene::Severity::error, "c.nome", {4, 5}, "second"}});
  log.error(error);
  REQUIRE(log.messages().size() == 6);
  CHECK(log.messages()[5].place == scene::SourcePlace{"c.nome", {4, 5}});
}

TEST_CASE("opening or applying a scene logs its warnings at their places", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("scene_warnings");
  const std::string file = dir + "/missing.nom";
  const std::string text = "# nome-dialect: jipcad\n" + std::string(nome::test::missing_point_scene);
  std::ofstream(file) << text;
  viewer::MessageLog log;
  viewer::SessionController sessions(log, nome::test::TestViewer::private_stores());
  REQUIRE(sessions.open(file));
  const auto warning = [&] {
    return std::find_if(log.messages().begin(), log.messages().end(),
                        [](const viewer::Message& m) { return m.level == viewer::MessageLevel::warning; });
  };
  REQUIRE(warning() != log.messages().end());
  CHECK(warning()->text == file + ":5:16: unknown point 'x': face 'f2' left out");
  CHECK(warning()->place == scene::SourcePlace{file, {5, 16}});
  log.clear();
  REQUIRE(sessions.apply_text(text));
  CHECK(warning() != log.messages().end());
}
