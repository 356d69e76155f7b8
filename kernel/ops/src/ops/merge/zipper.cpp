#include "nome/ops/zipper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nome/error.hpp"

namespace nome {
namespace {

// Fractions of arc length along a chain (by index when the chain has no length).
std::vector<double> arc_fractions(std::span<const Vec3> chain) {
  std::vector<double> t(chain.size(), 0.0);
  for (size_t i = 1; i < chain.size(); ++i) t[i] = t[i - 1] + glm::length(chain[i] - chain[i - 1]);
  const double total = t.empty() ? 0.0 : t.back();
  for (size_t i = 0; i < t.size(); ++i) t[i] = total > 0 ? t[i] / total : double(i) / double(t.size() - 1);
  return t;
}

enum class Step : unsigned char { none, quad, triangle_a, triangle_b };

}  // namespace

ZipperCost::ZipperCost(std::span<const Vec3> a, std::span<const Vec3> b, const ZipperOptions& options)
    : a_(a), b_(b), t_a_(arc_fractions(a)), t_b_(arc_fractions(b)), options_(options) {
  if (a.size() < 2 || b.size() < 2)
    throw InvalidInputError("ZipperCost: each chain needs at least two points");
  // Typical rung: the mean distance between points at the same index fraction of the two chains.
  const size_t samples = std::max(a.size(), b.size());
  double sum = 0.0;
  for (size_t k = 0; k < samples; ++k) {
    const size_t i = (k * (a.size() - 1) + (samples - 1) / 2) / (samples - 1);
    const size_t j = (k * (b.size() - 1) + (samples - 1) / 2) / (samples - 1);
    sum += glm::length(a[i] - b[j]);
  }
  typical_rung_ = sum / double(samples);
  if (!(typical_rung_ > 0)) typical_rung_ = 1.0;  // coincident chains: only the counts matter
}

double ZipperCost::step(Index i, Index j, bool is_triangle) const {
  const double rung = glm::length(a_[i] - b_[j]);
  const double skew = options_.skew_weight * typical_rung_ * std::abs(t_a_[i] - t_b_[j]);
  return rung + skew + (is_triangle ? (options_.triangle_penalty - 1.0) * typical_rung_ : 0.0);
}

ZipperStrip zipper_strip(std::span<const Vec3> a, std::span<const Vec3> b, const ZipperOptions& options) {
  const ZipperCost model(a, b, options);
  const Index m = model.last_a(), n = model.last_b();
  const size_t width = size_t(n) + 1;
  std::vector<double> cost((size_t(m) + 1) * width, std::numeric_limits<double>::infinity());
  std::vector<Step> from(cost.size(), Step::none);
  cost[0] = 0.0;
  // phase: cheapest path to every rung; ties prefer quads, then steps along A.
  for (Index i = 0; i <= m; ++i) {
    for (Index j = 0; j <= n; ++j) {
      if (i == 0 && j == 0) continue;
      double& best = cost[i * width + j];
      if (i > 0 && j > 0) {
        const double c = cost[(i - 1) * width + j - 1] + model.step(i, j, false);
        if (c < best) best = c, from[i * width + j] = Step::quad;
      }
      if (i > 0) {
        const double c = cost[(i - 1) * width + j] + model.step(i, j, true);
        if (c < best) best = c, from[i * width + j] = Step::triangle_a;
      }
      if (j > 0) {
        const double c = cost[i * width + j - 1] + model.step(i, j, true);
        if (c < best) best = c, from[i * width + j] = Step::triangle_b;
      }
    }
  }

  // phase: walk back from (m, n), then emit the faces in chain order.
  std::vector<Step> steps;
  for (Index i = m, j = n; i > 0 || j > 0;) {
    const Step s = from[i * width + j];
    steps.push_back(s);
    if (s != Step::triangle_b) --i;
    if (s != Step::triangle_a) --j;
  }
  std::reverse(steps.begin(), steps.end());
  ZipperStrip strip;
  strip.cost = cost.back();
  const Index b0 = m + 1;
  Index i = 0, j = 0;
  for (Step s : steps) {
    if (s == Step::quad) {
      strip.face_vertices.insert(strip.face_vertices.end(), {i, i + 1, b0 + j + 1, b0 + j});
      ++i, ++j, ++strip.quads;
    } else if (s == Step::triangle_a) {
      strip.face_vertices.insert(strip.face_vertices.end(), {i, i + 1, b0 + j});
      ++i, ++strip.triangles;
    } else {
      strip.face_vertices.insert(strip.face_vertices.end(), {i, b0 + j + 1, b0 + j});
      ++j, ++strip.triangles;
    }
    strip.face_offsets.push_back(Index(strip.face_vertices.size()));
  }
  return strip;
}

std::vector<Index> border_chain(const Mesh& mesh, const BorderSelection& selection) {
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l) {
    const auto loop = mesh.loop_vertices(l);
    const auto at = std::find(loop.begin(), loop.end(), selection.start);
    if (at == loop.end()) continue;
    const size_t size = loop.size(), first = size_t(at - loop.begin());
    std::vector<Index> chain{selection.start};
    for (size_t k = 1; k <= size; ++k) {
      const Index v = loop[selection.backwards ? (first + size - k) % size : (first + k) % size];
      chain.push_back(v);
      if (v == selection.end) return chain;
    }
    throw InvalidInputError("border_chain: vertex " + mesh.vertex_label(selection.end) +
                            " is not on the border of " + mesh.vertex_label(selection.start));
  }
  throw InvalidInputError("border_chain: vertex " +
                          (selection.start < mesh.num_vertices() ? mesh.vertex_label(selection.start)
                                                                 : std::to_string(selection.start)) +
                          " is not on a border");
}

Index chains_overlap(std::span<const Index> chain_a, std::span<const Index> chain_b) {
  std::vector<Index> inner_a(chain_a.begin() + 1, chain_a.end() - 1);
  std::sort(inner_a.begin(), inner_a.end());
  for (size_t k = 0; k < chain_b.size(); ++k) {
    const bool shared_end = (k == 0 || k + 1 == chain_b.size()) &&
                            (chain_b[k] == chain_a.front() || chain_b[k] == chain_a.back());
    if (std::binary_search(inner_a.begin(), inner_a.end(), chain_b[k]) ||
        (!shared_end && (chain_b[k] == chain_a.front() || chain_b[k] == chain_a.back())))
      return chain_b[k];
  }
  return no_index;
}

ZipperFaces zipper_chains(std::span<const Vec3> positions, std::span<const Index> chain_a,
                          std::span<const Index> chain_b, const ZipperOptions& options) {
  if (chain_a.size() < 2 || chain_b.size() < 2)
    throw InvalidInputError("zipper_chains: a chain needs two vertices at least");
  const bool a_closed = chain_a.front() == chain_a.back(), b_closed = chain_b.front() == chain_b.back();
  if (a_closed != b_closed)
    throw InvalidInputError("zipper_chains: zip a whole loop with a whole loop, or a segment with a segment");
  if (const Index v = chains_overlap(chain_a, chain_b); v != no_index)
    throw InvalidInputError("zipper_chains: the two chains overlap at vertex " + std::to_string(v));
  std::vector<Vec3> points_a, points_b;
  for (Index v : chain_a) points_a.push_back(positions[v]);
  for (Index v : chain_b) points_b.push_back(positions[v]);
  const ZipperStrip strip = zipper_strip(points_a, points_b, options);
  ZipperFaces out;
  out.cost = strip.cost;
  for (Index f = 0; f < strip.num_faces(); ++f) {
    std::vector<Index> face;
    for (Index c = strip.face_offsets[f]; c < strip.face_offsets[f + 1]; ++c) {
      const Index k = strip.face_vertices[c];
      const Index v = k < chain_a.size() ? chain_a[k] : chain_b[k - chain_a.size()];
      if (face.empty() || face.back() != v) face.push_back(v);
    }
    // Where the chains share an end vertex the first or last face loses a corner.
    if (face.size() > 1 && face.front() == face.back()) face.pop_back();
    if (face.size() < 3) continue;
    ++(face.size() == 3 ? out.triangles : out.quads);
    out.faces.push_back(std::move(face));
  }
  return out;
}

ZipperFaces zipper_borders(const Mesh& mesh, const BorderSelection& a, const BorderSelection& b,
                           const ZipperOptions& options) {
  const std::vector<Index> chain_a = border_chain(mesh, a), chain_b = border_chain(mesh, b);
  if ((a.start == a.end) != (b.start == b.end))
    throw InvalidInputError(
        "zipper_borders: zip a whole border with a whole border, or a segment with a segment");
  if (const Index v = chains_overlap(chain_a, chain_b); v != no_index)
    throw InvalidInputError("zipper_borders: the two borders overlap at " + mesh.vertex_label(v));
  ZipperFaces out =
      zipper_chains(std::span(mesh.positions().data(), mesh.positions().size()), chain_a, chain_b, options);
  // The strip runs along A forwards; it agrees with A's faces where they run along A backwards.
  int agree = 0;
  for (size_t k = 0; k + 1 < chain_a.size(); ++k)
    for (Index e : mesh.vertex_edges(chain_a[k]))
      if (mesh.edge(e).is_boundary() && mesh.edge(e).other_vertex(chain_a[k]) == chain_a[k + 1])
        agree += mesh.edge(e).vertices[0] == chain_a[k] ? -1 : 1;
  if (agree < 0)
    for (auto& face : out.faces) std::reverse(face.begin(), face.end());
  return out;
}

}  // namespace nome
