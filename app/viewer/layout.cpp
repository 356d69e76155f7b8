#include "viewer/layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "nome/atomic_file.hpp"
#include "nome/error.hpp"

namespace nome::viewer {

bool ScreenRect::contains(glm::dvec2 p) const {
  return p.x >= origin.x && p.y >= origin.y && p.x < origin.x + size.x && p.y < origin.y + size.y;
}

bool ScreenRect::contains(const ScreenRect& other) const {
  return other.origin.x >= origin.x && other.origin.y >= origin.y && other.max().x <= max().x &&
         other.max().y <= max().y;
}

ScreenLayout arrange(const LayoutSettings& settings, glm::dvec2 window, const LayoutChrome& chrome) {
  const double top = chrome.menu_height;
  const double height = std::max(0.0, window.y - top - chrome.status_height);
  double left = settings.is_left_shown ? settings.left_width * chrome.scale : 0.0;
  double right = settings.is_right_shown ? settings.right_width * chrome.scale : 0.0;
  double pane = settings.is_pane_shown ? settings.pane_width * chrome.scale : 0.0;
  // A narrow window shrinks the side panels alike so that the model keeps a place.
  const double room = std::max(0.0, window.x - min_viewport_pixels);
  if (left + right + pane > room) {
    const double shrink = room / (left + right + pane);
    left *= shrink;
    right *= shrink;
    pane *= shrink;
  }
  double log = settings.is_log_open ? settings.log_height * chrome.scale : chrome.log_bar_height;
  log = std::min(log, std::max(chrome.log_bar_height, height - min_viewport_pixels));
  ScreenLayout layout;
  layout.left = {{0.0, top}, {left, height}};
  layout.right = {{window.x - right, top}, {right, height}};
  layout.pane = {{left, top}, {pane, height}};
  const double middle = std::max(0.0, window.x - left - pane - right);
  layout.log = {{left + pane, top + height - log}, {middle, log}};
  layout.viewport = {{left + pane, top}, {middle, std::max(1.0, height - log)}};
  return layout;
}

std::filesystem::path default_layout_file() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config)
    return std::filesystem::path(config) / "nome" / "layout";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".config" / "nome" / "layout";
  return {};
}

namespace {

// The file's lines, `key value`: one table for reading and writing, so they cannot disagree.
struct Field {
  const char* key;
  double LayoutSettings::*number = nullptr;
  bool LayoutSettings::*flag = nullptr;
  int size_axis = -1;  // the window size's x (0) or y (1)
};

const Field fields[] = {
    {"left_width", &LayoutSettings::left_width},
    {"right_width", &LayoutSettings::right_width},
    {"log_height", &LayoutSettings::log_height},
    {"text_width", &LayoutSettings::pane_width},
    {"left_shown", nullptr, &LayoutSettings::is_left_shown},
    {"right_shown", nullptr, &LayoutSettings::is_right_shown},
    {"log_open", nullptr, &LayoutSettings::is_log_open},
    {"text_shown", nullptr, &LayoutSettings::is_pane_shown},
    {"dark", nullptr, &LayoutSettings::is_dark},
    {"window_width", nullptr, nullptr, 0},
    {"window_height", nullptr, nullptr, 1},
};

void read_field(const Field& field, double value, LayoutSettings& settings) {
  if (!std::isfinite(value)) return;
  if (field.number && value >= 0.0 && value <= 10000.0) settings.*field.number = value;
  if (field.flag) settings.*field.flag = value != 0.0;
  if (field.size_axis >= 0 && value >= 64.0 && value <= 8192.0)
    settings.window_size[field.size_axis] = int(value);
}

}  // namespace

LayoutSettings read_layout(const std::filesystem::path& file) {
  LayoutSettings settings;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    double value = 0.0;
    if (!(words >> key >> value)) continue;
    for (const Field& field : fields)
      if (key == field.key) read_field(field, value, settings);
  }
  return settings;
}

void write_layout(const std::filesystem::path& file, const LayoutSettings& settings) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) throw IoError(file.parent_path().string() + ": cannot make the folder: " + ec.message());
  write_file_atomically(file, [&](std::ostream& out) {
    for (const Field& field : fields) {
      out << field.key << ' ';
      if (field.number) out << settings.*field.number;
      if (field.flag) out << (settings.*field.flag ? 1 : 0);
      if (field.size_axis >= 0) out << settings.window_size[field.size_axis];
      out << '\n';
    }
  });
}

std::vector<std::string> LayoutReport::lines() const {
  auto line = [](const std::string& name, const ScreenRect& r) {
    std::ostringstream out;
    out << name << ' ' << std::lround(r.origin.x) << ' ' << std::lround(r.origin.y) << ' '
        << std::lround(r.size.x) << ' ' << std::lround(r.size.y);
    return out.str();
  };
  std::vector<std::string> result;
  for (const auto& [name, rect] : panels) result.push_back(line(name, rect));
  for (const auto& [name, rect] : banks) result.push_back(line("bank " + name, rect));
  return result;
}

const ScreenRect* LayoutReport::panel(const std::string& name) const {
  for (const auto& [n, rect] : panels)
    if (n == name) return &rect;
  return nullptr;
}

const ScreenRect* LayoutReport::bank(const std::string& name) const {
  for (const auto& [n, rect] : banks)
    if (n == name) return &rect;
  return nullptr;
}

}  // namespace nome::viewer
