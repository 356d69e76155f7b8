#pragma once

#include <chrono>

namespace nome::slide {

// What a scene's Tcl may spend on one evaluation (a `tclinit` block, a value) before it is stopped with a
// located error: a runaway loop must not freeze the viewer. Both are needed: a command limit alone never
// stops `while 1 {}`, whose empty body runs no command.
struct TclLimits {
  std::chrono::milliseconds time{5000};
  long commands = 50'000'000;
};

}  // namespace nome::slide
