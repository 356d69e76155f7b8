// The browser build has no Tcl: a SLIDE scene that runs Tcl is refused with a message.
#include "slide/scene_tcl.hpp"

namespace nome::slide {

void run_scene_tcl(scene::SceneAst& ast, const std::filesystem::path&, const TclReading&,
                   scene::Diagnostics& diagnostics) {
  const scene::SourceLocation at =
      ast.script_blocks.empty() ? ast.script_values.front().location : ast.script_blocks.front().location;
  diagnostics.error(
      at, "this SLIDE scene runs Tcl, which the browser build does not have: open it in the desktop Nome");
}

}  // namespace nome::slide
