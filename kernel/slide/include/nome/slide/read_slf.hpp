#pragma once

#include <filesystem>
#include <string_view>

#include "nome/scene/scene.hpp"
#include "nome/slide/polygon_file_reader.hpp"
#include "nome/slide/tcl_limits.hpp"

namespace nome::slide {

// Reads a SLIDE scene (.slf): its statements, then its Tcl (SLIDE ran `tclinit` blocks and computed braced
// values with Tcl; so does Nome, in a safe interpreter, with Tk's scales made the scene's sliders), then
// evaluates it. Throws SceneError listing every located error.
scene::Scene read_slf_scene(std::string_view text, const std::filesystem::path& path,
                            const scene::SceneOptions& options = {}, const TclLimits& limits = {},
                            const PolygonFileReader& read_polygons = {});

}  // namespace nome::slide
