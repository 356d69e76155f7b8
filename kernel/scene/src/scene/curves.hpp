#pragma once

#include <vector>

#include <glm/vec2.hpp>

#include "nome/scene/statement_kinds.hpp"
#include "scene/definition_context.hpp"

namespace nome::scene {

// One point of a sampled curve, with what a control point adds there (blended between control points
// along a B-spline or Bézier curve; a cross-section lands on the nearest sample).
struct CurvePoint {
  Vec3 position{0.0};
  glm::dvec2 scale{1.0, 1.0};
  Vec3 rotate{0.0};
  const Name* section = nullptr;
  bool is_reversing = false;
};

// A curve as a sweep reads it: its points in order, closed when the last joins the first (given as
// `closed` / `isloop`, or by ending where it starts; the repeated point is then dropped).
struct SampledCurve {
  std::vector<CurvePoint> points;
  bool is_closed = false;
};

// The named curve's samples; throws EvaluationError at `name` when it is not a curve.
SampledCurve sample_curve(DefinitionContext& context, const Name& name);
// A point or control point by name, with its control values.
CurvePoint curve_point(DefinitionContext& context, const Name& name);
// Drops a last point that repeats the first, marking the curve closed.
void close_if_repeated(SampledCurve& curve);
// The curve's samples as the piece's named vertices `prefix`0.. and one rim line through them.
void add_curve_rim(Piece& piece, const SampledCurve& curve, const char* prefix);

}  // namespace nome::scene
