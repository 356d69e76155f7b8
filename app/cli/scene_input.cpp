#include "cli/scene_input.hpp"

#include <algorithm>
#include <iostream>

#include "nome/error.hpp"
#include "nome/io/face_location.hpp"
#include "nome/io/file_extension.hpp"
#include "nome/io/read_polygons.hpp"
#include "nome/io/read_scene.hpp"
#include "nome/io/sif.hpp"
#include "nome/io/three_mf.hpp"

namespace nome::cli {

void apply_overrides(std::vector<SceneDocument>& scenes, const std::vector<std::string>& overrides) {
  for (const std::string& o : overrides) {
    const size_t eq = o.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set expects BANK_PARAM=VALUE, found '" + o + "'");
    const std::string name = o.substr(0, eq), text = o.substr(eq + 1);
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != text.size())
      throw UsageError("--set " + name + " expects a number, found '" + text + "'");
    bool found = false;
    std::vector<std::string> known;
    for (SceneDocument& document : scenes) {
      const scene::Scene& s = *document.scene();
      for (const scene::Parameter& p : s.parameters()) known.push_back(p.full_name);
      if (const auto id = s.find_parameter(name)) {
        document.set_parameter(*id, value);
        found = true;
      }
    }
    if (!found) throw UsageError("--set: no parameter '" + name + "'" + scene::did_you_mean(name, known));
  }
}

namespace {

scene::SceneOptions scene_options(const Arguments& args) {
  scene::SceneOptions options{.force = args.has("--force"), .shows_edits = false};
  if (const auto dialect = args.value("--dialect")) {
    if (*dialect == "2016")
      options.dialect = scene::Dialect::report2016;
    else if (*dialect == "jipcad")
      options.dialect = scene::Dialect::jipcad;
    else
      throw UsageError("--dialect expects 2016 or jipcad, found '" + *dialect + "'");
  }
  return options;
}

// `--time T` (nome render): the scenes' $time.
void apply_time(std::vector<SceneDocument>& scenes, const Arguments& args) {
  if (!args.has("--time")) return;
  const double time = args.double_value("--time", 0.0);
  for (SceneDocument& document : scenes) document.set_clock(scene::time_parameter, time);
}

void merge_obj_tags(ObjSubdivisionTags& into, const ObjSubdivisionTags& file) {
  if (file.boundary) into.boundary = file.boundary;
  if (file.crease_method) into.crease_method = file.crease_method;
  if (file.smooth_triangles) into.smooth_triangles = file.smooth_triangles;
  for (const std::string& note : file.notes) std::cerr << "nome: note: " << note << "\n";
}

// The file's edits that the slider values leave without their vertices or faces: left out of the geometry
// (as the viewer leaves them), each said.
void warn_unresolved(const SceneDocument& document) {
  for (const UnresolvedEdit& edit : document.edits().unresolved()) {
    std::string missing;
    for (const std::string& name : edit.missing) missing += (missing.empty() ? "" : ", ") + name;
    std::cerr << "nome: warning: " << document.scene()->file() << ": edit '" << edit.face << "' left out: "
              << (missing.empty()            ? "its face is gone"
                  : edit.missing.size() == 1 ? "vertex " + missing + " is gone"
                                             : "vertices " + missing + " are gone")
              << " at these slider values\n";
  }
}

}  // namespace

InputFiles read_input_files(const Arguments& args) {
  InputFiles input;
  const scene::SceneOptions options = scene_options(args);
  std::vector<std::pair<std::string, PolygonSoup>> flat;  // flat geometry, in argument order after the scenes
  for (const std::string& file : args.positionals()) {
    const std::string ext = lower_extension(file);
    if (is_scene_file(file)) {
      try {
        input.scenes.push_back(SceneDocument::from_scene(read_scene(file, options)));
      } catch (const BudgetError& e) {
        throw BudgetError(std::string(e.what()) + "; use --force to expand it anyway");
      }
    } else if (ext == ".anom") {
      if (input.scenes.empty())
        throw UsageError(file + ": an .anom file applies to an open scene: give the .nome file before it");
      input.scenes.back().apply_anom(read_text_file(file), file);
    } else if (ext == ".sif") {
      flat.emplace_back(file, read_sif(file, {args.has("--quads"), SifOptions{}.max_fold_degrees}));
    } else if (ext == ".3mf") {
      flat.emplace_back(file, three_mf_polygons(read_3mf(file)));
    } else if (ext == ".obj" || ext == ".stl" || ext == ".glb" || ext == ".gltf" || ext == ".ply") {
      flat.emplace_back(file, read_polygons(file));
      if (ext == ".obj") merge_obj_tags(input.obj_tags, read_obj_subdivision_tags(file));
    } else {
      throw IoError(file + ": unknown file type '" + ext +
                    "' (Nome reads .nome, .nom, .slf, .sif, .obj, .stl, .3mf, .glb, .gltf and .ply, and "
                    ".anom after its scene)");
    }
  }
  for (const SceneDocument& document : input.scenes)
    for (const scene::Diagnostic& w : document.scene()->warnings())
      std::cerr << "nome: " << w.to_string() << "\n";
  apply_overrides(input.scenes, args.values("--set"));
  apply_time(input.scenes, args);
  for (const SceneDocument& document : input.scenes) warn_unresolved(document);
  // A scene's pieces may meet at a point (JIPCAD's examples do); a flat file's polygons must be a manifold.
  auto add_part = [&](const PolygonSoup& soup, const std::string& file, bool is_scene) {
    append_soup(input.geometry.soup, soup);
    input.geometry.parts.push_back({file, soup.num_faces(), is_scene});
    if (!is_scene)
      input.geometry.parts.back().locate_face = [file](Index f) { return locate_face_in_file(file, f); };
  };
  for (const SceneDocument& document : input.scenes)
    add_part(document.pipeline_input().soup, document.scene()->file(), true);
  for (const auto& [file, soup] : flat) add_part(soup, file, false);
  return input;
}

}  // namespace nome::cli
