#include "cli/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace nome::cli {
namespace {

// How long a task runs before its bar shows: NOME_PROGRESS_AFTER_MS, half a second when unset.
std::chrono::milliseconds bar_show_after() {
  const char* text = std::getenv("NOME_PROGRESS_AFTER_MS");
  return std::chrono::milliseconds(text ? std::max(0L, std::strtol(text, nullptr, 10)) : 500L);
}
constexpr auto bar_redraw_every = std::chrono::milliseconds(100);
constexpr int bar_columns = 30;

}  // namespace

ProgressBar::ProgressBar(bool quiet)
    : enabled_(!quiet && isatty(STDERR_FILENO) == 1), show_after_(bar_show_after()) {}

ProgressBar::~ProgressBar() {
  finish();
}

Progress ProgressBar::sink() {
  if (!enabled_) return {};
  return {[this](std::string_view task, double fraction) { draw(task, fraction); }};
}

void ProgressBar::draw(std::string_view task, double fraction) {
  const auto now = std::chrono::steady_clock::now();
  if (task != task_) {
    task_ = task;
    task_start_ = now;
  }
  if (now - task_start_ < show_after_ || (drawn_ && now - last_draw_ < bar_redraw_every && fraction < 1.0))
    return;
  last_draw_ = now;
  drawn_ = true;
  const int filled = int(std::clamp(fraction, 0.0, 1.0) * bar_columns);
  std::fprintf(stderr, "\r\033[Knome: %-24.*s [%s%s] %3d%%", int(task.size()), task.data(),
               std::string(std::size_t(filled), '#').c_str(),
               std::string(std::size_t(bar_columns - filled), ' ').c_str(), int(fraction * 100.0));
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
  task_.clear();
}

}  // namespace nome::cli
