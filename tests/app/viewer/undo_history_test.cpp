#include <catch2/catch.hpp>

#include "app/viewer_support.hpp"
#include "viewer/session/session_controller.hpp"
#include "viewer/window.hpp"

using namespace nome;

TEST_CASE("steps with the same key merge while they continue, and a new step drops the undone ones",
          "[app]") {
  int value = 0;
  viewer::UndoHistory history;
  auto set_to = [&](int from, int to, bool continues) {
    value = to;
    history.push({[&value, from] { return (value = from), true; },
                  [&value, to] { return (value = to), true; }, "slider 1"},
                 continues);
  };
  set_to(0, 1, false);
  set_to(1, 2, true);
  set_to(2, 3, true);
  CHECK(history.size() == 1);
  set_to(3, 4, false);  // a new drag of the same slider
  CHECK(history.size() == 2);
  REQUIRE(history.undo());
  CHECK(value == 3);
  REQUIRE(history.undo());
  CHECK(value == 0);
  CHECK_FALSE(history.undo());
  REQUIRE(history.redo());
  CHECK(value == 3);
  set_to(3, 7, true);  // does not merge into a step that was undone and redone past
  CHECK(history.size() == 2);
  CHECK_FALSE(history.can_redo());
}

TEST_CASE("a slider drag is one undo step, undone to the file's positions, between edits", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("undo_drag");
  nome::test::write_twelve_banks(dir + "/twelve.nome");
  viewer::MessageLog log;
  viewer::SessionController sessions(log, nome::test::TestViewer::private_stores());
  REQUIRE(sessions.open(dir + "/twelve.nome"));
  const auto file_positions = sessions.session()->positions();
  const scene::ParameterId ro = *sessions.scene()->find_parameter("b2_ro");
  // One drag over five frames: the first move starts the step, the others continue it.
  for (int frame = 0; frame < 5; ++frame) sessions.move_sliders({{ro, 0.5 + 0.1 * frame}}, frame > 0);
  CHECK(sessions.scene()->parameters()[ro].value == Approx(0.9));
  sessions.set_parameter("b3_h", 1.0);
  const viewer::Selection none;
  REQUIRE(sessions.edit(viewer::Action::undo, nullptr, none, {}));
  CHECK(sessions.scene()->parameters()[ro].value == Approx(0.9));
  REQUIRE(sessions.edit(viewer::Action::undo, nullptr, none, {}));
  CHECK(sessions.session()->positions() == file_positions);
  CHECK_FALSE(sessions.can_undo());
  REQUIRE(sessions.edit(viewer::Action::redo, nullptr, none, {}));
  CHECK(sessions.scene()->parameters()[ro].value == Approx(0.9));
}

TEST_CASE("stage settings join the undo history: a script's subdiv is undone with Ctrl+Z", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("undo_settings");
  viewer::ViewerOptions options;
  options.file = std::string(NOME_SOURCE_DIR) + "/assets/mobius_band.nome";
  options.script = nome::test::write_script(dir, "subdiv 2\noffset 0.1\nkey Ctrl+Z\nquit\n");
  nome::test::TestViewer viewer(options);
  REQUIRE(viewer.run() == 0);
  INFO(viewer.messages());
  // The offset was undone; the subdivision stays.
  REQUIRE(viewer.window().shown());
  CHECK(viewer.window().shown()->stage == Stage::subdivided);
  CHECK(viewer.messages().find("undo: undone") != std::string::npos);
}
