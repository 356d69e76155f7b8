#include "nome/slide/read_slf.hpp"

#include "nome/scene/parser.hpp"
#include "slide/scene_tcl.hpp"

namespace nome::slide {

scene::Scene read_slf_scene(std::string_view text, const std::filesystem::path& path,
                            const scene::SceneOptions& options, const TclLimits& limits,
                            const PolygonFileReader& read_polygons) {
  scene::Diagnostics diagnostics(path.string());
  scene::SceneAst ast = scene::parse_slf(text, diagnostics);
  diagnostics.throw_if_errors();
  if (!ast.script_blocks.empty() || !ast.script_values.empty()) {
    run_scene_tcl(ast, path.parent_path(), {limits, read_polygons}, diagnostics);
    diagnostics.throw_if_errors();
  }
  return scene::Scene::from_ast(std::move(ast), diagnostics.all(), options);
}

}  // namespace nome::slide
