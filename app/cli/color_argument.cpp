#include "cli/color_argument.hpp"

#include <cctype>
#include <sstream>
#include <utility>

#include "cli/arguments.hpp"

namespace nome::cli {
namespace {

const std::pair<const char*, glm::vec3> named_colors[] = {{"white", {1, 1, 1}},
                                                          {"black", {0, 0, 0}},
                                                          {"gray", {0.5f, 0.5f, 0.5f}},
                                                          {"lightgray", {0.85f, 0.85f, 0.85f}},
                                                          {"red", {0.85f, 0.15f, 0.12f}},
                                                          {"green", {0.2f, 0.65f, 0.3f}},
                                                          {"blue", {0.25f, 0.45f, 0.8f}},
                                                          {"gold", {0.8f, 0.62f, 0.25f}},
                                                          {"orange", {0.95f, 0.55f, 0.15f}},
                                                          {"purple", {0.55f, 0.3f, 0.75f}}};

bool parse_hex(std::string text, glm::vec3& color) {
  if (!text.empty() && text[0] == '#') text.erase(0, 1);
  if (text.size() != 6) return false;
  for (char c : text)
    if (!std::isxdigit(static_cast<unsigned char>(c))) return false;
  for (int i = 0; i < 3; ++i) color[i] = float(std::stoi(text.substr(2 * i, 2), nullptr, 16)) / 255.0f;
  return true;
}

bool parse_triple(const std::string& text, glm::vec3& color) {
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  if (!(in >> color.r >> comma1 >> color.g >> comma2 >> color.b) || comma1 != ',' || comma2 != ',')
    return false;
  in >> std::ws;
  if (!in.eof()) return false;
  for (int i = 0; i < 3; ++i)
    if (!(color[i] >= 0.0f && color[i] <= 1.0f)) return false;
  return true;
}

}  // namespace

glm::vec3 parse_color(const std::string& option, const std::string& text) {
  for (const auto& [name, color] : named_colors)
    if (text == name) return color;
  glm::vec3 color;
  if (parse_hex(text, color) || parse_triple(text, color)) return color;
  throw UsageError(option + " expects a colour (#rrggbb, R,G,B in 0..1, or a name such as white), found '" +
                   text + "'");
}

}  // namespace nome::cli
