#include "nome/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <unordered_set>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "nome/scene/generators.hpp"
#include "nome/scene/parser.hpp"

namespace nome::scene {
namespace {

constexpr int max_ring_vertices = 100000;
// Instances are expanded recursively; a deeper hierarchy (no real scene has one) would overflow the stack.
constexpr size_t max_instance_depth = 256;

std::string at_text(SourceLocation at) {
  return std::to_string(at.line) + ":" + std::to_string(at.column);
}

void sort_unique(std::vector<Index>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

bool same_topology(const PolygonSoup& a, const PolygonSoup& b) {
  return a.num_vertices() == b.num_vertices() && a.face_offsets == b.face_offsets &&
         a.face_vertices == b.face_vertices;
}

// Every suffix of a hierarchical name that starts after a `_`, the name itself included.
template <typename F>
void for_each_suffix(const std::string& name, F f) {
  f(name);
  for (size_t i = name.find('_'); i != std::string::npos; i = name.find('_', i + 1))
    if (i + 1 < name.size()) f(name.substr(i + 1));
}

}  // namespace

Diagnostic Scene::located(SourceLocation at, std::string message) const {
  return {Severity::error, ast_.file, at, std::move(message)};
}

Scene Scene::from_text(std::string_view text, const std::string& file, const SceneOptions& options) {
  Diagnostics diagnostics(file);
  SceneAst ast = parse_nome(text, diagnostics);
  diagnostics.throw_if_errors();
  return from_ast(std::move(ast), diagnostics.all(), options);
}

Scene Scene::from_ast(SceneAst ast, std::vector<Diagnostic> warnings, const SceneOptions& options) {
  Scene scene;
  scene.ast_ = std::move(ast);
  scene.options_ = options;
  scene.warnings_ = std::move(warnings);
  std::vector<Diagnostic> errors;

  // Sliders and the expressions that read them.
  for (const BankDecl& b : scene.ast_.banks) {
    Bank bank{b.name.text, {}};
    for (const SliderDecl& s : b.sliders) {
      Parameter p{b.name.text,     s.name.text,   b.name.text + "_" + s.name.text,
                  s.value.literal, s.min.literal, s.max.literal,
                  s.step.literal};
      if (scene.parameter_ids_.count(p.full_name)) {
        errors.push_back(scene.located(s.name.location, "duplicate parameter '" + p.full_name + "'"));
        continue;
      }
      const Index id = Index(scene.parameters_.size());
      scene.parameter_ids_[p.full_name] = id;
      bank.parameters.push_back(id);
      scene.values_.push_back(p.value);
      scene.parameters_.push_back(std::move(p));
    }
    scene.banks_.push_back(std::move(bank));
  }
  std::vector<std::string> parameter_names;
  for (const Parameter& p : scene.parameters_) parameter_names.push_back(p.full_name);
  for (Index e = 0; e < scene.ast_.expressions.size(); ++e) {
    ExprNode& n = scene.ast_.expressions.node(e);
    if (n.op != ExprOp::parameter) continue;
    const auto it = scene.parameter_ids_.find(n.parameter_name);
    if (it != scene.parameter_ids_.end())
      n.parameter = it->second;
    else
      errors.push_back(scene.located(n.location, "unknown parameter '$" + n.parameter_name + "'" +
                                                     did_you_mean(n.parameter_name, parameter_names)));
  }

  // Names of definitions: surfaces, points and geometry each have their own namespace.
  auto define = [&](auto& table, const Name& name, auto value,
                    std::unordered_map<std::string, SourceLocation>& at) {
    if (const auto it = at.find(name.text); it != at.end()) {
      errors.push_back(scene.located(name.location, "duplicate name '" + name.text + "' (first defined at " +
                                                        at_text(it->second) + ")"));
      return;
    }
    at[name.text] = name.location;
    table[name.text] = value;
  };
  std::unordered_map<std::string, SourceLocation> surface_at, point_at, definition_at;
  for (Index i = 0; i < scene.ast_.surfaces.size(); ++i)
    define(scene.surfaces_, scene.ast_.surfaces[i].name, i, surface_at);
  for (Index i = 0; i < scene.ast_.points.size(); ++i)
    define(scene.points_, scene.ast_.points[i].name, i, point_at);
  auto define_all = [&](const auto& decls, DefinitionKind kind) {
    for (Index i = 0; i < decls.size(); ++i)
      define(scene.definitions_, decls[i].name, Definition{kind, i}, definition_at);
  };
  define_all(scene.ast_.faces, DefinitionKind::face);
  define_all(scene.ast_.polylines, DefinitionKind::polyline);
  define_all(scene.ast_.objects, DefinitionKind::object);
  define_all(scene.ast_.generators, DefinitionKind::generator);
  define_all(scene.ast_.meshes, DefinitionKind::mesh);
  define_all(scene.ast_.groups, DefinitionKind::group);
  if (definition_at.count(consolidated_mesh_name))
    errors.push_back(scene.located(definition_at[consolidated_mesh_name],
                                   std::string("'") + consolidated_mesh_name + "' is a reserved name"));
  scene.definitions_[consolidated_mesh_name] = {DefinitionKind::consolidated, 0};
  for (const GroupDecl& g : scene.ast_.groups) {
    std::unordered_map<std::string, SourceLocation> seen;
    for (const InstanceDecl& i : g.instances)
      if (const auto [it, fresh] = seen.emplace(i.name.text, i.name.location); !fresh)
        errors.push_back(scene.located(i.name.location, "duplicate instance name '" + i.name.text +
                                                            "' in group '" + g.name.text + "' (first at " +
                                                            at_text(it->second) + ")"));
  }
  for (const auto& face : scene.ast_.consolidated_faces) {
    std::vector<std::string> names;
    for (const Name& n : face.vertices) names.push_back(n.text);
    scene.consolidated_.push_back(std::move(names));
  }
  if (errors.empty()) scene.build(errors);
  if (!errors.empty()) throw SceneError(std::move(errors));
  return scene;
}

const InstanceDecl* Scene::statement(const Placement& p) const {
  if (p.statement == no_index) return nullptr;
  return p.group == no_index ? &ast_.instances[p.statement] : &ast_.groups[p.group].instances[p.statement];
}

void Scene::expand(const InstanceDecl& decl, Index group, Index statement, Index parent, Index top,
                   std::vector<Index>& stack, std::vector<Diagnostic>& errors) {
  // A statement inside a group is met once per placement of the group, 2^40 times in a doubling chain:
  // its error is reported (and its message, with the names it suggests, made) the first time only.
  const auto is_reported = [&](SourceLocation at) {
    return std::any_of(errors.begin(), errors.end(), [&](const Diagnostic& d) { return d.location == at; });
  };
  const auto it = definitions_.find(decl.target.text);
  if (it == definitions_.end()) {
    if (is_reported(decl.target.location)) return;
    std::vector<std::string> names;
    for (const auto& [name, d] : definitions_) names.push_back(name);
    std::sort(names.begin(), names.end());
    std::string message = "unknown name '" + decl.target.text + "' to instantiate";
    if (points_.count(decl.target.text))
      message = "'" + decl.target.text +
                "' is a point: instantiate a mesh, "
                "face, object, polyline, generator or group";
    else
      message += did_you_mean(decl.target.text, names);
    errors.push_back(located(decl.target.location, message));
    return;
  }
  Placement p;
  p.path = parent == no_index ? decl.name.text : placements_[parent].path + "_" + decl.name.text;
  p.parent = parent;
  p.top = top;
  p.group = group;
  p.statement = statement;
  p.target = it->second;
  const Index id = Index(placements_.size());
  placements_.push_back(std::move(p));
  if (it->second.kind != DefinitionKind::group) return;
  const Index g = it->second.index;
  if (std::find(stack.begin(), stack.end(), g) != stack.end()) {
    if (!is_reported(decl.target.location))
      errors.push_back(located(decl.target.location, "group '" + decl.target.text + "' contains itself"));
    return;
  }
  if (stack.size() >= max_instance_depth) {
    if (!is_reported(decl.location))
      errors.push_back(located(decl.location, "instances nested more than " +
                                                  std::to_string(max_instance_depth) + " levels deep"));
    return;
  }
  stack.push_back(g);
  std::unordered_map<std::string, SourceLocation> seen;
  const GroupDecl& gd = ast_.groups[g];
  for (Index i = 0; i < gd.instances.size(); ++i) {
    const InstanceDecl& child = gd.instances[i];
    if (!seen.emplace(child.name.text, child.name.location).second) continue;  // reported by from_ast
    expand(child, g, i, id, top, stack, errors);
  }
  stack.pop_back();
}

// Counted without recursion: a chain of groups may be far deeper than the stack allows (expand refuses
// it later). A group on a cycle counts what it reaches before the cycle, which expand reports.
std::vector<double> Scene::group_expansion_sizes() const {
  const size_t groups = ast_.groups.size();
  std::vector<double> size(groups, 0);
  std::vector<char> state(groups, 0);          // 0: not reached, 1: being counted, 2: counted
  std::vector<std::pair<Index, Index>> stack;  // a group and its next instance statement
  const auto group_target = [&](const InstanceDecl& decl) {
    const auto it = definitions_.find(decl.target.text);
    return it != definitions_.end() && it->second.kind == DefinitionKind::group ? it->second.index : no_index;
  };
  for (Index root = 0; root < groups; ++root) {
    if (state[root]) continue;
    state[root] = 1;
    stack.push_back({root, 0});
    while (!stack.empty()) {
      const auto [g, next] = stack.back();
      const std::vector<InstanceDecl>& statements = ast_.groups[g].instances;
      if (next == statements.size()) {
        state[g] = 2;
        stack.pop_back();
        if (!stack.empty()) size[stack.back().first] += size[g];
        continue;
      }
      ++stack.back().second;
      size[g] += 1;
      const Index target = group_target(statements[next]);
      if (target == no_index || state[target] == 1) continue;
      if (state[target] == 2) {
        size[g] += size[target];
      } else {
        state[target] = 1;
        stack.push_back({target, 0});
      }
    }
  }
  return size;
}

bool Scene::within_instance_budget(double placements, const InstanceDecl& crossing,
                                   std::vector<Diagnostic>& errors) const {
  const double budget = double(options_.instance_budget);
  // Placements are numbered by 32-bit ids.
  const double id_limit = double(no_index) - 1;
  if (placements <= (options_.force ? id_limit : std::min(budget, id_limit))) return true;
  char count[32];
  std::snprintf(count, sizeof count, placements < 1e15 ? "%.0f" : "%.3g", placements);
  const std::string expands = std::string("the scene would expand to about ") + count + " instances";
  if (options_.force || budget >= id_limit) {
    errors.push_back(located(crossing.location, expands + ", more than Nome can number"));
    return false;
  }
  throw BudgetError(
      located(crossing.location, expands + ", over the budget of " + std::to_string(options_.instance_budget))
          .to_string());
}

void Scene::build(std::vector<Diagnostic>& errors) {
  placements_.clear();
  instances_.clear();
  // The whole tree is counted before any of it is expanded, so that refusing it costs nothing.
  const std::vector<double> group_sizes = group_expansion_sizes();
  double placements = 0;
  std::unordered_map<std::string, SourceLocation> seen;
  for (Index i = 0; i < ast_.instances.size(); ++i) {
    const InstanceDecl& decl = ast_.instances[i];
    if (const auto s = seen.find(decl.name.text); s != seen.end()) {
      errors.push_back(located(decl.name.location, "duplicate instance name '" + decl.name.text +
                                                       "' (first at " + at_text(s->second) + ")"));
      continue;
    }
    seen[decl.name.text] = decl.name.location;
    const auto target = definitions_.find(decl.target.text);
    placements += 1;
    if (target != definitions_.end() && target->second.kind == DefinitionKind::group)
      placements += group_sizes[target->second.index];
    if (!within_instance_budget(placements, decl, errors)) return;
    std::vector<Index> stack;
    instances_.push_back({decl.name.text, {}, 0, 0});
    expand(decl, no_index, i, no_index, Index(instances_.size() - 1), stack, errors);
  }
  if (!consolidated_.empty()) {
    // The consolidated mesh is shown where it was made, like the 2016 program did.
    Placement p;
    p.path = consolidated_mesh_name;
    p.top = Index(instances_.size());
    p.target = {DefinitionKind::consolidated, 0};
    instances_.push_back({consolidated_mesh_name, {}, 0, 0});
    placements_.push_back(std::move(p));
  }
  if (!errors.empty()) return;
  std::vector<Index> leaves;
  for (Index i = 0; i < placements_.size(); ++i)
    if (is_leaf(placements_[i])) leaves.push_back(i);
  if (const auto over = evaluate_all(leaves, errors)) throw BudgetError(*over);
  if (!errors.empty()) return;
  deleted_ = resolve_deleted(ast_.deleted_faces, errors);
  assemble_all();
}

glm::dmat4 Scene::world_matrix(Index placement, std::vector<Index>& reads) const {
  glm::dmat4 m(1.0);
  for (Index p = placement; p != no_index; p = placements_[p].parent) {
    const InstanceDecl* decl = statement(placements_[p]);
    if (!decl) continue;
    glm::dmat4 local(1.0);
    for (const TransformDecl& t : decl->transforms) {
      double a[4];
      const int count = t.kind == TransformKind::translate || t.kind == TransformKind::scale ? 3 : 4;
      for (int k = 0; k < count; ++k) a[k] = evaluate(ast_.expressions, t.args[k], values_, &reads);
      const Vec3 v(a[0], a[1], a[2]);
      glm::dmat4 step(1.0);
      switch (t.kind) {
        case TransformKind::translate:
          step = glm::translate(glm::dmat4(1.0), v);
          break;
        case TransformKind::scale:
          step = glm::scale(glm::dmat4(1.0), v);
          break;
        case TransformKind::rotate:
          if (glm::length(v) == 0) throw EvaluationError(t.location, "rotate needs a non-zero axis");
          step = glm::rotate(glm::dmat4(1.0), a[3] * std::numbers::pi / 180, glm::normalize(v));
          break;
        case TransformKind::mirror: {
          // Reflection in the plane a x + b y + c z + d = 0: p' = p - 2 (n.p + d) n / |n|^2.
          const double nn = glm::dot(v, v);
          if (nn == 0) throw EvaluationError(t.location, "mirror needs a non-zero plane normal (a b c)");
          for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) step[c][r] = (r == c ? 1.0 : 0.0) - 2 * v[r] * v[c] / nn;
          for (int r = 0; r < 3; ++r) step[3][r] = -2 * a[3] * v[r] / nn;
          break;
        }
      }
      local = step * local;
    }
    m = local * m;
  }
  return m;
}

Color Scene::surface_color(const Name& surface, std::vector<Index>& reads) const {
  const auto it = surfaces_.find(surface.text);
  if (it == surfaces_.end()) {
    std::vector<std::string> names;
    for (const auto& [n, i] : surfaces_) names.push_back(n);
    throw EvaluationError(surface.location,
                          "unknown surface '" + surface.text + "'" + did_you_mean(surface.text, names));
  }
  const SurfaceDecl& s = ast_.surfaces[it->second];
  Color c;
  for (int k = 0; k < 3; ++k)
    c[k] = float(std::clamp(evaluate(ast_.expressions, s.rgb[k], values_, &reads), 0.0, 1.0));
  return c;
}

std::optional<Color> Scene::placement_color(Index placement, std::vector<Index>& reads) const {
  for (Index p = placement; p != no_index; p = placements_[p].parent) {
    const InstanceDecl* decl = statement(placements_[p]);
    if (decl && decl->surface) return surface_color(*decl->surface, reads);
  }
  return std::nullopt;
}

void Scene::index_vertex_names() {
  vertex_suffixes_.clear();
  for (Index p = 0; p < placements_.size(); ++p) {
    if (!is_leaf(placements_[p]) || placements_[p].references) continue;
    const auto& names = placements_[p].world.soup.vertex_names;
    for (Index v = 0; v < names.size(); ++v)
      for_each_suffix(names[v], [&](const std::string& s) { vertex_suffixes_[s].push_back({p, v}); });
  }
}

const Scene::VertexRef* Scene::lookup_vertex(const Name& name, std::vector<Diagnostic>& errors) const {
  const auto it = vertex_suffixes_.find(name.text);
  if (it != vertex_suffixes_.end() && it->second.size() == 1) return &it->second.front();
  if (it == vertex_suffixes_.end()) {
    std::vector<std::string> names;
    for (const auto& [s, refs] : vertex_suffixes_)
      if (refs.size() == 1 && placements_[refs[0].placement].world.soup.vertex_names[refs[0].vertex] == s)
        names.push_back(s);
    std::sort(names.begin(), names.end());
    errors.push_back(
        located(name.location, "unknown vertex '" + name.text + "'" + did_you_mean(name.text, names)));
  } else {
    std::string list;
    for (size_t i = 0; i < it->second.size() && i < 6; ++i)
      list += (i ? ", " : "") +
              placements_[it->second[i].placement].world.soup.vertex_names[it->second[i].vertex];
    if (it->second.size() > 6) list += ", ...";
    errors.push_back(located(name.location, "ambiguous vertex name '" + name.text + "': " +
                                                std::to_string(it->second.size()) + " candidates: " + list));
  }
  return nullptr;
}

std::string Scene::resolve_vertex_name(const std::string& name) const {
  std::vector<Diagnostic> errors;
  const VertexRef* ref = lookup_vertex({normalize_name(name), {}}, errors);
  if (!ref) throw SceneError(std::move(errors));
  return placements_[ref->placement].world.soup.vertex_names[ref->vertex];
}

Piece Scene::definition_piece(const Placement& p, std::vector<Index>& reads,
                              std::vector<Diagnostic>& errors) {
  Piece piece;
  const auto number = [&](const Value& v) { return evaluate(ast_.expressions, v, values_, &reads); };
  const auto whole = [&](const Value& v, int min, const char* what) {
    const double x = number(v);
    if (std::abs(x - std::round(x)) > 1e-9 || x < min || x > max_ring_vertices)
      throw EvaluationError(v.location, std::string(what) + " must be a whole number in [" +
                                            std::to_string(min) + ", " + std::to_string(max_ring_vertices) +
                                            "], found " + format_number(x));
    return int(std::lround(x));
  };
  const auto positive = [&](const Value& v, const char* what) {
    const double x = number(v);
    if (!(x > 0))
      throw EvaluationError(v.location, std::string(what) + " must be positive, found " + format_number(x));
    return x;
  };
  const auto ratio = [&](const Value& v) {
    const double x = number(v);
    if (!(x > -1)) throw EvaluationError(v.location, "ratio must be above -1, found " + format_number(x));
    return x;
  };

  // Vertices of meshes, faces, objects and polylines: a point by name, or any placed vertex by a unique
  // suffix of its hierarchical name, whose world position is copied.
  std::unordered_map<std::string, Index> local;
  const auto vertex = [&](const Name& name) -> Index {
    const bool is_point = points_.count(name.text) > 0;
    const std::string key = (is_point ? "p:" : "r:") + name.text;
    if (const auto it = local.find(key); it != local.end()) return it->second;
    Index v = no_index;
    if (is_point) {
      const PointDecl& pt = ast_.points[points_.at(name.text)];
      v = piece.add_vertex({number(pt.xyz[0]), number(pt.xyz[1]), number(pt.xyz[2])}, name.text);
    } else if (const VertexRef* ref = lookup_vertex(name, errors)) {
      const Placement& source = placements_[ref->placement];
      v = piece.add_vertex(source.world.soup.positions[ref->vertex],
                           source.world.soup.vertex_names[ref->vertex]);
      reads.insert(reads.end(), source.reads.begin(), source.reads.end());
    }
    if (v != no_index) local[key] = v;
    return v;
  };
  const auto add_face = [&](const std::vector<Name>& names, const std::string& face_name,
                            const std::optional<Name>& surface) {
    std::vector<Index> corners;
    for (const Name& n : names) corners.push_back(vertex(n));
    if (std::find(corners.begin(), corners.end(), no_index) != corners.end()) return;
    piece.add_face(corners, face_name);
    if (surface) {
      piece.soup.face_colors.back() = surface_color(*surface, reads);
      piece.face_has_color.back() = 1;
    }
  };
  const auto add_rim = [&](const PolylineDecl& line) {
    RimLine rim{line.name.text, {}, line.is_loop};
    for (const Name& n : line.vertices) rim.vertices.push_back(vertex(n));
    if (std::find(rim.vertices.begin(), rim.vertices.end(), no_index) == rim.vertices.end())
      piece.rims.push_back(std::move(rim));
  };

  const Index index = p.target.index;
  switch (p.target.kind) {
    case DefinitionKind::generator: {
      const GeneratorDecl& g = ast_.generators[index];
      const auto& a = g.args;
      switch (g.kind) {
        case GeneratorKind::funnel:
          return funnel({whole(a[0], 3, "n"), positive(a[1], "ro"), ratio(a[2]), number(a[3])});
        case GeneratorKind::tunnel: {
          TunnelParams t{whole(a[0], 3, "n"), positive(a[1], "ro"), ratio(a[2]), number(a[3]), 0, 0};
          t.ratio_low = a.size() == 6 ? ratio(a[4]) : t.ratio;
          t.h_low = a.size() == 6 ? number(a[5]) : t.h;
          return tunnel(t);
        }
        case GeneratorKind::circle:
          return circle(whole(a[0], 3, "n"), positive(a[1], "r"));
        case GeneratorKind::mobius_strip:
          return mobius_strip({positive(a[0], "radius"), whole(a[1], 0, "twists"), whole(a[2], 1, "cuts"),
                               whole(a[3], 3, "segs")});
      }
      break;
    }
    case DefinitionKind::mesh: {
      const MeshDecl& m = ast_.meshes[index];
      for (const FaceDecl& f : m.faces) add_face(f.vertices, f.name.text, f.surface);
      for (const SharpDecl& s : m.sharps) {
        for (size_t i = 0; i + 1 < s.vertices.size(); ++i) {
          const Index a = vertex(s.vertices[i]), b = vertex(s.vertices[i + 1]);
          if (a != no_index && b != no_index) piece.soup.sharp_edges.emplace_back(a, b);
        }
      }
      break;
    }
    case DefinitionKind::face: {
      const FaceDecl& f = ast_.faces[index];
      add_face(f.vertices, f.name.text, f.surface);
      break;
    }
    case DefinitionKind::object: {
      for (const Name& face : ast_.objects[index].faces) {
        const auto it = definitions_.find(face.text);
        if (it == definitions_.end() || it->second.kind != DefinitionKind::face) {
          std::vector<std::string> names;
          for (const FaceDecl& f : ast_.faces) names.push_back(f.name.text);
          errors.push_back(
              located(face.location, "unknown face '" + face.text + "'" + did_you_mean(face.text, names)));
          continue;
        }
        const FaceDecl& f = ast_.faces[it->second.index];
        add_face(f.vertices, f.name.text, f.surface);
      }
      break;
    }
    case DefinitionKind::polyline:
      add_rim(ast_.polylines[index]);
      break;
    case DefinitionKind::consolidated: {
      const size_t first_error = errors.size();
      for (size_t i = 0; i < ast_.consolidated_faces.size(); ++i)
        add_face(ast_.consolidated_faces[i].vertices, "cf" + std::to_string(i), std::nullopt);
      // The names are located in the file that gave them: the scene, or an .anom file's working mesh.
      if (!consolidated_file_.empty())
        for (size_t e = first_error; e < errors.size(); ++e) errors[e].file = consolidated_file_;
      break;
    }
    case DefinitionKind::group:
      break;
  }
  return piece;
}

Piece Scene::evaluate_placement(Index placement, std::vector<Index>& reads, std::vector<Diagnostic>& errors) {
  ++placement_evaluations_;
  reads.clear();
  const Placement& p = placements_[placement];
  try {
    const glm::dmat4 m = world_matrix(placement, reads);
    const std::optional<Color> color = placement_color(placement, reads);
    Piece piece = definition_piece(p, reads, errors);
    for (Vec3& x : piece.soup.positions) x = Vec3(m * glm::dvec4(x, 1.0));
    if (glm::determinant(m) < 0) {
      // A reflection turns every face inside out: reverse the corner order so normals stay outward.
      for (Index f = 0; f < piece.soup.num_faces(); ++f)
        std::reverse(piece.soup.face_vertices.begin() + piece.soup.face_offsets[f],
                     piece.soup.face_vertices.begin() + piece.soup.face_offsets[f + 1]);
    }
    for (std::string& n : piece.soup.vertex_names) n = p.path + "_" + n;
    for (std::string& n : piece.soup.face_names) n = p.path + "_" + n;
    for (RimLine& r : piece.rims) r.name = r.name.empty() ? p.path : p.path + "_" + r.name;
    if (color)
      for (Index f = 0; f < piece.soup.num_faces(); ++f)
        if (!piece.face_has_color[f]) {
          piece.soup.face_colors[f] = *color;
          piece.face_has_color[f] = 1;
        }
    sort_unique(reads);
    return piece;
  } catch (const EvaluationError& e) {
    errors.push_back(located(e.where(), e.what()));
  }
  sort_unique(reads);
  return {};
}

std::optional<std::string> Scene::evaluate_all(const std::vector<Index>& placements,
                                               std::vector<Diagnostic>& errors) {
  // The faces of every piece, those about to be made again left out; each new piece is counted in as it
  // comes, so that evaluation stops within one piece (at most a generator's 100,000 segments) of the budget.
  double faces = 0;
  for (const Placement& p : placements_) faces += p.world.soup.num_faces();
  for (Index i : placements) faces -= placements_[i].world.soup.num_faces();
  Index evaluated = 0;
  std::optional<std::string> over_budget;
  const auto count_in = [&](Index i) {
    faces += placements_[i].world.soup.num_faces();
    ++evaluated;
    if (options_.force || faces <= double(options_.face_budget)) return true;
    // The pieces not made yet are taken to be as large as those made so far.
    const double estimate = faces / evaluated * double(placements.size());
    char count[32];
    std::snprintf(count, sizeof count, "%.0f", std::max(estimate, faces));
    const InstanceDecl* at = statement(placements_[i]);
    over_budget = located(at ? at->location : SourceLocation{},
                          std::string("the scene's pieces would have about ") + count +
                              " faces, over the budget of " + std::to_string(options_.face_budget))
                      .to_string();
    return false;
  };
  // Placements whose vertices others copy go first; the name index follows their vertex names.
  bool names_changed = vertex_suffixes_.empty();
  for (Index i : placements) {
    Placement& p = placements_[i];
    if (p.target.kind == DefinitionKind::consolidated) p.references = true;
    if (p.target.kind == DefinitionKind::mesh || p.target.kind == DefinitionKind::face ||
        p.target.kind == DefinitionKind::object || p.target.kind == DefinitionKind::polyline) {
      std::vector<const std::vector<Name>*> lists;
      if (p.target.kind == DefinitionKind::mesh)
        for (const FaceDecl& f : ast_.meshes[p.target.index].faces) lists.push_back(&f.vertices);
      if (p.target.kind == DefinitionKind::face) lists.push_back(&ast_.faces[p.target.index].vertices);
      if (p.target.kind == DefinitionKind::polyline)
        lists.push_back(&ast_.polylines[p.target.index].vertices);
      if (p.target.kind == DefinitionKind::object)
        for (const Name& f : ast_.objects[p.target.index].faces)
          if (const auto it = definitions_.find(f.text);
              it != definitions_.end() && it->second.kind == DefinitionKind::face)
            lists.push_back(&ast_.faces[it->second.index].vertices);
      p.references = std::any_of(lists.begin(), lists.end(), [&](const std::vector<Name>* names) {
        return std::any_of(names->begin(), names->end(),
                           [&](const Name& n) { return !points_.count(n.text); });
      });
    }
  }
  for (Index i : placements) {
    if (placements_[i].references) continue;
    std::vector<Index> reads;
    Piece piece = evaluate_placement(i, reads, errors);
    Placement& p = placements_[i];
    names_changed = names_changed || piece.soup.vertex_names != p.world.soup.vertex_names;
    p.world = std::move(piece);
    p.reads = std::move(reads);
    if (!count_in(i)) return over_budget;
  }
  if (names_changed) index_vertex_names();
  for (Index i : placements) {
    if (!placements_[i].references) continue;
    std::vector<Index> reads;
    Piece piece = evaluate_placement(i, reads, errors);
    placements_[i].world = std::move(piece);
    placements_[i].reads = std::move(reads);
    if (!count_in(i)) return over_budget;
  }
  return std::nullopt;
}

std::vector<std::string> Scene::resolve_deleted(const std::vector<Name>& names,
                                                std::vector<Diagnostic>& errors) {
  std::unordered_map<std::string, std::vector<std::string>> suffixes;
  std::vector<std::string> all;
  for (const Placement& p : placements_)
    for (const std::string& f : p.world.soup.face_names) {
      all.push_back(f);
      for_each_suffix(f, [&](const std::string& s) { suffixes[s].push_back(f); });
    }
  std::vector<std::string> out;
  for (const Name& n : names) {
    const auto it = suffixes.find(n.text);
    if (it == suffixes.end()) {
      errors.push_back(located(n.location, "unknown face '" + n.text + "'" + did_you_mean(n.text, all)));
    } else if (it->second.size() > 1) {
      std::string list;
      for (size_t i = 0; i < it->second.size() && i < 6; ++i) list += (i ? ", " : "") + it->second[i];
      errors.push_back(located(n.location, "ambiguous face name '" + n.text + "': " +
                                               std::to_string(it->second.size()) + " candidates: " + list));
    } else {
      out.push_back(it->second.front());
    }
  }
  return out;
}

void Scene::assemble(Index top) {
  const std::unordered_set<std::string> deleted(deleted_.begin(), deleted_.end());
  Piece out;
  bool any_color = false;
  for (const Placement& p : placements_) {
    if (p.top != top || !is_leaf(p)) continue;
    const PolygonSoup& s = p.world.soup;
    // Keep a vertex unless every face using it is deleted.
    std::vector<unsigned char> used(s.num_vertices(), 0), kept(s.num_vertices(), 0);
    for (Index f = 0; f < s.num_faces(); ++f) {
      const bool keep = !deleted.count(s.face_names[f]);
      for (Index c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c) {
        used[s.face_vertices[c]] = 1;
        if (keep) kept[s.face_vertices[c]] = 1;
      }
    }
    std::vector<Index> new_id(s.num_vertices(), no_index);
    for (Index v = 0; v < s.num_vertices(); ++v)
      if (kept[v] || !used[v]) new_id[v] = out.add_vertex(s.positions[v], s.vertex_names[v]);
    for (Index f = 0; f < s.num_faces(); ++f) {
      if (deleted.count(s.face_names[f])) continue;
      std::vector<Index> corners;
      for (Index c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c)
        corners.push_back(new_id[s.face_vertices[c]]);
      out.add_face(corners, s.face_names[f]);
      out.soup.face_colors.back() = s.face_colors[f];
      out.face_has_color.back() = p.world.face_has_color[f];
      any_color = any_color || p.world.face_has_color[f];
    }
    for (auto [a, b] : s.sharp_edges)
      if (new_id[a] != no_index && new_id[b] != no_index)
        out.soup.sharp_edges.emplace_back(new_id[a], new_id[b]);
    for (const RimLine& r : p.world.rims) {
      RimLine rim{r.name, {}, r.is_loop};
      for (Index v : r.vertices) rim.vertices.push_back(new_id[v]);
      out.rims.push_back(std::move(rim));
    }
  }
  if (!any_color) {
    out.soup.face_colors.clear();
  } else {
    for (Index f = 0; f < out.soup.num_faces(); ++f)
      if (!out.face_has_color[f]) out.soup.face_colors[f] = Color(0.75f);
  }
  SceneInstance& inst = instances_[top];
  if (!same_topology(inst.geometry.soup, out.soup) || inst.geometry_version == 0) ++inst.topology_version;
  ++inst.geometry_version;
  inst.geometry = std::move(out);
}

void Scene::assemble_all() {
  for (Index t = 0; t < instances_.size(); ++t) assemble(t);
}

std::optional<Index> Scene::find_parameter(const std::string& name) const {
  const auto it = parameter_ids_.find(normalize_name(name));
  if (it == parameter_ids_.end()) return std::nullopt;
  return it->second;
}

std::vector<Index> Scene::set_parameter(Index parameter, double value) {
  if (parameter >= parameters_.size())
    throw InvalidInputError("Scene::set_parameter: no parameter " + std::to_string(parameter));
  const Parameter& param = parameters_[parameter];
  if (!std::isfinite(value) || value < param.min || value > param.max)
    throw InvalidInputError(param.full_name + "=" + format_number(value) + " is outside its slider range [" +
                            format_number(param.min) + ", " + format_number(param.max) + "]");
  const double old_value = values_[parameter];
  values_[parameter] = value;
  parameters_[parameter].value = value;
  std::vector<Index> affected;
  for (Index i = 0; i < placements_.size(); ++i)
    if (is_leaf(placements_[i]) &&
        std::binary_search(placements_[i].reads.begin(), placements_[i].reads.end(), parameter))
      affected.push_back(i);
  std::vector<std::pair<Piece, std::vector<Index>>> backup;
  for (Index i : affected) backup.emplace_back(placements_[i].world, placements_[i].reads);
  std::vector<Diagnostic> errors;
  const auto over_budget = evaluate_all(affected, errors);
  if (!errors.empty() || over_budget) {
    values_[parameter] = old_value;
    parameters_[parameter].value = old_value;
    for (size_t k = 0; k < affected.size(); ++k) {
      placements_[affected[k]].world = std::move(backup[k].first);
      placements_[affected[k]].reads = std::move(backup[k].second);
    }
    index_vertex_names();
    if (over_budget) throw BudgetError(*over_budget);
    throw SceneError(std::move(errors));
  }
  std::vector<Index> tops;
  for (Index i : affected) tops.push_back(placements_[i].top);
  sort_unique(tops);
  for (Index t : tops) assemble(t);
  return tops;
}

void Scene::set_consolidated_faces(std::vector<std::vector<std::string>> faces) {
  std::vector<NamedFace> named;
  for (const auto& face : faces) {
    NamedFace f;
    for (const std::string& n : face) f.vertices.push_back({normalize_name(n), {}});
    named.push_back(std::move(f));
  }
  Scene next = *this;
  next.ast_.consolidated_faces = std::move(named);
  next.consolidated_ = std::move(faces);
  next.consolidated_file_.clear();
  std::vector<Diagnostic> errors;
  next.vertex_suffixes_.clear();
  next.build(errors);
  if (!errors.empty()) throw SceneError(std::move(errors));
  *this = std::move(next);
}

void Scene::set_deleted_faces(std::vector<std::string> faces) {
  std::vector<Name> names;
  for (const std::string& f : faces) names.push_back({normalize_name(f), {}});
  std::vector<Diagnostic> errors;
  std::vector<std::string> resolved = resolve_deleted(names, errors);
  if (!errors.empty()) throw SceneError(std::move(errors));
  ast_.deleted_faces = std::move(names);
  deleted_ = std::move(resolved);
  assemble_all();
}

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
    next.values_[*id] = value;
    next.parameters_[*id].value = value;
  }
  if (!errors.empty()) throw SceneError(std::move(errors));
  if (!anom.working_mesh.empty()) {
    next.ast_.consolidated_faces = anom.working_mesh;
    next.consolidated_file_ = file;
    next.consolidated_.clear();
    for (const NamedFace& f : anom.working_mesh) {
      std::vector<std::string> face;
      for (const Name& n : f.vertices) face.push_back(n.text);
      next.consolidated_.push_back(std::move(face));
    }
  }
  next.vertex_suffixes_.clear();
  next.build(errors);
  if (!errors.empty()) throw SceneError(std::move(errors));
  *this = std::move(next);
}

PolygonSoup Scene::combined_soup() const {
  PolygonSoup out;
  bool any_color = false;
  for (const SceneInstance& i : instances_) any_color = any_color || !i.geometry.soup.face_colors.empty();
  for (const SceneInstance& i : instances_) {
    const PolygonSoup& s = i.geometry.soup;
    const Index base = out.num_vertices();
    out.positions.insert(out.positions.end(), s.positions.begin(), s.positions.end());
    out.vertex_names.insert(out.vertex_names.end(), s.vertex_names.begin(), s.vertex_names.end());
    for (Index f = 0; f < s.num_faces(); ++f) {
      for (Index c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c)
        out.face_vertices.push_back(s.face_vertices[c] + base);
      out.face_offsets.push_back(Index(out.face_vertices.size()));
      if (any_color) out.face_colors.push_back(s.face_colors.empty() ? Color(0.75f) : s.face_colors[f]);
    }
    out.face_names.insert(out.face_names.end(), s.face_names.begin(), s.face_names.end());
    for (auto [a, b] : s.sharp_edges) out.sharp_edges.emplace_back(a + base, b + base);
  }
  return out;
}

}  // namespace nome::scene
