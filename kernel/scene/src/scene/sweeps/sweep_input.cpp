// A sweep statement's curves read into what sweep() takes.
#include <string>
#include <unordered_map>

#include "scene/curves.hpp"
#include "scene/sweeps/sweep_syntax.hpp"

namespace nome::scene {
namespace {

// A curve as a cross-section: its points' x and y (JIPCAD draws cross-sections in the plane z = 0).
CrossSection section_of(DefinitionContext& context, const Name& name) {
  const SampledCurve curve = sample_curve(context, name);
  CrossSection section{{}, curve.is_closed};
  for (const CurvePoint& p : curve.points) section.points.emplace_back(p.position.x, p.position.y);
  return section;
}

CrossSection blend(const CrossSection& a, const CrossSection& b, double w, const Name& at) {
  if (a.points.size() != b.points.size())
    throw EvaluationError(at.location,
                          "sweepmorph '" + at.text +
                              "': cross-sections to blend need the same number of points, found " +
                              std::to_string(a.points.size()) + " and " + std::to_string(b.points.size()));
  CrossSection c{{}, a.is_closed};
  for (std::size_t j = 0; j < a.points.size(); ++j)
    c.points.push_back((1 - w) * a.points[j] + w * b.points[j]);
  return c;
}

// A sweepmorph's cross-section at every sample: those its control points give, blended linearly between
// them, the first before them and the last after.
void morph(SweepInput& in, const SweepDecl& decl) {
  std::vector<std::size_t> given;
  for (std::size_t i = 0; i < in.path.size(); ++i)
    if (in.path[i].section != no_index) given.push_back(i);
  if (given.empty())
    throw EvaluationError(decl.name.location, "sweepmorph '" + decl.name.text +
                                                  "': no control point of its path gives a cross-section");
  std::vector<CrossSection> sections;
  std::size_t k = 0;
  for (std::size_t i = 0; i < in.path.size(); ++i) {
    while (k + 1 < given.size() && given[k + 1] <= i) ++k;
    const CrossSection& a = in.sections[in.path[given[k]].section];
    if (i <= given.front() || k + 1 == given.size()) {
      sections.push_back(a);
    } else {
      const CrossSection& b = in.sections[in.path[given[k + 1]].section];
      sections.push_back(blend(a, b, double(i - given[k]) / double(given[k + 1] - given[k]), decl.name));
    }
  }
  for (std::size_t i = 0; i < in.path.size(); ++i) in.path[i].section = Index(i);
  in.sections = std::move(sections);
}

}  // namespace

SweepInput sweep_input(DefinitionContext& context, const SweepDecl& decl) {
  SweepInput in;
  const SampledCurve path = sample_curve(context, decl.path);
  SweepOptions& o = in.options;
  o.frames = decl.is_minimal_torsion ? FrameKind::minimal_torsion : FrameKind::frenet;
  o.azimuth = decl.azimuth ? context.number(*decl.azimuth) : 0;
  o.twist = decl.twist ? context.number(*decl.twist) : 0;
  o.is_path_closed = path.is_closed;
  o.is_reversed = decl.is_reversed;
  o.has_begin_cap = decl.has_begin_cap;
  o.has_end_cap = decl.has_end_cap;
  o.is_cut_begin = decl.is_cut_begin;
  o.is_cut_end = decl.is_cut_end;
  o.faces = decl.is_triangles ? FaceShape::triangles : FaceShape::quadrilaterals;
  std::unordered_map<std::string, Index> index_of;
  const auto section_index = [&](const Name& name) {
    const auto [it, is_new] = index_of.emplace(name.text, Index(in.sections.size()));
    if (is_new) in.sections.push_back(section_of(context, name));
    return it->second;
  };
  const bool is_morph = !decl.cross_section;
  if (!is_morph) section_index(*decl.cross_section);
  for (const CurvePoint& p : path.points)
    in.path.push_back({p.position, p.scale, p.rotate,
                       p.section ? section_index(*p.section) : (is_morph ? no_index : Index(0)),
                       p.is_reversing});
  if (is_morph) morph(in, decl);
  return in;
}

}  // namespace nome::scene
