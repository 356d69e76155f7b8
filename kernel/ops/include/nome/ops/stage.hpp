#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace nome {

// The names of the built-in stages from a scene to a printable solid (the pipeline's stages, PipelineStage):
// the scene's pieces as one mesh, merged, subdivided, offset into a solid, and the solid subdivided again.
// The command line and the panels select the stage shown by these names; the values have no order.
enum class Stage { scene, merged, subdivided, offset, subdivided_offset };

// The built-in stages in the order of the pipeline's list, read from that list (builtin_stages): the one
// place the order is written.
std::span<const Stage> builtin_stage_order();

// "scene", "merged", "subdivided", "offset", "subdivided offset": for panels, logs and messages.
const char* to_string(Stage stage);
// The names of to_string, with '-' or '_' for the space; none for anything else.
std::optional<Stage> parse_stage(std::string_view name);

// Whether edits name the stage's vertices and faces (the scene's, the merge's; later stages are computed
// from them): the stage's own PipelineStage::is_editable.
bool is_editable(Stage stage);

// Whether a pipeline that stops at `last` makes `stage` on its way: `stage` is `last` or comes before it in
// the list of built-in stages.
bool passes_through(Stage last, Stage stage);
// Whether the stage's mesh is a solid: the offset's, or one made from it.
bool is_solid(Stage stage);

}  // namespace nome
