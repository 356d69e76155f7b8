#pragma once

#include <functional>
#include <string_view>

namespace nome {

// Where long kernel work says how far it got, since the kernel never prints: the command line draws a bar
// on a terminal, the viewer a percentage in its status bar, a test nothing. Called from the thread that
// started the work, with fractions rising from 0 to 1, a few hundred times per task at most.
struct Progress {
  std::function<void(std::string_view task, double fraction)> report;

  void operator()(std::string_view task, double fraction) const {
    if (report) report(task, fraction);
  }
};

}  // namespace nome
