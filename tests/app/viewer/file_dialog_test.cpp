// The file dialog as a user meets it: the folder's matching files and its folders, and a name typed and
// accepted with Enter.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <imgui.h>

#include "app/cli_support.hpp"
#include "app/viewer/imgui_text.hpp"
#include "viewer/panels/file_dialog.hpp"

using namespace nome::viewer;

namespace {

constexpr int tab_key = 1;
constexpr int enter_key = 2;

// One frame of the dialog with these keys held and these characters typed: its text and what it chose.
std::string dialog_frame(const nome::test::OwnImGuiContext& context, FileBrowser& browser,
                         std::optional<std::filesystem::path>& chosen, std::initializer_list<int> keys = {},
                         const char* typed = "") {
  ImGuiIO& io = ImGui::GetIO();
  io.KeyMap[ImGuiKey_Tab] = tab_key;
  io.KeyMap[ImGuiKey_Enter] = enter_key;
  for (bool& down : io.KeysDown) down = false;
  for (int key : keys) io.KeysDown[key] = true;
  io.AddInputCharactersUTF8(typed);
  return nome::test::imgui_frame(context, [&] {
    if (auto path = browser.draw()) chosen = path;
  });
}

}  // namespace

TEST_CASE("the file dialog lists the folder's matching files and folders, and Enter takes a typed name",
          "[app]") {
  const std::filesystem::path dir = nome::test::private_scratch_dir("file_dialog");
  std::filesystem::create_directories(dir / "models");
  std::filesystem::create_directories(dir / ".hidden");
  for (const char* name : {"torus.nome", "cube.stl", "notes.txt", ".secret.nome"})
    std::ofstream(dir / name) << "x";
  FileBrowser browser;
  browser.open("Save As", dir, {".nome"}, "Save", "torus.nome");
  REQUIRE(browser.is_open());
  const nome::test::OwnImGuiContext context;
  std::optional<std::filesystem::path> chosen;
  dialog_frame(context, browser, chosen);
  const std::string text = dialog_frame(context, browser, chosen);
  INFO(text);
  CHECK(text.find(std::filesystem::weakly_canonical(dir).string()) != std::string::npos);
  CHECK(text.find("../") != std::string::npos);
  CHECK(text.find("models/") != std::string::npos);
  CHECK(text.find("torus.nome") != std::string::npos);
  CHECK(text.find("cube.stl") == std::string::npos);
  CHECK(text.find("notes.txt") == std::string::npos);
  CHECK(text.find("secret") == std::string::npos);
  CHECK(text.find("hidden") == std::string::npos);
  CHECK(text.find("Save") != std::string::npos);
  CHECK(text.find("Cancel") != std::string::npos);
  // Tab goes to the name field and selects it; what is typed replaces it; Enter accepts.
  dialog_frame(context, browser, chosen, {tab_key});
  dialog_frame(context, browser, chosen);
  dialog_frame(context, browser, chosen, {}, "copy.nome");
  dialog_frame(context, browser, chosen, {enter_key});
  REQUIRE(chosen);
  CHECK(*chosen == std::filesystem::weakly_canonical(dir) / "copy.nome");
  CHECK_FALSE(browser.is_open());
}
