#include "slide/tk_stand_in.hpp"

#include <algorithm>

#include <tcl.h>

namespace nome::slide {
namespace {

constexpr const char* widget_types[] = {"scale",   "checkbutton", "radiobutton", "button",     "toplevel",
                                        "frame",   "label",       "entry",       "canvas",     "listbox",
                                        "message", "text",        "scrollbar",   "menubutton", "menu",
                                        "spinbox", "labelframe",  "panedwindow"};
// Layout, window-manager and event commands: nothing to do without a display.
constexpr const char* ignored_commands[] = {"pack",  "grid",  "place",  "wm",   "update",        "bind",
                                            "focus", "raise", "lower",  "bell", "tk_setPalette", "option",
                                            "image", "font",  "tkwait", "grab", "selection",     "clipboard"};

bool variable_exists(Tcl_Interp* interp, const std::string& name) {
  return Tcl_GetVar2(interp, name.c_str(), nullptr, TCL_GLOBAL_ONLY) != nullptr;
}

void set_variable(Tcl_Interp* interp, const std::string& name, const std::string& value) {
  Tcl_SetVar2(interp, name.c_str(), nullptr, value.c_str(), TCL_GLOBAL_ONLY);
}

}  // namespace

std::string TkWidget::option(const std::string& name, const std::string& fallback) const {
  for (auto it = options.rbegin(); it != options.rend(); ++it)
    if (it->first == name) return it->second;
  return fallback;
}

TkStandIn::TkStandIn(SafeInterpreter& interpreter) : interpreter_(interpreter) {
  for (const char* type : widget_types)
    interpreter_.add_command(type,
                             [this, type](std::span<Tcl_Obj* const> args) { return create(type, args); });
  for (const char* name : ignored_commands)
    interpreter_.add_command(name, [](std::span<Tcl_Obj* const>) { return std::string(); });
  // `winfo exists .w` and the like: there is no window.
  interpreter_.add_command("winfo", [](std::span<Tcl_Obj* const>) { return std::string("0"); });
  interpreter_.add_command("destroy", [](std::span<Tcl_Obj* const>) { return std::string(); });
}

std::string TkStandIn::create(const std::string& type, std::span<Tcl_Obj* const> args) {
  if (args.size() < 2)
    throw TclCommandError{"wrong # args: should be \"" + type + " pathName ?-option value ...?\""};
  TkWidget widget{type, tcl_string(args[1]), {}, running_block};
  for (std::size_t i = 2; i + 1 < args.size(); i += 2) {
    std::string name = tcl_string(args[i]);
    if (name.starts_with('-')) name.erase(0, 1);
    widget.options.emplace_back(name, tcl_string(args[i + 1]));
  }
  // Tk accepts unambiguous abbreviations; SLIDE's library writes -var for -variable.
  for (auto& [name, value] : widget.options)
    if (name == "var") name = "variable";
  Tcl_Interp* interp = interpreter_.interp();
  const std::string variable = widget.option("variable");
  if (!variable.empty() && !variable_exists(interp, variable)) {
    if (type == "scale") set_variable(interp, variable, widget.option("from", "0"));
    if (type == "checkbutton") set_variable(interp, variable, widget.option("offvalue", "0"));
  }
  const std::size_t index = widgets_.size();
  widgets_.push_back(std::move(widget));
  interpreter_.add_command(widgets_[index].path,
                           [this, index](std::span<Tcl_Obj* const> a) { return widget_command(index, a); });
  return widgets_[index].path;
}

// `$w set 5`, `$w get`, `$w configure -opt v`, `$w cget -opt`, `$w invoke`: the few the files send.
std::string TkStandIn::widget_command(std::size_t index, std::span<Tcl_Obj* const> args) {
  TkWidget& widget = widgets_[index];
  const std::string verb = args.size() > 1 ? tcl_string(args[1]) : "";
  Tcl_Interp* interp = interpreter_.interp();
  const std::string variable = widget.option("variable");
  if (verb == "set" && args.size() > 2 && !variable.empty()) {
    set_variable(interp, variable, tcl_string(args[2]));
  } else if (verb == "get" && !variable.empty()) {
    const char* value = Tcl_GetVar2(interp, variable.c_str(), nullptr, TCL_GLOBAL_ONLY);
    return value ? value : "";
  } else if (verb == "configure") {
    for (std::size_t i = 2; i + 1 < args.size(); i += 2) {
      std::string name = tcl_string(args[i]);
      if (name.starts_with('-')) name.erase(0, 1);
      widget.options.emplace_back(name, tcl_string(args[i + 1]));
    }
  } else if (verb == "cget" && args.size() > 2) {
    std::string name = tcl_string(args[2]);
    if (name.starts_with('-')) name.erase(0, 1);
    return widget.option(name);
  }
  return {};
}

std::string TkStandIn::toplevel_of(const std::string& path) const {
  std::string best;
  for (const TkWidget& w : widgets_)
    if (w.type == "toplevel" && (path == w.path || path.starts_with(w.path + ".")) &&
        w.path.size() > best.size())
      best = w.path;
  return best;
}

}  // namespace nome::slide
