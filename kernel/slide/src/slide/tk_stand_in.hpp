#pragma once

#include <string>
#include <vector>

#include "nome/scene/diagnostic.hpp"
#include "slide/safe_interpreter.hpp"

namespace nome::slide {

// A Tk widget a file's Tcl made, with its options as given (`-from 1.0` is options "from" -> "1.0").
struct TkWidget {
  std::string type;  // scale, checkbutton, toplevel, ...
  std::string path;  // .slfWINDOW.star.n
  std::vector<std::pair<std::string, std::string>> options;
  scene::SourceLocation at;  // the `tclinit` block that made it

  // The option's value, or `fallback` when it was not given.
  std::string option(const std::string& name, const std::string& fallback = {}) const;
};

// Tk as SLIDE's files use it, without a display: every widget is recorded (the scales become the scene's
// sliders) and answers the widget commands the files send it; geometry managers, window-manager hints and
// event bindings do nothing. A widget bound to a variable sets it as Tk does: a scale to its `-from` value,
// a check button to its off value, when the variable does not exist yet.
class TkStandIn {
 public:
  explicit TkStandIn(SafeInterpreter& interpreter);

  const std::vector<TkWidget>& widgets() const { return widgets_; }
  // The path of the nearest toplevel holding `path` (itself included), or "" when none does.
  std::string toplevel_of(const std::string& path) const;

  scene::SourceLocation running_block;  // where the widgets being made are said to stand

 private:
  std::string create(const std::string& type, std::span<Tcl_Obj* const> args);
  std::string widget_command(std::size_t widget, std::span<Tcl_Obj* const> args);

  SafeInterpreter& interpreter_;
  std::vector<TkWidget> widgets_;
};

}  // namespace nome::slide
