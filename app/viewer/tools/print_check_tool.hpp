#pragma once

#include <string>
#include <vector>

#include "viewer/tools/print_check_job.hpp"
#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// The print check in the viewer: its actions (check now, frame the next place), its section (the check's
// button and settings, its verdict and counts, the worst places to frame), and its findings painted on
// the shown stage with a cube at each place.
class PrintCheckTool final : public Tool {
 public:
  std::string title() const override { return "Print check"; }
  void bind(ToolContext& context) override;
  void update(ToolContext& context) override;
  void draw_section(ToolContext& context) override;
  std::vector<FacePaint> face_paints(const ToolContext& context) const override;
  std::vector<render::CubeMarker> markers() const override { return job_.markers(); }
  bool is_busy() const override { return job_.is_busy(); }
  bool is_animating() const override { return job_.is_busy(); }

  const PrintCheckView& job() const { return job_; }

 private:
  PrintCheckView job_;
};

}  // namespace nome::viewer
