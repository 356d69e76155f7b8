#pragma once

#include <algorithm>

#include <glm/gtc/constants.hpp>

namespace nome::viewer {

// The viewer's turntable (T): while on, the view turns about the vertical axis at a steady speed, one
// turn in seconds_per_turn whatever the frame rate, as `nome render --turntable` does in frames.
class TurntableMode {
 public:
  static constexpr double seconds_per_turn = 12.0;

  bool is_on() const { return is_on_; }
  void toggle(double now) {
    is_on_ = !is_on_;
    last_ = now;
  }
  // The angle in radians to turn by since the last call (0 while off).
  double advance(double now) {
    if (!is_on_) return 0.0;
    const double seconds = std::max(0.0, now - last_);
    last_ = now;
    return glm::two_pi<double>() * seconds / seconds_per_turn;
  }

 private:
  bool is_on_ = false;
  double last_ = 0.0;
};

}  // namespace nome::viewer
