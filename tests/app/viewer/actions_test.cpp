#include <catch2/catch.hpp>

#include <map>
#include <set>

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>

#include "viewer/commands/actions.hpp"
#include "viewer/message_log.hpp"

using namespace nome::viewer;

TEST_CASE("one action table serves key presses, labels for the help and script names", "[app]") {
  ActionRegistry actions;
  int wire = 0, undo = 0, help = 0;
  actions.bind(Action::toggle_faces, [&] { return ++wire > 0; });
  actions.bind(Action::undo, [&] {
    ++undo;
    return false;  // refused
  });
  actions.bind(Action::toggle_help, [&] { return ++help > 0; });
  CHECK(actions.press(GLFW_KEY_W, KeyModifier::none));
  CHECK_FALSE(actions.press(GLFW_KEY_W, KeyModifier::control));
  CHECK(actions.press(GLFW_KEY_Z, KeyModifier::control | KeyModifier(0x4)));  // Alt is ignored
  CHECK(actions.press("ctrl+z"));
  CHECK(actions.press("?"));
  CHECK(actions.press("F1"));
  CHECK_FALSE(actions.press("Ctrl+Shift+Z"));
  CHECK(actions.run(Action::toggle_faces));
  CHECK_FALSE(actions.run(Action::undo));
  CHECK_FALSE(actions.run(Action::zip));  // nothing bound
  CHECK(wire == 2);
  CHECK(undo == 3);
  CHECK(help == 2);
  CHECK(shortcut(Action::undo) == "Ctrl+Z");
  CHECK(shortcut(Action::zip).empty());
  CHECK(key_label(GLFW_KEY_F1, KeyModifier::none) == "F1");
  CHECK(find_action("add-polygon") == Action::add_polygon);
  CHECK_FALSE(find_action("fly"));
  CHECK(action_name(Action::delete_faces) == "delete");
}

TEST_CASE("every action of the table has one script name, and no two rows share a shortcut", "[app]") {
  std::map<std::string, Action> names;
  std::set<std::string> labels;
  for (const ActionInfo& row : action_table()) {
    const auto [at, is_new] = names.emplace(row.name, row.action);
    CHECK((is_new || at->second == row.action));
    if (row.key != 0) CHECK(labels.insert(key_label(row.key, row.modifiers)).second);
  }
  CHECK(names.size() == std::size_t(Action::save_text) + 1);
  CHECK(action_names().starts_with("help, open, open-recent-1"));
}

TEST_CASE("the log batches repeated warnings and keeps errors apart", "[app]") {
  MessageLog log;
  log.info("opened a.nome");
  log.warning("face f3 is degenerate");
  log.error("a.nome:3:7: expected ')'");
  log.warning("face f3 is degenerate");
  REQUIRE(log.messages().size() == 3);
  CHECK(log.latest()->count == 2);
  CHECK(log.count(MessageLevel::warning) == 2);
  CHECK(log.count(MessageLevel::error) == 1);
}
