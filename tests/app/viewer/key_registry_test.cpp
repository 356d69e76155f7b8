#include <catch2/catch.hpp>

#define GLFW_INCLUDE_NONE  // GL comes from glad (render/gl.hpp)
#include <GLFW/glfw3.h>

#include "viewer/key_registry.hpp"
#include "viewer/message_log.hpp"

using namespace nome::viewer;

TEST_CASE("one key registry serves key presses, labels for the help and script names", "[app]") {
  KeyRegistry keys;
  int wire = 0, undo = 0, help = 0;
  keys.add(GLFW_KEY_W, 0, "wire", [&] { ++wire; });
  keys.add(GLFW_KEY_Z, KeyModifier::control, "undo", [&] { ++undo; });
  keys.add(GLFW_KEY_SLASH, KeyModifier::shift, "help", [&] { ++help; });
  CHECK(keys.press(GLFW_KEY_W, 0));
  CHECK_FALSE(keys.press(GLFW_KEY_W, KeyModifier::control));
  CHECK(keys.press(GLFW_KEY_Z, KeyModifier::control | 0x4));  // Alt is ignored
  CHECK(keys.press("ctrl+z"));
  CHECK(keys.press("?"));
  CHECK_FALSE(keys.press("Ctrl+Y"));
  CHECK(wire == 1);
  CHECK(undo == 2);
  CHECK(help == 1);
  CHECK(keys.bindings()[1].label == "Ctrl+Z");
  CHECK(key_label(GLFW_KEY_F1, 0) == "F1");
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
