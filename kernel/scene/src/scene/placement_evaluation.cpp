// A placement's piece in world space: its definition evaluated by the definition's kind, moved by the
// transforms of its instance statement and its ancestors', coloured by the nearest surface, named by
// its path; and the passes that evaluate many placements within the face budget.
#include <algorithm>
#include <cstdio>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "nome/error.hpp"
#include "nome/scene/scene.hpp"
#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"
#include "scene/index_sets.hpp"

namespace nome::scene {
namespace {

// One transform as a matrix; `a` holds its evaluated arguments.
glm::dmat4 transform_matrix(const TransformDecl& t, const double* a) {
  const Vec3 v(a[0], a[1], a[2]);
  switch (t.kind) {
    case TransformKind::translate:
      return glm::translate(glm::dmat4(1.0), v);
    case TransformKind::scale:
      return glm::scale(glm::dmat4(1.0), v);
    case TransformKind::rotate:
      // A turn by no angle is the identity whatever its axis (arts_expo__cross.nom writes (0 0 0) (0)).
      if (a[3] == 0) return glm::dmat4(1.0);
      if (glm::length(v) == 0) throw EvaluationError(t.location, "rotate needs a non-zero axis");
      return glm::rotate(glm::dmat4(1.0), a[3] * std::numbers::pi / 180, glm::normalize(v));
    case TransformKind::mirror:
      break;
  }
  // Reflection in the plane a x + b y + c z + d = 0: p' = p - 2 (n.p + d) n / |n|^2.
  const double nn = glm::dot(v, v);
  if (nn == 0) throw EvaluationError(t.location, "mirror needs a non-zero plane normal (a b c)");
  glm::dmat4 step(1.0);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) step[c][r] = (r == c ? 1.0 : 0.0) - 2 * v[r] * v[c] / nn;
  for (int r = 0; r < 3; ++r) step[3][r] = -2 * a[3] * v[r] / nn;
  return step;
}

// A reflection turns every face inside out: reverse the corner order so normals stay outward.
void reverse_faces(PolygonSoup& soup) {
  soup.grid.reset();
  for (Index f = 0; f < soup.num_faces(); ++f)
    std::reverse(soup.face_vertices.begin() + soup.face_offsets[f],
                 soup.face_vertices.begin() + soup.face_offsets[f + 1]);
}

// The points into the world (an instance without a transform, most of them, is left as it is).
void place_points(Buffer<Vec3>& points, const glm::dmat4& m) {
  if (m == glm::dmat4(1.0)) return;
  for (Vec3& x : points) x = Vec3(m * glm::dvec4(x, 1.0));
}

}  // namespace

glm::dmat4 Scene::transforms_matrix(const InstanceDecl& decl, std::size_t first, std::size_t end,
                                    ParameterReads& reads) const {
  glm::dmat4 local(1.0);
  for (std::size_t i = first; i < end && i < decl.transforms.size(); ++i) {
    const TransformDecl& t = decl.transforms[i];
    double a[4];
    const int count = t.kind == TransformKind::translate || t.kind == TransformKind::scale ? 3 : 4;
    for (int k = 0; k < count; ++k) a[k] = evaluate(ast_.expressions, t.args[k], values_, &reads);
    local = transform_matrix(t, a) * local;
  }
  return local;
}

glm::dmat4 Scene::transforms_matrix(const InstanceDecl& decl, std::size_t first, std::size_t end) const {
  ParameterReads reads;
  return transforms_matrix(decl, first, end, reads);
}

glm::dmat4 Scene::world_matrix(Index placement, ParameterReads& reads) const {
  glm::dmat4 m(1.0);
  for (Index p = placement; p != no_index; p = placements_[p].parent)
    if (const InstanceDecl* decl = statement(placements_[p])) m = instance_matrix(*decl, reads) * m;
  return m;
}

Color Scene::surface_color(const Name& surface, ParameterReads& reads) const {
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

std::optional<Color> Scene::placement_color(Index placement, ParameterReads& reads) const {
  for (Index p = placement; p != no_index; p = placements_[p].parent) {
    const InstanceDecl* decl = statement(placements_[p]);
    if (decl && decl->surface) return surface_color(*decl->surface, reads);
  }
  return std::nullopt;
}

void Scene::evaluate_definition(const Placement& p, Evaluated& out, std::vector<Diagnostic>& errors) {
  DefinitionContext context(*this, out.reads, errors);
  const auto finish = [&] {
    out.copied_from = context.copied_from();
    if (out.copied_from.size() != context.piece().soup.num_vertices()) out.copied_from.clear();
    out.warnings = context.warnings();
    out.piece = std::move(context.piece());
  };
  if (p.target.kind != consolidated_kind) {
    const StatementKind& kind = statement_kinds()[p.target.kind];
    context.piece() = kind.evaluate(context, p.target.index);
    PolygonSoup& soup = context.piece().soup;
    // A generator's faces all come from its statement; faces over named vertices noted their own.
    if (soup.face_origins.empty() && soup.num_faces() > 0) {
      std::vector<DeclaredName> names;
      kind.declare(ast_, p.target.kind, names);
      for (const DeclaredName& d : names)
        if (d.decl == p.target.index) soup.face_origins.push_back({0, where(d.name->location)});
    }
    finish();
    return;
  }
  const size_t first_error = errors.size();
  for (size_t i = 0; i < ast_.consolidated_faces.size(); ++i)
    context.add_face(ast_.consolidated_faces[i].vertices, "cf" + std::to_string(i), std::nullopt,
                     ast_.consolidated_faces[i].location);
  // The names are located in the file that gave them: the scene, or an .anom file's working mesh.
  if (!consolidated_file_.empty()) {
    for (size_t e = first_error; e < errors.size(); ++e) errors[e].file = consolidated_file_;
    for (FaceOrigin& o : context.piece().soup.face_origins)
      o.where = consolidated_file_ + o.where.substr(ast_.file.size());
  }
  finish();
}

Scene::Evaluated Scene::evaluate_placement(Index placement, std::vector<Diagnostic>& errors) {
  ++placement_evaluations_;
  Evaluated out;
  ParameterReads& reads = out.reads;
  Placement& p = placements_[placement];
  try {
    const glm::dmat4 m = world_matrix(placement, reads);
    const std::optional<Color> color = placement_color(placement, reads);
    evaluate_definition(p, out, errors);
    Piece& piece = out.piece;
    place_points(piece.soup.positions, m);
    p.colors_own_faces = piece.has_face_colors();
    p.color = color;
    p.is_mirrored = glm::determinant(m) < 0;
    if (p.is_mirrored) reverse_faces(piece.soup);
    const std::string prefix = p.path + "_";
    piece.soup.vertex_names.add_prefix(prefix);
    piece.soup.face_names.add_prefix(prefix);
    for (RimLine& r : piece.rims) r.name = r.name.empty() ? p.path : p.path + "_" + r.name;
    if (color) {
      for (Index f = 0; f < piece.soup.num_faces(); ++f)
        if (!piece.has_face_color(f)) piece.set_face_color(f, *color);
      for (RimLine& r : piece.rims)
        if (!r.color) r.color = color;
    }
    sort_unique(reads);
    return out;
  } catch (const EvaluationError& e) {
    errors.push_back(located(e.where(), e.what()));
  }
  sort_unique(reads);
  return {{}, std::move(reads), {}, {}};
}

bool Scene::move_vertices(Index placement, Moved& previous) {
  Placement& p = placements_[placement];
  if (p.target.kind == consolidated_kind || p.references || p.world.topology_key == 0) return false;
  const StatementKind& kind = statement_kinds()[p.target.kind];
  if (!kind.evaluate_positions) return false;
  ParameterReads reads;
  std::vector<Diagnostic> errors;  // any error: the whole evaluation runs and reports it
  try {
    const glm::dmat4 m = world_matrix(placement, reads);
    if (placement_color(placement, reads) != p.color || (glm::determinant(m) < 0) != p.is_mirrored)
      return false;
    DefinitionContext context(*this, reads, errors);
    PiecePositions moved = kind.evaluate_positions(context, p.target.index);
    if (!errors.empty() || moved.topology_key != p.world.topology_key ||
        moved.positions.size() != p.world.soup.positions.size())
      return false;
    place_points(moved.positions, m);
    previous.positions = std::exchange(p.world.soup.positions, std::move(moved.positions));
    previous.warnings = std::exchange(p.warnings, context.warnings());
  } catch (const EvaluationError&) {
    return false;
  } catch (const BudgetError&) {
    return false;  // the whole evaluation refuses it again, and says why
  }
  sort_unique(reads);
  p.reads = std::move(reads);
  ++vertex_moves_;
  return true;
}

bool Scene::move_copied_vertices(Index placement, Moved& previous) {
  Placement& p = placements_[placement];
  // Copying positions would keep the colours of faces whose own surfaces may read the slider.
  if (p.copied_from.empty() || p.colors_own_faces || p.copied_from.size() != p.world.soup.positions.size())
    return false;
  ParameterReads reads;
  Buffer<Vec3> moved(p.copied_from.size());
  try {
    const glm::dmat4 m = world_matrix(placement, reads);
    if (placement_color(placement, reads) != p.color || (glm::determinant(m) < 0) != p.is_mirrored)
      return false;
    for (size_t v = 0; v < moved.size(); ++v) {
      const Placement& source = placements_[p.copied_from[v].placement];
      moved[v] = source.world.soup.positions[p.copied_from[v].vertex];
    }
    place_points(moved, m);
  } catch (const EvaluationError&) {
    return false;
  }
  std::vector<Index> sources;
  for (const VertexRef& ref : p.copied_from) sources.push_back(ref.placement);
  sort_unique(sources);
  for (Index s : sources) reads.insert(reads.end(), placements_[s].reads.begin(), placements_[s].reads.end());
  sort_unique(reads);
  p.reads = std::move(reads);
  previous.positions = std::exchange(p.world.soup.positions, std::move(moved));
  previous.warnings = p.warnings;
  ++vertex_moves_;
  return true;
}

// A placement references other placements when its definition names a vertex that is not a point.
void Scene::mark_references(const std::vector<Index>& placements) {
  const DefinitionScope scope(*this);
  for (Index i : placements) {
    Placement& p = placements_[i];
    if (p.target.kind == consolidated_kind) {
      p.references = true;
      continue;
    }
    const StatementKind& kind = statement_kinds()[p.target.kind];
    if (!kind.vertex_lists) continue;
    std::vector<const std::vector<Name>*> lists;
    kind.vertex_lists(scope, p.target.index, lists);
    p.references = std::any_of(lists.begin(), lists.end(), [&](const std::vector<Name>* names) {
      return std::any_of(names->begin(), names->end(),
                         [&](const Name& n) { return scope.may_name_placed_vertex(n.text); });
    });
  }
}

std::optional<std::string> Scene::evaluate_all(const std::vector<Index>& placements,
                                               std::vector<Diagnostic>& errors) {
  // The faces of every piece, those about to be made again left out; each new piece is counted in as it
  // comes, so that evaluation stops within one piece (at most a generator's 100,000 segments) of the budget.
  double faces = 0;
  for (const Placement& p : placements_) faces += p.world.soup.num_faces();
  for (Index i : placements) faces -= placements_[i].world.soup.num_faces();
  Index evaluated = 0;
  const auto over_budget = [&](Index i) -> std::optional<std::string> {
    faces += placements_[i].world.soup.num_faces();
    ++evaluated;
    if (options_.force || faces <= double(options_.face_budget)) return std::nullopt;
    // The pieces not made yet are taken to be as large as those made so far.
    const double estimate = faces / evaluated * double(placements.size());
    char count[32];
    std::snprintf(count, sizeof count, "%.0f", std::max(estimate, faces));
    const InstanceDecl* at = statement(placements_[i]);
    return located(at ? at->location : SourceLocation{}, std::string("the scene's pieces would have about ") +
                                                             count + " faces, over the budget of " +
                                                             std::to_string(options_.face_budget))
        .to_string();
  };
  mark_references(placements);
  // Placements whose vertices others copy go first; the name index follows their vertex names.
  for (const bool is_referencing : {false, true}) {
    for (Index i : placements) {
      if (placements_[i].references != is_referencing) continue;
      Evaluated evaluated;
      try {
        evaluated = evaluate_placement(i, errors);
      } catch (const BudgetError& e) {
        // A statement refused its piece before making it (DefinitionContext::expect_faces).
        return std::string(e.what());
      }
      Placement& p = placements_[i];
      if (!is_referencing && is_vertex_index_current_ &&
          evaluated.piece.soup.vertex_names != p.world.soup.vertex_names)
        is_vertex_index_current_ = false;
      p.world = std::move(evaluated.piece);
      p.reads = std::move(evaluated.reads);
      p.copied_from = std::move(evaluated.copied_from);
      p.warnings = std::move(evaluated.warnings);
      if (auto over = over_budget(i)) return over;
    }
  }
  return std::nullopt;
}

}  // namespace nome::scene
