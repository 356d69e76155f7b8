// A cross-section swept along a sampled path: each sample's section placed in its frame, bands of faces
// between consecutive sections, caps, and a closed path's join by position.
#include "nome/scene/sweep.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "nome/error.hpp"
#include "scene/sweep_geometry.hpp"

namespace nome::scene {
namespace {

constexpr double degrees = std::numbers::pi / 180;

// The samples' turn of the cross-section and whether its order is reversed there.
struct SampleTurns {
  std::vector<double> angle;  // radians, from N towards B
  std::vector<unsigned char> is_reversed;
};

SampleTurns sample_turns(std::span<const PathSample> path, const SweepOptions& o, double holonomy) {
  const std::size_t n = path.size();
  // The twist reaches its full amount at the last sample, or back at the first on a closed path.
  const double steps = double(o.is_path_closed ? n : n - 1);
  SampleTurns turns{std::vector<double>(n + 1), std::vector<unsigned char>(n + 1)};
  bool is_reversed = o.is_reversed;
  bool is_turn_reversed = false;  // a control point's `reverse` turns the section the other way after it
  for (std::size_t i = 0; i <= n; ++i) {
    const bool is_virtual = i == n;  // a closed path's first sample, reached again
    if (!is_virtual && path[i].is_reversing) {
      is_reversed = !is_reversed;
      is_turn_reversed = !is_turn_reversed;
    }
    const double sense = is_turn_reversed ? -1 : 1;
    const double own = is_virtual ? path[0].rotate.z : path[i].rotate.z;
    turns.angle[i] =
        (sense * (o.azimuth + own + o.twist * double(i) / steps) - holonomy * double(i) / steps) * degrees;
    turns.is_reversed[i] = is_reversed;
  }
  return turns;
}

// Where point j of the sample's cross-section lands.
Vec3 place(const CrossSection& section, std::size_t j, bool is_reversed, const PathSample& sample,
           const Frame& frame, double angle, const Vec3& bend, double stretch) {
  const std::size_t m = section.points.size();
  const glm::dvec2 p = section.points[is_reversed ? m - 1 - j : j] * sample.scale;
  const double c = std::cos(angle), s = std::sin(angle);
  Vec3 local(p.x * c - p.y * s, p.x * s + p.y * c, 0.0);
  // A control point's tilt: about N by rx, then about B by ry.
  if (sample.rotate.x != 0 || sample.rotate.y != 0) {
    const double a = sample.rotate.x * degrees, b = sample.rotate.y * degrees;
    local = Vec3(local.x, local.y * std::cos(a) - local.z * std::sin(a),
                 local.y * std::sin(a) + local.z * std::cos(a));
    local = Vec3(local.x * std::cos(b) + local.z * std::sin(b), local.y,
                 -local.x * std::sin(b) + local.z * std::cos(b));
  }
  Vec3 q = local.x * frame.normal + local.y * frame.binormal + local.z * frame.tangent;
  q += (stretch - 1) * glm::dot(q, bend) * bend;
  return sample.position + q;
}

// The correspondence of a closed path's end to its start: `to[j]` is the start's point that the end's
// point j meets, the one of all cyclic shifts and reversals (for an open section: identity and reversal)
// that lies nearest. Returns the largest distance of a matched pair.
double nearest_correspondence(std::span<const Vec3> end, std::span<const Vec3> start, bool is_closed,
                              std::vector<Index>& to) {
  const std::size_t m = end.size();
  double best = 1e300, best_worst = 0;
  const std::size_t shifts = is_closed ? m : 1;
  std::vector<Index> candidate(m);
  for (const bool is_mirrored : {false, true})
    for (std::size_t k = 0; k < shifts; ++k) {
      double sum = 0, worst = 0;
      for (std::size_t j = 0; j < m; ++j) {
        const std::size_t target =
            is_closed ? (is_mirrored ? (k + m - j) % m : (k + j) % m) : (is_mirrored ? m - 1 - j : j);
        candidate[j] = Index(target);
        const double d = glm::length(end[j] - start[target]);
        sum += d * d;
        worst = std::max(worst, d);
      }
      if (sum < best) {
        best = sum;
        best_worst = worst;
        to = candidate;
      }
    }
  return best_worst;
}

std::string vertex_name(std::size_t i, std::size_t j) {
  return "v" + std::to_string(i) + "_" + std::to_string(j);
}

void add_band_face(Piece& piece, const std::array<Index, 4>& quad, std::size_t i, std::size_t j,
                   FaceShape shape) {
  const std::string name = "f" + std::to_string(i) + "_" + std::to_string(j);
  if (shape == FaceShape::quadrilaterals) {
    piece.add_face(quad, name);
    return;
  }
  piece.add_face(std::array<Index, 3>{quad[0], quad[1], quad[2]}, name + "a");
  piece.add_face(std::array<Index, 3>{quad[0], quad[2], quad[3]}, name + "b");
}

void check_input(std::span<const PathSample> path, std::span<const CrossSection> sections,
                 const SweepOptions& o) {
  const std::size_t cut = std::size_t(o.is_cut_begin) + std::size_t(o.is_cut_end);
  if (o.is_path_closed && cut > 0) throw InvalidInputError("sweep: cutbegin and cutend need an open path");
  if (path.size() < (o.is_path_closed ? 3u : 2u + cut))
    throw InvalidInputError("sweep: the path needs at least 2 drawn samples (3 when closed)");
  if (sections.empty() || sections[0].points.empty())
    throw InvalidInputError("sweep: an empty cross-section");
  for (const PathSample& s : path) {
    if (s.section >= sections.size()) throw InvalidInputError("sweep: a sample names no cross-section");
    const CrossSection& c = sections[s.section];
    if (c.points.size() != sections[0].points.size() || c.is_closed != sections[0].is_closed)
      throw InvalidInputError(
          "sweep: the cross-sections along a path must have the same number of points "
          "and be all closed or all open");
  }
}

}  // namespace

SweepResult sweep(std::span<const PathSample> path, std::span<const CrossSection> sections,
                  const SweepOptions& o) {
  check_input(path, sections, o);
  const std::size_t n = path.size(), m = sections[0].points.size();
  std::vector<Vec3> points(n);
  for (std::size_t i = 0; i < n; ++i) points[i] = path[i].position;
  const PathShape shape = path_shape(points, o.is_path_closed);
  const std::vector<Frame> frames = frames_of(points, shape, o.is_path_closed, o.frames);
  // Rotation-minimising frames come back turned once around a closed path: spread that turn along it.
  double holonomy = 0;
  if (o.is_path_closed)
    holonomy = std::atan2(glm::dot(frames[n].normal, frames[0].binormal),
                          glm::dot(frames[n].normal, frames[0].normal)) /
               degrees;
  const SampleTurns turns = sample_turns(path, o, holonomy);
  const std::size_t first = o.is_cut_begin ? 1 : 0, last = o.is_cut_end ? n - 2 : n - 1;
  SweepResult result;
  Piece& piece = result.piece;
  piece.soup.positions.reserve((last - first + 1) * m);
  for (std::size_t i = first; i <= last; ++i)
    for (std::size_t j = 0; j < m; ++j)
      piece.add_vertex(place(sections[path[i].section], j, turns.is_reversed[i], path[i], frames[i],
                             turns.angle[i], shape.bend[i], shape.stretch[i]),
                       vertex_name(i, j));
  const auto vertex = [&](std::size_t i, std::size_t j) { return Index((i - first) * m + j); };
  if (m == 1) {
    RimLine rim{"", {}, o.is_path_closed};
    for (std::size_t i = first; i <= last; ++i) rim.vertices.push_back(vertex(i, 0));
    piece.rims.push_back(std::move(rim));
    return result;
  }
  const bool is_section_closed = sections[0].is_closed;
  const std::size_t around = is_section_closed ? m : m - 1;
  for (std::size_t i = first; i < last; ++i)
    for (std::size_t j = 0; j < around; ++j) {
      const std::size_t k = (j + 1) % m;
      add_band_face(piece, {vertex(i, j), vertex(i, k), vertex(i + 1, k), vertex(i + 1, j)}, i, j, o.faces);
    }
  if (o.is_path_closed) {
    // The first section placed once more at the end of the loop, to find which of its points meet.
    std::vector<Vec3> end(m), start(m);
    for (std::size_t j = 0; j < m; ++j) {
      end[j] = place(sections[path[0].section], j, turns.is_reversed[n], path[0], frames[n], turns.angle[n],
                     shape.bend[0], shape.stretch[0]);
      start[j] = piece.soup.positions[vertex(0, j)];
    }
    std::vector<Index> to;
    const double gap = nearest_correspondence(end, start, is_section_closed, to);
    double size = 0;
    for (const Vec3& p : start) size = std::max(size, glm::length(p - path[0].position));
    if (gap > 1e-6 * std::max(size, 1e-12))
      result.warnings.push_back(
          "a twist of " + std::to_string(o.twist) +
          " degrees is no symmetry of the cross-section: the path's end is joined to its "
          "start by the nearest match, points up to " +
          std::to_string(gap) + " apart");
    for (std::size_t j = 0; j < around; ++j) {
      const std::size_t k = (j + 1) % m;
      add_band_face(piece, {vertex(n - 1, j), vertex(n - 1, k), to[k], to[j]}, n - 1, j, o.faces);
    }
    return result;
  }
  // Caps close a closed section; on an open one (JIPCAD's files cap those too) they span its ends.
  if (m < 3) return result;
  std::vector<Index> cap(m);
  if (o.has_begin_cap) {
    for (std::size_t j = 0; j < m; ++j) cap[j] = vertex(first, m - 1 - j);
    piece.add_face(cap, "begincap");
  }
  if (o.has_end_cap) {
    for (std::size_t j = 0; j < m; ++j) cap[j] = vertex(last, j);
    piece.add_face(cap, "endcap");
  }
  return result;
}

}  // namespace nome::scene
