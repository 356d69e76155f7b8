#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "nome/scene/scene.hpp"
#include "nome/scene/statement_kinds.hpp"

namespace nome::scene {

// What a definition kind may look up in the scene without evaluating anything.
class DefinitionScope {
 public:
  explicit DefinitionScope(const Scene& scene) : scene_(scene) {}
  const SceneAst& ast() const { return scene_.ast_; }
  bool is_point(const std::string& name) const {
    return scene_.points_.count(name) > 0 || scene_.control_points_.count(name) > 0;
  }
  // Whether a name that is not a point may name another placement's vertex. In JIPCAD's dialect only a path
  // does (`inst.point`): a bare name there means a point, so an unknown one is a missing point, not a
  // vertex found by suffix as in the 2016 report.
  bool may_name_placed_vertex(const std::string& name) const {
    return !is_point(name) &&
           (scene_.dialect().dialect != Dialect::jipcad || name.find('_') != std::string::npos);
  }
  // The control point of that name, or null.
  const ControlPointDecl* control_point(const std::string& name) const;
  // What a name defines: its row of statement_kinds() and declaration, if a definition of a kind.
  std::optional<std::pair<Index, Index>> definition(const std::string& name) const;
  // The top-level face definition of that name (objects are made of them), or no_index.
  Index top_level_face(const std::string& name) const;

 protected:
  const Scene& scene_;
};

// One definition being evaluated into a piece: its numbers (recording the sliders they read), its
// vertices (points, or other placements' vertices by unique name suffix, whose world positions are
// copied), faces, rim lines, and the errors found on the way.
class DefinitionContext : public DefinitionScope {
 public:
  DefinitionContext(const Scene& scene, ParameterReads& reads, std::vector<Diagnostic>& errors)
      : DefinitionScope(scene), reads_(reads), errors_(errors) {}

  double number(const Value& v);
  // A whole number in [min, 100000] (a generator makes at most 100,000 segments).
  int whole(const Value& v, int min, const char* what);
  double positive(const Value& v, const char* what);
  // A funnel's ratio: above -1, so that the high circle keeps a positive radius.
  double ratio(const Value& v);

  // The piece's vertex for a name: a point, or a placed vertex; no_index (with the error) if unknown.
  Index vertex(const Name& name);
  // Where a named vertex is, without adding it to the piece (a sweep reads its curves' points so).
  std::optional<Vec3> position(const Name& name);
  // A warning about the values this evaluation read; the next evaluation of the placement replaces it.
  void warning(SourceLocation at, std::string message);
  const std::vector<Diagnostic>& warnings() const { return warnings_; }
  // A face over named vertices, made by the statement at `at`; left out when one of them is unknown.
  void add_face(const std::vector<Name>& names, const std::string& face_name,
                const std::optional<Name>& surface, SourceLocation at);
  void add_rim(const Name& name, const std::vector<Name>& vertices, bool is_loop);
  Color surface_color(const Name& surface);
  void error(SourceLocation at, std::string message);
  // Refuses a piece before it is made: `what` (the statement, "torus 't'") would make about `faces`
  // faces. Over the scene's face budget it throws BudgetError at `at` with the estimate, unless forced;
  // beyond 32-bit ids, an EvaluationError even when forced.
  void expect_faces(SourceLocation at, const std::string& what, double faces) const;

  Piece& piece() { return piece_; }
  // Where each vertex of the piece was copied from, in order, when every one added through vertex() was
  // copied from another placement (a slider that only moved those moves the copies without evaluating
  // again); empty otherwise. The caller checks that the piece has no other vertices.
  std::vector<Scene::VertexRef> copied_from() const;

 private:
  ParameterReads& reads_;
  std::vector<Diagnostic>& errors_;
  std::vector<Diagnostic> warnings_;
  Piece piece_;
  std::unordered_map<std::string, Index> local_;  // "p:NAME" (a point) or "r:NAME" (a reference) -> vertex
  std::vector<Scene::VertexRef> copied_from_;     // one per vertex, while is_copy_only_
  bool is_copy_only_ = true;
};

}  // namespace nome::scene
