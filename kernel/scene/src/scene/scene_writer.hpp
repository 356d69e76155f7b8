#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "nome/scene/scene.hpp"

namespace nome::scene {

// The .nome text of a scene being written: each row of statement_kinds() writes its statements here,
// the editing statements from `edits` (the scene's own, or those an editor keeps).
class SceneWriter {
 public:
  SceneWriter(const Scene& scene, const SceneEdits& edits)
      : scene_(scene), ast_(scene.ast()), edits_(edits) {}

  // The whole text: every row's statements in table order.
  std::string run();

  const Scene& scene() const { return scene_; }
  const SceneAst& ast() const { return ast_; }
  const SceneEdits& edits() const { return edits_; }
  std::ostream& out() { return out_; }

  // `v0 v1 ...` as written (expressions as `{expr ...}`).
  std::string values(const Value* v, int count) const;
  static std::string names(const std::vector<Name>& list);
  void face(const FaceDecl& f, const char* indent);
  void instance(const InstanceDecl& i, const char* indent);

 private:
  const Scene& scene_;
  const SceneAst& ast_;
  const SceneEdits& edits_;
  std::ostringstream out_;
};

}  // namespace nome::scene
