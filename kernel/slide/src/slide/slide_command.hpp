#pragma once

#include <functional>
#include <span>
#include <string>

#include "nome/scene/ast.hpp"
#include "slide/safe_interpreter.hpp"

namespace nome::slide {

// SLIDE's `slide` command while a scene's `tclinit` blocks run: `slide create point|face|object|group|
// instance ...` adds the statement to the scene being read, `slide delete point|face|object|group NAME`
// takes one out (with the instances of a deleted object or group), as SLIDE's scene editing did before the
// first picture. A coordinate written as a list starting with `expr` stays a value Tcl computes again when
// its sliders move: `add_value` registers its text and gives its expression node.
class SlideCommand {
 public:
  SlideCommand(scene::SceneAst& ast, scene::SourceLocation at,
               std::function<scene::ExprId(std::string text, scene::SourceLocation at)> add_value);

  std::string run(std::span<Tcl_Obj* const> args);

 private:
  std::string create(const std::string& type, std::span<Tcl_Obj* const> args);
  std::string remove(const std::string& type, const std::string& name);
  scene::Value coordinate(Tcl_Obj* element);
  std::vector<scene::TransformDecl> transforms(const std::string& xforms);
  scene::Name name(const std::string& text) const { return {text, at_}; }

  scene::SceneAst& ast_;
  scene::SourceLocation at_;  // the block being run: where the statements it makes are said to stand
  std::function<scene::ExprId(std::string, scene::SourceLocation)> add_value_;
};

}  // namespace nome::slide
