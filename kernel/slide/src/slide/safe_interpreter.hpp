#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "nome/slide/tcl_limits.hpp"

struct Tcl_Interp;
struct Tcl_Obj;

namespace nome::slide {

// What a failed Tcl evaluation says: Tcl's message and the line of the evaluated text where it stopped
// (1 for the first).
struct TclFailure {
  std::string message;
  int line = 1;
};

// A safe Tcl interpreter for one scene: a file's code runs with no exec, sockets, file writes or
// directory walks, and each evaluation stops with an error when it passes either of its `limits`. A Tcl
// interpreter belongs to the thread that made it: use it from that thread only.
class SafeInterpreter {
 public:
  SafeInterpreter();
  ~SafeInterpreter();
  SafeInterpreter(const SafeInterpreter&) = delete;
  SafeInterpreter& operator=(const SafeInterpreter&) = delete;

  // Evaluates a script at global level; its result, or the failure.
  bool eval(std::string_view script, std::string& result, TclFailure& failure);
  // The same for a cached script object (compiled once, for a value evaluated on every slider tick).
  bool eval(Tcl_Obj* script, std::string& result, TclFailure& failure);

  using Command = std::function<std::string(std::span<Tcl_Obj* const> args)>;
  // Adds a command; the function throws TclCommandError to fail with a message.
  void add_command(const std::string& name, Command command);

  Tcl_Interp* interp() const { return interp_; }

  TclLimits limits;

 private:
  void arm_limits();
  bool finish(int code, std::string& result, TclFailure& failure);

  Tcl_Interp* parent_ = nullptr;
  Tcl_Interp* interp_ = nullptr;
};

// Thrown by a command the host adds: Tcl sees an error with this message.
struct TclCommandError {
  std::string message;
};

// The text of a Tcl value.
std::string tcl_string(Tcl_Obj* obj);

}  // namespace nome::slide
