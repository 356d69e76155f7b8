#pragma once

#include <algorithm>

#include <glm/gtc/constants.hpp>

#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The viewer's turntable (T): while on, the view turns about the vertical axis at a steady speed, one
// turn in seconds_per_turn whatever the frame rate, as `nome render --turntable` does in frames.
class TurntableTool final : public Tool {
 public:
  void bind(ToolContext& context) override {
    context.actions.bind(Action::toggle_turntable, [this, &context] {
      toggle(context.platform.now());
      return true;
    });
  }
  void before_draw(ToolContext& context) override { context.view.turn(advance(context.platform.now())); }
  bool is_animating() const override { return is_on_; }

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
