// A scene from its text: the sliders, the names of definitions, then expansion and evaluation; the
// slider moves that change it afterwards; and the file's edits handed over to an editor.
#include "nome/scene/scene.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "nome/scene/parser.hpp"
#include "nome/scene/statement_kinds.hpp"
#include "scene/index_sets.hpp"
#include "scene/value_change.hpp"

namespace nome::scene {
namespace {

std::atomic<std::uint64_t> scenes_evaluated{0};

}  // namespace

std::uint64_t scene_evaluation_count() {
  return scenes_evaluated.load(std::memory_order_relaxed);
}

Diagnostic Scene::located(SourceLocation at, std::string message) const {
  return {Severity::error, ast_.file, at, std::move(message)};
}

std::string Scene::where(SourceLocation at) const {
  return ast_.file + ":" + location_text(at);
}

void Scene::add_warning(SourceLocation at, std::string message) const {
  Diagnostic d{Severity::warning, ast_.file, at, std::move(message)};
  const auto is_same = [&](const Diagnostic& w) {
    return w.location.line == at.line && w.location.column == at.column && w.message == d.message;
  };
  if (std::none_of(warnings_.begin(), warnings_.end(), is_same)) warnings_.push_back(std::move(d));
}

std::vector<Diagnostic> Scene::warnings() const {
  std::vector<Diagnostic> all = warnings_;
  for (const Placement& p : placements_)
    for (const Diagnostic& w : p.warnings)
      if (std::find(all.begin(), all.end(), w) == all.end()) all.push_back(w);
  return all;
}

Scene Scene::from_text(std::string_view text, const std::string& file, const SceneOptions& options) {
  Diagnostics diagnostics(file);
  SceneAst ast = parse_nome(text, diagnostics, {options.dialect, {}});
  diagnostics.throw_if_errors();
  return from_ast(std::move(ast), diagnostics.all(), options);
}

Scene Scene::from_ast(SceneAst ast, std::vector<Diagnostic> warnings, const SceneOptions& options) {
  Scene scene;
  scene.ast_ = std::move(ast);
  scene.options_ = options;
  scene.warnings_ = std::move(warnings);
  std::vector<Diagnostic> errors;
  scene.register_parameters(errors);
  scene.define_names(errors);
  if (errors.empty()) scene.check_settings(errors);
  if (errors.empty()) scene.build(errors);
  if (!errors.empty()) throw SceneError(std::move(errors));
  return scene;
}

// Sliders, and the expressions that read them.
void Scene::register_parameters(std::vector<Diagnostic>& errors) {
  for (const BankDecl& b : ast_.banks) {
    Bank bank{b.name.text, {}, {}};
    for (const SliderDecl& s : b.sliders) {
      Parameter p{b.name.text,     s.name.text,     b.name.text + "_" + s.name.text,
                  s.value.literal, s.min.literal,   s.max.literal,
                  s.step.literal,  s.value.literal, s.label};
      if (parameter_ids_.count(p.full_name)) {
        errors.push_back(located(s.name.location, "duplicate parameter '" + p.full_name + "'"));
        continue;
      }
      bank.parameters.push_back(add_parameter(std::move(p)));
    }
    bank.shown = bank.parameters;
    if (b.shown) {
      bank.shown.clear();
      for (const Name& n : *b.shown)
        if (const auto it = parameter_ids_.find(b.name.text + "_" + n.text); it != parameter_ids_.end())
          bank.shown.push_back(it->second);
    }
    banks_.push_back(std::move(bank));
  }
  // Animation clocks every scene has: values expressions read, but no slider (not saved, not on a panel).
  for (const char* name : {time_parameter, frame_parameter}) {
    parameter_ids_[name] = ParameterId(Index(values_.size()));
    values_.push_back(0);
  }
  if (ExpressionScript* script = ast_.expressions.script())
    script->bind([&](const std::string& name) -> std::optional<ParameterId> {
      const auto it = parameter_ids_.find(name);
      return it == parameter_ids_.end() ? std::nullopt : std::optional(it->second);
    });
  std::vector<std::string> parameter_names;
  for (const Parameter& p : parameters_) parameter_names.push_back(p.full_name);
  for (Index e = 0; e < ast_.expressions.size(); ++e) {
    ExprNode& n = ast_.expressions.node(e);
    if (n.op != ExprOp::parameter) continue;
    const auto it = parameter_ids_.find(n.parameter_name);
    if (it != parameter_ids_.end())
      n.parameter = it->second;
    else
      errors.push_back(located(n.location, "unknown parameter '$" + n.parameter_name + "'" +
                                               did_you_mean(n.parameter_name, parameter_names)));
  }
}

ParameterId Scene::add_parameter(Parameter p) {
  // Sliders come first: a slider's id is its index in parameters_ and in values_.
  values_.push_back(p.value);
  const std::string name = p.full_name;
  return parameter_ids_[name] = parameters_.push_back(std::move(p));
}

// Names of definitions: surfaces, points and geometry each have their own namespace. Definitions are
// named in the order they are written, whatever their kind, so the second of two is the duplicate.
void Scene::define_names(std::vector<Diagnostic>& errors) {
  const auto define = [&](auto& table, const Name& name, auto value,
                          std::unordered_map<std::string, SourceLocation>& at) {
    if (const auto it = at.find(name.text); it != at.end()) {
      const std::string first = location_text(it->second);
      if (ast_.dialect.dialect != Dialect::jipcad) {
        errors.push_back(
            located(name.location, "duplicate name '" + name.text + "' (first defined at " + first + ")"));
        return;
      }
      // JIPCAD reads its statements in order, a later definition replacing the earlier one.
      add_warning(name.location, "'" + name.text + "' is defined again (first at " + first +
                                     "): this definition is used everywhere");
    }
    at[name.text] = name.location;
    table[name.text] = value;
  };
  std::unordered_map<std::string, SourceLocation> surface_at, point_at, definition_at;
  for (Index i = 0; i < ast_.surfaces.size(); ++i) define(surfaces_, ast_.surfaces[i].name, i, surface_at);
  for (Index i = 0; i < ast_.points.size(); ++i) define(points_, ast_.points[i].name, i, point_at);
  for (Index i = 0; i < ast_.control_points.size(); ++i)
    define(control_points_, ast_.control_points[i].name, i, point_at);
  std::vector<std::pair<DeclaredName, Index>> declared;  // with the row of its kind
  const std::span<const StatementKind> kinds = statement_kinds();
  for (Index k = 0; k < kinds.size(); ++k) {
    if (!kinds[k].is_definition()) continue;
    std::vector<DeclaredName> names;
    kinds[k].declare(ast_, k, names);
    for (const DeclaredName& d : names) declared.emplace_back(d, k);
  }
  std::stable_sort(declared.begin(), declared.end(), [](const auto& a, const auto& b) {
    const SourceLocation x = a.first.name->location, y = b.first.name->location;
    return x.line != y.line ? x.line < y.line : x.column < y.column;
  });
  for (const auto& [d, kind] : declared)
    define(definitions_, *d.name, Definition{kind, d.decl}, definition_at);
  if (definition_at.count(consolidated_mesh_name))
    errors.push_back(located(definition_at[consolidated_mesh_name],
                             std::string("'") + consolidated_mesh_name + "' is a reserved name"));
  definitions_[consolidated_mesh_name] = {consolidated_kind, 0};
  rename_repeated_instances(ast_.instances);
  for (GroupDecl& g : ast_.groups) rename_repeated_instances(g.instances);
}

// Files written with JIPCAD repeat instance names in one group, and JIPCAD draws every one; here names
// are paths to vertices, so each repeat gets a name of its own (`bc` again becomes `bc_2`), with a warning.
void Scene::rename_repeated_instances(std::vector<InstanceDecl>& instances) {
  std::unordered_map<std::string, SourceLocation> seen;
  for (const InstanceDecl& i : instances) seen.emplace(i.name.text, i.name.location);
  std::unordered_map<std::string, SourceLocation> first;
  for (InstanceDecl& i : instances) {
    const auto [it, is_fresh] = first.emplace(i.name.text, i.name.location);
    if (is_fresh) continue;
    std::string renamed;
    for (int k = 2; renamed.empty() || seen.count(renamed); ++k)
      renamed = i.name.text + "_" + std::to_string(k);
    add_warning(i.name.location, "instance name '" + i.name.text + "' repeated (first at " +
                                     location_text(it->second) + "): this one is named '" + renamed + "'");
    seen.emplace(renamed, i.name.location);
    i.name.text = renamed;
  }
}

void Scene::build(std::vector<Diagnostic>& errors) {
  scenes_evaluated.fetch_add(1, std::memory_order_relaxed);
  placements_.clear();
  instances_.clear();
  expand_roots(errors);
  if (!errors.empty()) return;
  std::vector<Index> leaves;
  for (Index i = 0; i < placements_.size(); ++i)
    if (is_leaf(placements_[i])) leaves.push_back(i);
  if (const auto over = evaluate_all(leaves, errors)) throw BudgetError(*over);
  if (!errors.empty()) return;
  edits_.deleted = resolve_deleted(ast_.deleted_faces, errors);
  resolve_sharp_edits(errors);
  resolve_consolidated(errors);
  assemble_all();
  resolve_text_sharps(errors);
}

std::optional<ParameterId> Scene::find_parameter(const std::string& name) const {
  const auto it = parameter_ids_.find(normalize_name(name));
  if (it == parameter_ids_.end() || !parameters_.contains(it->second)) return std::nullopt;
  return it->second;
}

std::vector<InstanceId> Scene::set_parameter(ParameterId parameter, double value) {
  if (!parameters_.contains(parameter))
    throw InvalidInputError("Scene::set_parameter: no parameter " + std::to_string(parameter.index()));
  const Parameter& param = parameters_[parameter];
  if (!std::isfinite(value) || value < param.min || value > param.max)
    throw InvalidInputError(param.full_name + "=" + format_number(value) + " is outside its slider range [" +
                            format_number(param.min) + ", " + format_number(param.max) + "]");
  return change_value(parameter, value);
}

std::vector<InstanceId> Scene::set_clock(const std::string& name, double value) {
  if (name != time_parameter && name != frame_parameter)
    throw InvalidInputError("Scene::set_clock: no built-in parameter '$" + name + "'");
  if (!std::isfinite(value))
    throw InvalidInputError("$" + name + " must be a finite number, found " + format_number(value));
  return change_value(parameter_ids_.at(name), value);
}

// Sets value `parameter` (a slider's, or a clock's past the sliders) and re-evaluates what reads it: the
// placements whose topology stays only move their vertices, the others are made again.
std::vector<InstanceId> Scene::change_value(ParameterId parameter, double value) {
  ValueChange change(*this, parameter, value);
  std::vector<Diagnostic> errors;
  const auto over_budget = change.reevaluate(errors);
  // A `sharp` weight that reads the slider changes the soup's creases: the soup is made again.
  const bool moves_sharpness =
      std::binary_search(text_sharp_reads_.begin(), text_sharp_reads_.end(), parameter);
  if (moves_sharpness) check_text_sharp_weights(errors);
  if (!errors.empty() || over_budget) {
    change.roll_back();
    if (over_budget) throw BudgetError(*over_budget);
    throw SceneError(std::move(errors));
  }
  has_only_moved_vertices_ = change.has_only_moved() && !moves_sharpness;
  return change.assemble();
}

const std::vector<std::string>& Scene::shown_deletions() const {
  static const std::vector<std::string> none;
  return options_.shows_edits ? edits_.deleted : none;
}

const std::vector<NamedSharpEdge>& Scene::shown_sharp_edits() const {
  static const std::vector<NamedSharpEdge> none;
  return options_.shows_edits ? edits_.sharp : none;
}

SceneEdits Scene::take_edits() {
  SceneEdits taken = edits_;
  const bool shows_consolidated = options_.shows_edits && !taken.consolidated.empty();
  if (options_.shows_edits)
    for (std::vector<std::string>& face : taken.consolidated)
      for (std::string& name : face) name = resolve_vertex_name(name);
  const bool shows_deletions = !shown_deletions().empty();
  edits_ = {};
  ast_.consolidated_faces.clear();
  ast_.deleted_faces.clear();
  ast_.sharp_edges.clear();
  consolidated_file_.clear();
  options_.shows_edits = false;
  if (shows_consolidated) {
    // The consolidated mesh was a placement of its own, which other placements may name.
    std::vector<Diagnostic> errors;
    is_vertex_index_current_ = false;
    build(errors);
    if (!errors.empty()) throw SceneError(std::move(errors));
  } else if (shows_deletions) {
    assemble_all();
  }
  return taken;
}

}  // namespace nome::scene
