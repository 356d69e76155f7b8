// .anom files: slider values and a working (consolidated) mesh saved by the 2016 program, applied on
// top of an open scene.
#include "nome/scene/parser.hpp"
#include "nome/scene/scene.hpp"

namespace nome::scene {

void Scene::apply_anom(std::string_view text, const std::string& file) {
  Diagnostics diagnostics(file);
  const AnomAst anom = parse_anom(text, diagnostics);
  diagnostics.throw_if_errors();
  std::vector<Diagnostic> errors;
  Scene next = *this;
  std::vector<std::string> names;
  for (const Parameter& p : parameters_) names.push_back(p.full_name);
  for (const auto& [name, value] : anom.saved_parameters) {
    const auto id = find_parameter(name.text);
    // An init-capture: clang before 16 cannot capture a structured binding (the fuzz build uses clang-14).
    const auto at = [&, location = name.location](std::string m) {
      errors.push_back({Severity::error, file, location, std::move(m)});
    };
    if (!id) {
      at("unknown parameter '" + name.text + "'" + did_you_mean(name.text, names));
      continue;
    }
    const Parameter& p = parameters_[*id];
    if (value < p.min || value > p.max) {
      at("value " + format_number(value) + " of '" + p.full_name + "' is outside its slider range [" +
         format_number(p.min) + ", " + format_number(p.max) + "]");
      continue;
    }
    next.values_[id->index()] = value;
    next.parameters_[*id].value = value;
  }
  if (!errors.empty()) throw SceneError(std::move(errors));
  if (!anom.working_mesh.empty()) {
    next.ast_.consolidated_faces = anom.working_mesh;
    next.consolidated_file_ = file;
  }
  next.is_vertex_index_current_ = false;
  next.build(errors);
  if (!errors.empty()) throw SceneError(std::move(errors));
  *this = std::move(next);
}

}  // namespace nome::scene
