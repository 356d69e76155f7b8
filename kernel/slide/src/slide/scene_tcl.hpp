#pragma once

#include <filesystem>

#include "nome/scene/ast.hpp"
#include "nome/slide/polygon_file_reader.hpp"
#include "nome/slide/tcl_limits.hpp"

namespace nome::slide {

// Runs a .slf scene's `tclinit` blocks, in file order, in a new safe Tcl interpreter whose `source` reads
// files in `folder` (the scene's) and whose library is Nome's own version of SLIDE's. Then the scales those
// blocks made become the scene's sliders (a bank per toplevel window) and the interpreter computes the
// scene's braced values. Tcl errors go to `diagnostics`, located at the .slf line where Tcl stopped.
// What the scene's Tcl may spend, and how it reads mesh files.
struct TclReading {
  TclLimits limits;
  PolygonFileReader read_polygons;
};

void run_scene_tcl(scene::SceneAst& ast, const std::filesystem::path& folder, const TclReading& reading,
                   scene::Diagnostics& diagnostics);

}  // namespace nome::slide
