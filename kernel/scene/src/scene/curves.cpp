// Curves as sweeps read them: any row with a `sample` function, its points resolved by name.
#include "scene/curves.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace nome::scene {

CurvePoint curve_point(DefinitionContext& context, const Name& name) {
  CurvePoint p;
  const std::optional<Vec3> at = context.position(name);
  if (!at) throw EvaluationError(name.location, "unknown point '" + name.text + "'");
  p.position = *at;
  if (const ControlPointDecl* c = context.control_point(name.text)) {
    p.scale = {context.number(c->scale[0]), context.number(c->scale[1])};
    p.rotate = {context.number(c->rotate[0]), context.number(c->rotate[1]), context.number(c->rotate[2])};
    p.section = c->cross_section ? &*c->cross_section : nullptr;
    p.is_reversing = c->is_reversing;
  }
  return p;
}

void close_if_repeated(SampledCurve& curve) {
  if (curve.points.size() < 3) return;
  double size = 0;
  for (const CurvePoint& p : curve.points)
    size = std::max(size, glm::length(p.position - curve.points[0].position));
  if (glm::length(curve.points.back().position - curve.points.front().position) > 1e-9 * std::max(size, 1.0))
    return;
  curve.points.pop_back();
  curve.is_closed = true;
}

SampledCurve sample_curve(DefinitionContext& context, const Name& name) {
  const auto d = context.definition(name.text);
  if (!d || !statement_kinds()[d->first].sample)
    throw EvaluationError(name.location,
                          "'" + name.text +
                              "' is no curve: a sweep's path and cross-section are a polyline, "
                              "circle, beziercurve or bspline");
  return statement_kinds()[d->first].sample(context, d->second);
}

void add_curve_rim(Piece& piece, const SampledCurve& curve, const char* prefix) {
  RimLine rim{"", {}, curve.is_closed};
  for (std::size_t i = 0; i < curve.points.size(); ++i)
    rim.vertices.push_back(piece.add_vertex(curve.points[i].position, prefix + std::to_string(i)));
  piece.rims.push_back(std::move(rim));
}

}  // namespace nome::scene
