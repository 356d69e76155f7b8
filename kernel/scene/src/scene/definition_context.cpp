#include "scene/definition_context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "nome/error.hpp"

namespace nome::scene {
namespace {

constexpr int max_ring_vertices = 100000;

}  // namespace

Index DefinitionScope::top_level_face(const std::string& name) const {
  const auto it = scene_.definitions_.find(name);
  if (it == scene_.definitions_.end() || it->second.kind == Scene::consolidated_kind ||
      statement_kinds()[it->second.kind].keyword != "face")
    return no_index;
  return it->second.index;
}

double DefinitionContext::number(const Value& v) {
  return evaluate(scene_.ast_.expressions, v, scene_.values_, &reads_);
}

int DefinitionContext::whole(const Value& v, int min, const char* what) {
  const double x = number(v);
  if (std::abs(x - std::round(x)) > 1e-9 || x < min || x > max_ring_vertices)
    throw EvaluationError(v.location, std::string(what) + " must be a whole number in [" +
                                          std::to_string(min) + ", " + std::to_string(max_ring_vertices) +
                                          "], found " + format_number(x));
  return int(std::lround(x));
}

double DefinitionContext::positive(const Value& v, const char* what) {
  const double x = number(v);
  if (!(x > 0))
    throw EvaluationError(v.location, std::string(what) + " must be positive, found " + format_number(x));
  return x;
}

double DefinitionContext::ratio(const Value& v) {
  const double x = number(v);
  if (!(x > -1)) throw EvaluationError(v.location, "ratio must be above -1, found " + format_number(x));
  return x;
}

const ControlPointDecl* DefinitionScope::control_point(const std::string& name) const {
  const auto it = scene_.control_points_.find(name);
  return it == scene_.control_points_.end() ? nullptr : &scene_.ast_.control_points[it->second];
}

std::optional<std::pair<Index, Index>> DefinitionScope::definition(const std::string& name) const {
  const auto it = scene_.definitions_.find(name);
  if (it == scene_.definitions_.end() || it->second.kind == Scene::consolidated_kind) return std::nullopt;
  return std::pair{it->second.kind, it->second.index};
}

std::optional<Vec3> DefinitionContext::position(const Name& name) {
  is_copy_only_ = false;  // a position read, not a vertex copied: the piece's positions are computed
  Name point = name;
  if (const ControlPointDecl* c = control_point(name.text)) {
    if (!scene_.points_.count(c->point.text))
      throw EvaluationError(c->point.location,
                            "controlpoint '" + c->name.text + "': '" + c->point.text + "' is not a point");
    point = c->point;
  }
  if (const auto it = scene_.points_.find(point.text); it != scene_.points_.end()) {
    const PointDecl& pt = scene_.ast_.points[it->second];
    return Vec3(number(pt.xyz[0]), number(pt.xyz[1]), number(pt.xyz[2]));
  }
  const Scene::VertexRef* ref = scene_.lookup_vertex(name, errors_);
  if (!ref) return std::nullopt;
  const Scene::Placement& source = scene_.placements_[ref->placement];
  reads_.insert(reads_.end(), source.reads.begin(), source.reads.end());
  return source.world.soup.positions[ref->vertex];
}

Index DefinitionContext::vertex(const Name& name) {
  const bool is_pt = is_point(name.text);
  const std::string key = (is_pt ? "p:" : "r:") + name.text;
  if (const auto it = local_.find(key); it != local_.end()) return it->second;
  Index v = no_index;
  if (is_pt) {
    v = piece_.add_vertex(*position(name), name.text);
  } else if (!may_name_placed_vertex(name.text)) {
    error(name.location, "unknown point '" + name.text + "'");
  } else if (const Scene::VertexRef* ref = scene_.lookup_vertex(name, errors_)) {
    const Scene::Placement& source = scene_.placements_[ref->placement];
    v = piece_.add_vertex(source.world.soup.positions[ref->vertex],
                          source.world.soup.vertex_names[ref->vertex]);
    reads_.insert(reads_.end(), source.reads.begin(), source.reads.end());
    is_copy_only_ = is_copy_only_ && v == copied_from_.size();
    copied_from_.push_back(*ref);
  }
  if (v != no_index) local_[key] = v;
  return v;
}

std::vector<Scene::VertexRef> DefinitionContext::copied_from() const {
  return is_copy_only_ ? copied_from_ : std::vector<Scene::VertexRef>{};
}

void DefinitionContext::add_face(const std::vector<Name>& names, const std::string& face_name,
                                 const std::optional<Name>& surface, SourceLocation at) {
  const size_t errors_before = errors_.size();
  std::vector<Index> corners;
  for (const Name& n : names) corners.push_back(vertex(n));
  if (std::find(corners.begin(), corners.end(), no_index) != corners.end()) {
    // JIPCAD skips a point it cannot find and goes on; its files rely on that (one of its examples names
    // points that do not exist). In its dialect the face is left out instead, with a warning: a face
    // with points missing is not the one its author meant.
    if (scene_.dialect().dialect == Dialect::jipcad) {
      for (size_t i = errors_before; i < errors_.size(); ++i)
        warning(errors_[i].location, errors_[i].message + ": face '" + face_name + "' left out");
      errors_.resize(errors_before);
    }
    return;
  }
  if (scene_.dialect().dialect == Dialect::jipcad && corners.size() >= 4 &&
      corners.front() == corners.back()) {
    // JIPCAD's files close a polygon by naming its first vertex again (`(sq1 sq2 sq3 sq4 sq1)`), as its
    // tutorials do on face after face: the polygon is meant, and one note per file says so.
    corners.pop_back();
    constexpr std::string_view note =
        "a face that names its first vertex again at its end is read as the "
        "closed polygon without the repeat";
    const auto is_note = [&](const Diagnostic& d) { return d.message.starts_with(note); };
    // It is about the text, not a value: the scene keeps it once for the file.
    if (std::none_of(scene_.warnings_.begin(), scene_.warnings_.end(), is_note))
      scene_.add_warning(
          at, std::string(note) + " (face '" + face_name + "' here, and every such face in this file)");
  }
  piece_.soup.note_origin(scene_.where(at));
  piece_.add_face(corners, face_name);
  if (surface) piece_.set_face_color(piece_.soup.num_faces() - 1, surface_color(*surface));
}

void DefinitionContext::add_rim(const Name& name, const std::vector<Name>& vertices, bool is_loop) {
  RimLine rim{name.text, {}, is_loop};
  for (const Name& n : vertices) rim.vertices.push_back(vertex(n));
  if (std::find(rim.vertices.begin(), rim.vertices.end(), no_index) == rim.vertices.end())
    piece_.rims.push_back(std::move(rim));
}

Color DefinitionContext::surface_color(const Name& surface) {
  return scene_.surface_color(surface, reads_);
}

void DefinitionContext::warning(SourceLocation at, std::string message) {
  Diagnostic d{Severity::warning, scene_.file(), at, std::move(message)};
  if (std::find(warnings_.begin(), warnings_.end(), d) == warnings_.end()) warnings_.push_back(std::move(d));
}

void DefinitionContext::error(SourceLocation at, std::string message) {
  errors_.push_back(scene_.located(at, std::move(message)));
}

void DefinitionContext::expect_faces(SourceLocation at, const std::string& what, double faces) const {
  const SceneOptions& options = scene_.options_;
  if (faces <= double(options.face_budget)) return;
  char count[64];
  // About 150 bytes a face from the scene's pieces to the merged mesh (SceneOptions).
  std::snprintf(count, sizeof count, "%.0f faces (about %.1f GB)", faces, faces * 150.0 / double(1 << 30));
  const std::string estimate = what + " would make about " + count;
  if (faces > double(no_index) - 1) throw EvaluationError(at, estimate + ", more than Nome can number");
  if (options.force) return;
  throw BudgetError(scene_
                        .located(at, estimate + ", over the scene's budget of " +
                                         std::to_string(options.face_budget) + " faces")
                        .to_string());
}

}  // namespace nome::scene
