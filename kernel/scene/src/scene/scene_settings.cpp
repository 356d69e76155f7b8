// What the successor's stage blocks and render statements ask of the pipeline and of the picture,
// evaluated with the current slider values.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "nome/scene/scene.hpp"

namespace nome::scene {
namespace {

const RenderField* find_field(const RenderDecl& r, std::string_view key) {
  for (const RenderField& f : r.fields)
    if (f.key.text == key) return &f;
  return nullptr;
}

}  // namespace

double Scene::current(const Value& v) const {
  return evaluate(ast_.expressions, v, values_);
}

StageSettings Scene::stage_settings() const {
  StageSettings s;
  for (const StageDecl& stage : ast_.stages) {
    const double amount = current(stage.amount);
    if (stage.kind == StageKind::subdivision)
      s.subdivision_levels = std::max(s.subdivision_levels.value_or(0), int(std::lround(amount)));
    else
      s.offset_distance = std::max(s.offset_distance.value_or(0.0), amount);
    if (stage.boundary) s.boundary = parse_boundary_mode(stage.boundary->text);
  }
  for (const Name& mode : ast_.boundary_modes) s.boundary = parse_boundary_mode(mode.text);
  s.welds_before_subdividing = ast_.dialect.dialect == Dialect::jipcad;
  return s;
}

bool weld_before_subdividing(const StageSettings& stages, PipelineSettings& settings) {
  if (!stages.welds_before_subdividing || settings.levels_before() == 0) return false;
  settings.should_merge = true;
  return true;
}

RenderDefaults Scene::render_defaults() const {
  RenderDefaults d;
  const auto color = [&](const RenderField* f) -> std::optional<Color> {
    if (!f || f->values.size() != 3) return std::nullopt;
    Color c;
    for (int k = 0; k < 3; ++k) c[k] = float(std::clamp(current(f->values[size_t(k)]), 0.0, 1.0));
    return c;
  };
  std::vector<std::string> backfaces_used;
  for (const InstanceDecl& i : ast_.instances)
    if (i.backface) backfaces_used.push_back(i.backface->text);
  for (const GroupDecl& g : ast_.groups)
    for (const InstanceDecl& i : g.instances)
      if (i.backface) backfaces_used.push_back(i.backface->text);
  for (const RenderDecl& r : ast_.render) {
    if (r.keyword == "frontcolor") d.front_color = color(find_field(r, "color"));
    if (r.keyword == "backcolor") d.back_color = color(find_field(r, "color"));
    if (r.keyword == "backgroundcolor") d.background = color(find_field(r, "color"));
    if (r.keyword == "window" && !d.background) d.background = color(find_field(r, "background"));
    if (r.keyword == "light") ++d.light_count;
    if (r.keyword == "camera" && !d.camera_projection) {
      if (const RenderField* p = find_field(r, "projection"); p && p->word)
        d.camera_projection = p->word->text;
      if (const RenderField* f = find_field(r, "frustum"))
        for (const Value& v : f->values) d.camera_frustum.push_back(current(v));
    }
  }
  for (const InstanceDecl& placed : ast_.render_instances)
    for (const RenderDecl& r : ast_.render)
      if (r.keyword == "light" && r.name && r.name->text == placed.target.text) {
        SceneLight light;
        const RenderField* type = find_field(r, "type");
        const bool is_slide = type && type->word && type->word->text.starts_with("SLF_");
        light.kind =
            type && type->word && (type->word->text == "NOME_AMBIENT" || type->word->text == "SLF_AMBIENT")
                ? SceneLight::Kind::ambient
                : SceneLight::Kind::directional;
        light.color = color(find_field(r, "color")).value_or(Color(1.0f));
        if (const RenderField* d = find_field(r, "direction"); d && d->values.size() == 3)
          light.direction = Vec3(current(d->values[0]), current(d->values[1]), current(d->values[2]));
        // SLIDE's lights shine down their -z axis, or from a lookat's eye to its target.
        if (is_slide) light.direction = Vec3(0.0, 0.0, -1.0);
        if (placed.look_at)
          for (int k = 0; k < 3; ++k)
            light.direction[k] = current(placed.look_at->target[k]) - current(placed.look_at->eye[k]);
        ParameterReads reads;
        light.direction = glm::dmat3(instance_matrix(placed, reads)) * light.direction;
        const double length = glm::length(light.direction);
        light.direction = length > 0.0 ? light.direction / length : Vec3(0.0, 1.0, 0.0);
        d.lights.push_back(light);
      }
  // A backface an instance names colours the back of the picture (the renderer has one back colour).
  for (const RenderDecl& r : ast_.render)
    if (r.keyword == "backface" && r.name && !backfaces_used.empty() && r.name->text == backfaces_used[0])
      d.back_color = color(find_field(r, "color"));
  return d;
}

// The stage blocks' values must be usable: whole subdivision levels in 0..12, a positive offset.
void Scene::check_settings(std::vector<Diagnostic>& errors) {
  std::optional<int> level;
  for (const StageDecl& stage : ast_.stages) {
    double amount = 0;
    try {
      amount = current(stage.amount);
    } catch (const EvaluationError& e) {
      errors.push_back(located(e.where(), e.what()));
      continue;
    }
    if (stage.kind == StageKind::subdivision) {
      if (!(amount >= 0 && amount <= 12 && amount == std::floor(amount)))
        errors.push_back(located(stage.amount.location,
                                 "sd_level must be a whole number in 0..12, found " + format_number(amount)));
      else if (level && *level != int(amount))
        warnings_.push_back({Severity::warning, file(), stage.location,
                             "subdivision levels differ between blocks: the whole scene is subdivided at the "
                             "highest"});
      level = int(amount);
      if (stage.type && stage.type->text != "NOME_SD_CatmullClark" && stage.type->text != "NOME_SD_CC_sharp")
        errors.push_back(located(stage.type->location, "unknown sd_type '" + stage.type->text +
                                                           "' (NOME_SD_CatmullClark or NOME_SD_CC_sharp)"));
    } else {
      if (!(amount > 0))
        errors.push_back(
            located(stage.amount.location, "offset height must be positive, found " + format_number(amount)));
      if (stage.type && stage.type->text != "NOME_OFFSET_DEFAULT")
        errors.push_back(
            located(stage.type->location,
                    "offset_type '" + stage.type->text + "' is not supported yet (NOME_OFFSET_DEFAULT is)"));
    }
  }
  std::vector<const Name*> modes;
  for (const StageDecl& stage : ast_.stages)
    if (stage.boundary) modes.push_back(&*stage.boundary);
  for (const Name& mode : ast_.boundary_modes) modes.push_back(&mode);
  for (const Name* mode : modes)
    if (!parse_boundary_mode(mode->text))
      errors.push_back(located(
          mode->location, "unknown boundary mode '" + mode->text + "' (none, edge_only or edge_and_corner)"));
}

}  // namespace nome::scene
