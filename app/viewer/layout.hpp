#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

namespace nome::viewer {

// A rectangle in window pixels, origin top-left, y down (as the cursor and ImGui have it).
struct ScreenRect {
  glm::dvec2 origin{0.0};
  glm::dvec2 size{0.0};

  glm::dvec2 max() const { return origin + size; }
  bool contains(glm::dvec2 p) const;
  // The other lies inside this one (edges may touch).
  bool contains(const ScreenRect& other) const;
};

// What the user arranged, remembered between runs in the XDG config folder.
struct LayoutSettings {
  // Narrow enough that the model has 60 % of a 1280-pixel window; a user's drag is remembered.
  double left_width = 250.0;  // window pixels at content scale 1
  double right_width = 250.0;
  double log_height = 140.0;
  double pane_width = 460.0;
  bool is_left_shown = true;
  bool is_pane_shown = false;  // the pane beside the left sidebar (a tool's), hidden until asked for
  bool is_right_shown = true;
  bool is_log_open = false;  // collapsed: only its title bar (the status bar shows the newest message)
  bool is_dark = false;
  glm::ivec2 window_size{1280, 800};

  bool operator==(const LayoutSettings&) const = default;
};

// The sizes ImGui decides (they grow with the font), in window pixels.
struct LayoutChrome {
  double menu_height = 0.0;
  double status_height = 0.0;
  double log_bar_height = 0.0;  // the collapsed log
  double scale = 1.0;           // the content scale the widths are multiplied by
};

// The window cut into its panels' places, with the 3D viewport the rectangle between them. A hidden
// sidebar or pane has width 0; the pane (a tool's) stands beside the left sidebar, the log under the
// viewport.
struct ScreenLayout {
  ScreenRect left, right, log, viewport, pane;
};

// The viewport keeps at least this much of the window's width and height: sidebars and log give way.
inline constexpr double min_viewport_pixels = 160.0;

ScreenLayout arrange(const LayoutSettings& settings, glm::dvec2 window, const LayoutChrome& chrome);

// `$XDG_CONFIG_HOME/nome/layout`, else `~/.config/nome/layout`; empty when neither is known.
std::filesystem::path default_layout_file();
// The remembered layout; the defaults for a missing file, and for each missing or unreadable line.
LayoutSettings read_layout(const std::filesystem::path& file);
// Replaces the file (atomically), making its folder; throws IoError when it cannot.
void write_layout(const std::filesystem::path& file, const LayoutSettings& settings);

// Where the panels and the bank headers were drawn in the last frame: the script's `layout` lines.
struct LayoutReport {
  std::vector<std::pair<std::string, ScreenRect>> panels;  // "viewport", "controls", "parameters", "log"
  std::vector<std::pair<std::string, ScreenRect>> banks;   // headers visible in the parameter panel
  // `NAME X Y W H` lines (bank headers as `bank NAME X Y W H`), rounded to whole pixels.
  std::vector<std::string> lines() const;
  const ScreenRect* panel(const std::string& name) const;
  const ScreenRect* bank(const std::string& name) const;
};

}  // namespace nome::viewer
