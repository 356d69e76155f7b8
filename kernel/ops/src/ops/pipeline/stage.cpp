#include "nome/ops/stage.hpp"

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "nome/ops/pipeline_stage.hpp"

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

namespace {

// The name of each enumerator, in the enum's own (meaningless) order: what parse_stage searches.
std::optional<Stage> stage_named(std::string_view name) {
  for (Stage stage :
       {Stage::scene, Stage::merged, Stage::subdivided, Stage::offset, Stage::subdivided_offset})
    if (name == to_string(stage)) return stage;
  return std::nullopt;
}

// The built-in list read once: its order and which of its stages are editable.
struct BuiltinStages {
  std::vector<Stage> order;
  std::vector<Stage> editable;

  BuiltinStages() {
    for (const std::unique_ptr<PipelineStage>& made : builtin_stages()) {
      const Stage stage = *stage_named(made->name());
      order.push_back(stage);
      if (made->is_editable()) editable.push_back(stage);
    }
  }
};

const BuiltinStages& builtin() {
  static const BuiltinStages stages;
  return stages;
}

}  // namespace

std::span<const Stage> builtin_stage_order() {
  return builtin().order;
}

std::optional<Stage> parse_stage(std::string_view name) {
  std::string spaced(name);
  for (char& c : spaced)
    if (c == '-' || c == '_') c = ' ';
  return stage_named(spaced);
}

bool is_editable(Stage stage) {
  const std::vector<Stage>& editable = builtin().editable;
  return std::find(editable.begin(), editable.end(), stage) != editable.end();
}

bool passes_through(Stage last, Stage stage) {
  for (Stage made : builtin_stage_order()) {
    if (made == stage) return true;
    if (made == last) return false;
  }
  return false;
}

bool is_solid(Stage stage) {
  return passes_through(stage, Stage::offset);
}

}  // namespace nome
