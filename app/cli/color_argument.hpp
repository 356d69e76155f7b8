#pragma once

#include <string>

#include <glm/vec3.hpp>

namespace nome::cli {

// A colour written on the command line: `#rrggbb`, `rrggbb`, `R,G,B` with components in 0..1, or a
// name (white, black, gray, lightgray, red, green, blue, gold, orange, purple). Throws UsageError
// naming the option otherwise.
glm::vec3 parse_color(const std::string& option, const std::string& text);

}  // namespace nome::cli
