#include "slide/safe_interpreter.hpp"

#include <memory>
#include <mutex>

#include <tcl.h>

namespace nome::slide {
namespace {

int run_command(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  const auto& command = *static_cast<SafeInterpreter::Command*>(data);
  try {
    const std::string result = command(std::span<Tcl_Obj* const>(objv, size_t(objc)));
    Tcl_SetObjResult(interp, Tcl_NewStringObj(result.data(), int(result.size())));
    return TCL_OK;
  } catch (const TclCommandError& e) {
    Tcl_SetObjResult(interp, Tcl_NewStringObj(e.message.data(), int(e.message.size())));
    return TCL_ERROR;
  }
}

void delete_command(ClientData data) {
  delete static_cast<SafeInterpreter::Command*>(data);
}

}  // namespace

std::string tcl_string(Tcl_Obj* obj) {
  int length = 0;
  const char* text = Tcl_GetStringFromObj(obj, &length);
  return std::string(text, size_t(length));
}

SafeInterpreter::SafeInterpreter() {
  static std::once_flag initialised;
  std::call_once(initialised, [] { Tcl_FindExecutable(nullptr); });
  parent_ = Tcl_CreateInterp();
  interp_ = Tcl_CreateSlave(parent_, "scene", 1);
}

SafeInterpreter::~SafeInterpreter() {
  Tcl_DeleteInterp(parent_);
}

void SafeInterpreter::add_command(const std::string& name, Command command) {
  Tcl_CreateObjCommand(interp_, name.c_str(), run_command, new Command(std::move(command)), delete_command);
}

void SafeInterpreter::arm_limits() {
  Tcl_Time deadline;
  Tcl_GetTime(&deadline);
  const auto limit = std::chrono::duration_cast<std::chrono::microseconds>(limits.time).count();
  deadline.sec += long(limit / 1'000'000);
  deadline.usec += long(limit % 1'000'000);
  if (deadline.usec >= 1'000'000) {
    deadline.sec += 1;
    deadline.usec -= 1'000'000;
  }
  Tcl_LimitSetTime(interp_, &deadline);
  Tcl_LimitTypeSet(interp_, TCL_LIMIT_TIME);
  // The command count is the interpreter's total so far: the limit is that plus this evaluation's share.
  Tcl_LimitTypeReset(interp_, TCL_LIMIT_COMMANDS);
  Tcl_Eval(interp_, "info cmdcount");
  long count = 0;
  Tcl_GetLongFromObj(nullptr, Tcl_GetObjResult(interp_), &count);
  Tcl_LimitSetCommands(interp_, int(std::min<long>(count + limits.commands, 0x7fffffff)));
  Tcl_LimitTypeSet(interp_, TCL_LIMIT_COMMANDS);
}

bool SafeInterpreter::finish(int code, std::string& result, TclFailure& failure) {
  if (code == TCL_OK || code == TCL_RETURN) {
    result = tcl_string(Tcl_GetObjResult(interp_));
    return true;
  }
  failure.message = code == TCL_ERROR ? tcl_string(Tcl_GetObjResult(interp_))
                                      : "invoked \"break\" or \"continue\" outside of a loop";
  failure.line = Tcl_GetErrorLine(interp_);
  Tcl_ResetResult(interp_);
  return false;
}

bool SafeInterpreter::eval(std::string_view script, std::string& result, TclFailure& failure) {
  arm_limits();
  return finish(Tcl_EvalEx(interp_, script.data(), int(script.size()), TCL_EVAL_GLOBAL), result, failure);
}

bool SafeInterpreter::eval(Tcl_Obj* script, std::string& result, TclFailure& failure) {
  arm_limits();
  return finish(Tcl_EvalObjEx(interp_, script, TCL_EVAL_GLOBAL), result, failure);
}

}  // namespace nome::slide
