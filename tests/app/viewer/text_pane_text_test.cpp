// The text pane's toolbar and notes as a user reads them, when another program changes the file.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "app/cli_support.hpp"
#include "app/viewer/imgui_text.hpp"
#include "viewer/tools/text_pane.hpp"

using namespace nome::viewer;

namespace {

std::string pane_text(TextPane& pane) {
  return nome::test::imgui_text([&] { pane.draw(); });
}

}  // namespace

TEST_CASE("the text pane says when the file changed on disk under the user's edits, until it is loaded",
          "[app]") {
  const std::string dir = nome::test::private_scratch_dir("text_pane_text");
  const std::string file = dir + "/scene.nome";
  std::ofstream(file) << "point p (0 0 0) endpoint\n";
  TextPane pane;
  pane.sync(file, true, 1);
  const std::string opened = pane_text(pane);
  INFO(opened);
  CHECK(opened.find("scene.nome") != std::string::npos);
  CHECK(opened.find("changed on disk") == std::string::npos);
  CHECK(opened.find("Load from disk") == std::string::npos);
  // The user types; another program writes the file.
  pane.set_text("point p (1 0 0) endpoint\n");
  std::ofstream(file) << "point p (2 0 0) endpoint\n";
  pane.sync(file, true, 2);
  const std::string changed = pane_text(pane);
  INFO(changed);
  CHECK(changed.find("the file changed on disk; the geometry shows it, this text is yours") !=
        std::string::npos);
  CHECK(changed.find("Load from disk") != std::string::npos);
  pane.load_from_disk();
  const std::string loaded = pane_text(pane);
  CHECK(loaded.find("changed on disk") == std::string::npos);
  CHECK(loaded.find("Load from disk") == std::string::npos);
  CHECK(loaded.find("point p (2 0 0) endpoint") != std::string::npos);
}
