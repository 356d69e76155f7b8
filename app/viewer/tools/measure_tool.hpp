#pragma once

#include <optional>
#include <string>

#include "nome/mesh/mesh.hpp"
#include "nome/query/screen_projection.hpp"
#include "nome/query/triangle_bvh.hpp"
#include "viewer/tools/tool.hpp"

namespace nome::viewer {

// What a click on the surface measures: nothing (it selects), the distance between two clicked points,
// or the wall of the solid under the click (query/wall_thickness).
enum class MeasureMode { off, distance, wall };

// A measured length between two surface points.
struct Measurement {
  Vec3 from{0.0};
  Vec3 to{0.0};
  double length = 0.0;
  bool is_wall = false;
};

// The viewer's measuring (M: distance, Shift+M: wall thickness): clicks cast the picking ray at the shown
// stage; the result is logged, listed in the Measure section and drawn over the view, in mm (the export
// unit).
class MeasureTool final : public Tool {
 public:
  std::string title() const override { return "Measure"; }
  void bind(ToolContext& context) override;
  bool click(ToolContext& context, glm::dvec2 pixel) override;
  void draw_section(ToolContext&) override { draw_section(); }
  void draw_overlay(ToolContext& context) override;

  MeasureMode mode() const { return mode_; }
  // Switches to `mode`, or off when it is on already; forgets a half-made distance.
  void toggle(MeasureMode mode);
  // A click whose ray is `ray`: returns the log line.
  std::string click(const Mesh& shown, const TriangleBvh& bvh, const Ray& ray);
  const std::optional<Measurement>& last() const { return last_; }
  const std::optional<Vec3>& first_point() const { return first_; }
  // The last measurement (or the pending first point) over the view, as a line with its length.
  void draw_overlay(const ScreenProjection& projection) const;
  // The Measure section of the sidebar: the modes and the last result.
  void draw_section();

 private:
  MeasureMode mode_ = MeasureMode::off;
  std::optional<Vec3> first_;
  std::optional<Measurement> last_;
};

// "12.5 mm".
std::string measure_length_text(double length);

}  // namespace nome::viewer
