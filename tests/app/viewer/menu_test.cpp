// The menu bar as a user meets it: what each menu holds, what is enabled, and what choosing an item does,
// read through a recording MenuSink instead of a screen.
#include <catch2/catch.hpp>

#include <map>
#include <string>
#include <vector>

#include "app/cli_support.hpp"
#include "viewer/panels/panels.hpp"

using namespace nome::viewer;

namespace {

// Opens every menu, records each item by its path ("View/Section plane") and chooses the one asked for.
class RecordingMenus final : public MenuSink {
 public:
  struct Item {
    std::string shortcut;
    bool is_checked;
    bool is_enabled;
  };
  std::map<std::string, Item> items;
  std::map<std::string, bool> menus;  // by path: enabled
  std::vector<std::string> notes;
  std::string chosen;  // the path of the item to choose, if any

  bool begin_bar() override { return true; }
  void end_bar() override {}
  bool begin_menu(const char* label, bool is_enabled) override {
    path_.push_back(label);
    menus[joined()] = is_enabled;
    return true;
  }
  void end_menu() override { path_.pop_back(); }
  bool item(const char* label, const std::string& shortcut, bool is_checked, bool is_enabled) override {
    const std::string path = joined() + "/" + label;
    items[path] = {shortcut, is_checked, is_enabled};
    return is_enabled && path == chosen;
  }
  void separator() override {}
  void note(const std::string& text) override { notes.push_back(text); }

 private:
  std::string joined() const {
    std::string out;
    for (const std::string& p : path_) out += (out.empty() ? "" : "/") + p;
    return out;
  }
  std::vector<std::string> path_;
};

// Every action bound to a counter.
struct CountedActions {
  ActionRegistry registry;
  std::map<Action, int> runs;
  CountedActions() {
    for (const ActionInfo& info : action_table())
      registry.bind(info.action, [this, a = info.action] { return ++runs[a] > 0; });
  }
};

}  // namespace

TEST_CASE("the menus hold every command a user looks for there, with its shortcut", "[app]") {
  RecentFiles recent(nome::test::private_scratch_dir("menu_recent") + "/recent");
  CountedActions actions;
  render::DisplaySettings display;
  LayoutSettings layout;
  RecordingMenus menus;
  const MenuContext context{recent, true, true, true, false};
  CHECK_FALSE(draw_main_menu(menus, actions.registry, context, display, layout));
  for (const char* path : {"File/Open...",
                           "File/Save",
                           "File/Save As...",
                           "File/Export STL / OBJ / glTF / PLY...",
                           "File/Screenshot",
                           "File/Quit",
                           "Edit/Undo",
                           "Edit/Redo",
                           "Edit/Move the selection",
                           "View/Faces",
                           "View/Wireframe overlay",
                           "View/Shading/Automatic: flat until subdivided",
                           "View/Shading/Smooth",
                           "View/Shading/Flat",
                           "View/Back-face culling",
                           "View/Back faces in their own colour",
                           "View/Möbius edges",
                           "View/Borders",
                           "View/Instance colours",
                           "View/The scene's lights",
                           "View/Palette/Nome: gold front, blue back",
                           "View/Palette/JIPCAD: orange front, dark grey back",
                           "View/Frame all",
                           "View/Section plane",
                           "View/Reset view",
                           "View/Turntable",
                           "View/Front",
                           "View/Right",
                           "View/Top",
                           "View/Controls sidebar",
                           "View/Parameters sidebar",
                           "View/Hide / show both sidebars",
                           "View/Log open",
                           "View/Scene text",
                           "View/Dark theme",
                           "Help/Keys and mouse"}) {
    INFO(path);
    CHECK(menus.items.count(path) == 1);
  }
  CHECK(menus.items["Edit/Undo"].shortcut == "Ctrl+Z");
  CHECK(menus.items["View/Faces"].shortcut == shortcut(Action::toggle_faces));
  CHECK(menus.items["File/Open..."].shortcut == shortcut(Action::open));
  CHECK(menus.items["View/Section plane"].shortcut == shortcut(Action::toggle_section));
  CHECK(menus.notes == std::vector<std::string>{shortcut(Action::toggle_shading) + " cycles them"});
  // Nothing recent yet: the submenu is greyed, not missing.
  REQUIRE(menus.menus.count("File/Open Recent") == 1);
  CHECK_FALSE(menus.menus["File/Open Recent"]);
  CHECK(menus.menus.count("Tools") == 0);  // no tool added a command
}

TEST_CASE("a menu item is enabled only when its command can run, and choosing it runs that command",
          "[app]") {
  RecentFiles recent(nome::test::private_scratch_dir("menu_enabled") + "/recent");
  CountedActions actions;
  render::DisplaySettings display;
  LayoutSettings layout;
  SECTION("no file open: saving and undoing are greyed, opening and quitting are not") {
    RecordingMenus menus;
    draw_main_menu(menus, actions.registry, {recent, false, false, false, false}, display, layout);
    for (const char* greyed : {"File/Save", "File/Save As...", "File/Export STL / OBJ / glTF / PLY...",
                               "Edit/Undo", "Edit/Redo", "Edit/Move the selection"}) {
      INFO(greyed);
      CHECK_FALSE(menus.items[greyed].is_enabled);
    }
    for (const char* enabled : {"File/Open...", "File/Screenshot", "File/Quit", "View/Section plane",
                                "View/Frame all", "Help/Keys and mouse"}) {
      INFO(enabled);
      CHECK(menus.items[enabled].is_enabled);
    }
  }
  SECTION("a flat file open: export but no scene saving; undo but no redo") {
    RecordingMenus menus;
    draw_main_menu(menus, actions.registry, {recent, true, false, true, false}, display, layout);
    CHECK(menus.items["File/Export STL / OBJ / glTF / PLY..."].is_enabled);
    CHECK_FALSE(menus.items["File/Save"].is_enabled);
    CHECK(menus.items["Edit/Undo"].is_enabled);
    CHECK_FALSE(menus.items["Edit/Redo"].is_enabled);
    CHECK_FALSE(menus.items["Edit/Move the selection"].is_enabled);  // a flat file has no text to change
  }
  SECTION("each command item runs its own action, once") {
    const std::map<std::string, Action> commands{{"File/Open...", Action::open},
                                                 {"File/Screenshot", Action::screenshot},
                                                 {"File/Quit", Action::quit},
                                                 {"Edit/Undo", Action::undo},
                                                 {"Edit/Move the selection", Action::move},
                                                 {"View/Frame all", Action::frame_all},
                                                 {"View/Section plane", Action::toggle_section},
                                                 {"View/Reset view", Action::reset_view},
                                                 {"View/Turntable", Action::toggle_turntable},
                                                 {"View/Front", Action::view_front},
                                                 {"View/Right", Action::view_right},
                                                 {"View/Top", Action::view_top},
                                                 {"View/Hide / show both sidebars", Action::toggle_sidebars},
                                                 {"Help/Keys and mouse", Action::toggle_help}};
    for (const auto& [path, action] : commands) {
      INFO(path);
      actions.runs.clear();
      RecordingMenus menus;
      menus.chosen = path;
      draw_main_menu(menus, actions.registry, {recent, true, true, true, true}, display, layout);
      CHECK(actions.runs == std::map<Action, int>{{action, 1}});
    }
  }
}

TEST_CASE("the view menu's check marks show the display settings and turn them on and off", "[app]") {
  RecentFiles recent(nome::test::private_scratch_dir("menu_toggles") + "/recent");
  CountedActions actions;
  render::DisplaySettings display;
  LayoutSettings layout;
  const auto choose = [&](const std::string& path) {
    RecordingMenus menus;
    menus.chosen = path;
    draw_main_menu(menus, actions.registry, {recent, true, true, false, false}, display, layout);
    return menus;
  };
  const bool borders = display.draws_borders;
  CHECK(choose("").items["View/Borders"].is_checked == borders);
  choose("View/Borders");
  CHECK(display.draws_borders == !borders);
  CHECK(choose("").items["View/Borders"].is_checked == !borders);
  choose("View/Borders");
  CHECK(display.draws_borders == borders);
  // Hiding the faces shows the wireframe, so that something stays on screen.
  display.draws_faces = true;
  display.draws_wireframe = false;
  choose("View/Faces");
  CHECK_FALSE(display.draws_faces);
  CHECK(display.draws_wireframe);
  choose("View/Shading/Flat");
  CHECK(display.shading == render::Shading::flat);
  CHECK(choose("").items["View/Shading/Flat"].is_checked);
  CHECK_FALSE(choose("").items["View/Shading/Smooth"].is_checked);
  choose("View/Back-face culling");
  CHECK(display.back_faces == render::BackFacePolicy::cull);
  choose("View/Back-face culling");
  CHECK(display.back_faces == render::BackFacePolicy::different);
  const bool left = layout.is_left_shown;
  choose("View/Controls sidebar");
  CHECK(layout.is_left_shown == !left);
  CHECK(actions.runs.empty());  // settings, not commands
}

TEST_CASE("Open Recent lists the recent files and gives back the one chosen", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("menu_open_recent");
  RecentFiles recent(dir + "/recent");
  recent.add(dir + "/a.nome");
  recent.add(dir + "/b.nome");
  CountedActions actions;
  render::DisplaySettings display;
  LayoutSettings layout;
  RecordingMenus menus;
  menus.chosen = "File/Open Recent/" + (std::filesystem::path(dir) / "a.nome").string();
  const auto chosen =
      draw_main_menu(menus, actions.registry, {recent, false, false, false, false}, display, layout);
  CHECK(menus.menus["File/Open Recent"]);
  REQUIRE(chosen);
  CHECK(*chosen == std::filesystem::path(dir) / "a.nome");
  CHECK(menus.items["File/Open Recent/" + (std::filesystem::path(dir) / "b.nome").string()].shortcut ==
        "Ctrl+1");
}
