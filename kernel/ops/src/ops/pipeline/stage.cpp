#include "nome/ops/stage.hpp"

#include <string>

namespace nome {

const char* to_string(Stage stage) {
  switch (stage) {
    case Stage::scene:
      return "scene";
    case Stage::merged:
      return "merged";
    case Stage::subdivided:
      return "subdivided";
    case Stage::offset:
      return "offset";
    case Stage::subdivided_offset:
      return "subdivided offset";
  }
  return "scene";
}

std::optional<Stage> parse_stage(std::string_view name) {
  std::string spaced(name);
  for (char& c : spaced)
    if (c == '-' || c == '_') c = ' ';
  for (Stage stage : all_stages)
    if (spaced == to_string(stage)) return stage;
  return std::nullopt;
}

bool is_editable(Stage stage) {
  return stage == Stage::scene || stage == Stage::merged;
}

bool passes_through(Stage last, Stage stage) {
  for (Stage made : all_stages) {
    if (made == stage) return true;
    if (made == last) return false;
  }
  return false;
}

bool is_solid(Stage stage) {
  return passes_through(stage, Stage::offset);
}

}  // namespace nome
