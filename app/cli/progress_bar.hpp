#pragma once

#include <chrono>
#include <string>

#include "nome/progress.hpp"

namespace nome::cli {

// A progress bar on stderr for long kernel work: drawn only when stderr is a terminal and the user did not
// ask for --quiet, and only once a task has run for half a second (quick work stays silent;
// NOME_PROGRESS_AFTER_MS sets another delay). The line is
// cleared when the work ends, so nothing of it stays in the terminal's scrollback.
class ProgressBar {
 public:
  explicit ProgressBar(bool quiet);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // The sink to hand to the kernel (valid while this bar lives).
  Progress sink();
  // Clears the bar's line if it was drawn.
  void finish();

 private:
  void draw(std::string_view task, double fraction);

  bool enabled_;
  bool drawn_ = false;
  std::string task_;
  std::chrono::milliseconds show_after_;
  std::chrono::steady_clock::time_point task_start_, last_draw_;
};

}  // namespace nome::cli
