#pragma once

#include <optional>
#include <string_view>

namespace nome {

// The stages from a scene to a printable solid, in order (DESIGN.md's data flow): the scene's pieces as
// one mesh, merged, subdivided, offset into a solid, and the solid subdivided again.
enum class Stage { scene, merged, subdivided, offset, subdivided_offset };

inline constexpr Stage all_stages[] = {Stage::scene, Stage::merged, Stage::subdivided, Stage::offset,
                                       Stage::subdivided_offset};

// "scene", "merged", "subdivided", "offset", "subdivided offset": for panels, logs and messages.
const char* to_string(Stage stage);
// The names of to_string, with '-' or '_' for the space; none for anything else.
std::optional<Stage> parse_stage(std::string_view name);

// Edits name the scene's vertices and faces, which only the scene and merged stages show: the later
// stages are computed from them.
bool is_editable(Stage stage);

}  // namespace nome
