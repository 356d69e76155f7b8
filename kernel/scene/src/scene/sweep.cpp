// A cross-section swept along a sampled path: each sample's section placed in its frame, bands of faces
// between consecutive sections, caps, and a closed path's join by position.
#include "nome/scene/sweep.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "nome/error.hpp"
#include "nome/scene/expression.hpp"
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

// Where point j of the sample's cross-section lands, turned by the angle whose cosine and sine are c, s.
Vec3 place(const CrossSection& section, std::size_t j, bool is_reversed, const PathSample& sample,
           const Frame& frame, double c, double s, const Vec3& bend, double stretch) {
  const std::size_t m = section.points.size();
  const glm::dvec2 p = section.points[is_reversed ? m - 1 - j : j] * sample.scale;
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

// One sweep being made: the path's shape, frames and turns, and the piece the sections go into.
class Sweeper {
 public:
  Sweeper(std::span<const PathSample> path, std::span<const CrossSection> sections, const SweepOptions& o)
      : path_(path), sections_(sections), o_(o), n_(path.size()), m_(sections[0].points.size()) {
    std::vector<Vec3> points(n_);
    for (std::size_t i = 0; i < n_; ++i) points[i] = path[i].position;
    shape_ = path_shape(points, o.is_path_closed);
    frames_ = frames_of(points, shape_, o.is_path_closed, o.frames);
    // Rotation-minimising frames come back turned once around a closed path: spread that turn along it.
    double holonomy = 0;
    if (o.is_path_closed)
      holonomy = std::atan2(glm::dot(frames_[n_].normal, frames_[0].binormal),
                            glm::dot(frames_[n_].normal, frames_[0].normal)) /
                 degrees;
    turns_ = sample_turns(path, o, holonomy);
    first_ = o.is_cut_begin ? 1 : 0;
    last_ = o.is_cut_end ? n_ - 2 : n_ - 1;
    around_ = sections[0].is_closed ? m_ : m_ - 1;
  }

  SweepPositions positions() {
    SweepPositions out;
    out.positions.resize((last_ - first_ + 1) * m_);  // every one written below
    for (std::size_t i = first_; i <= last_; ++i) place_ring(i, out.positions.data() + vertex(i, 0));
    std::vector<Index> to;
    if (o_.is_path_closed && m_ > 1) join_correspondence(out.positions, to);
    out.topology_key = topology_key(to);
    out.warnings = std::move(result_.warnings);
    return out;
  }

  SweepResult run() {
    reserve();
    PolygonSoup& soup = result_.piece.soup;
    soup.positions.resize((last_ - first_ + 1) * m_);  // every one written below
    for (std::size_t i = first_; i <= last_; ++i) place_ring(i, soup.positions.data() + vertex(i, 0));
    soup.vertex_names = Names::grid({'v', first_, m_}, soup.positions.size());
    if (m_ == 1) {
      RimLine rim{"", {}, o_.is_path_closed};
      for (std::size_t i = first_; i <= last_; ++i) rim.vertices.push_back(vertex(i, 0));
      result_.piece.rims.push_back(std::move(rim));
      result_.piece.topology_key = topology_key({});
      return std::move(result_);
    }
    // The bands' faces, written in place: they are most of the sweep's arrays.
    const std::size_t cells = (last_ - first_ + (o_.is_path_closed ? 1 : 0)) * around_;
    const bool is_triangles = o_.faces == FaceShape::triangles;
    soup.face_offsets.resize(cells * (is_triangles ? 2 : 1) + 1);
    soup.face_vertices.resize(cells * (is_triangles ? 6 : 4));
    for (std::size_t i = first_; i < last_; ++i)
      for (std::size_t j = 0; j < around_; ++j) {
        const std::size_t k = (j + 1) % m_;
        put_cell({vertex(i, j), vertex(i, k), vertex(i + 1, k), vertex(i + 1, j)});
      }
    std::vector<Index> to;
    if (o_.is_path_closed) join_ends(to);
    soup.face_names =
        Names::grid({'f', first_, around_,
                     is_triangles ? std::vector<std::string>{"a", "b"} : std::vector<std::string>{""}},
                    soup.num_faces());
    if (!o_.is_path_closed) add_caps();
    soup.grid = SoupGrid{Index(last_ - first_ + 1),
                         Index(m_),
                         sections_[0].is_closed,
                         is_triangles,
                         to,
                         !o_.is_path_closed && o_.has_begin_cap && m_ >= 3,
                         !o_.is_path_closed && o_.has_end_cap && m_ >= 3};
    result_.piece.topology_key = topology_key(to);
    return std::move(result_);
  }

 private:
  Index vertex(std::size_t i, std::size_t j) const { return Index((i - first_) * m_ + j); }
  // The points of sample i's section, placed, into out[0, m); sample n is a closed path's first sample
  // reached again.
  void place_ring(std::size_t i, Vec3* out) const {
    const double c = std::cos(turns_.angle[i]), s = std::sin(turns_.angle[i]);
    const std::size_t at = i % n_;
    const PathSample& sample = path_[at];
    const CrossSection& section = sections_[sample.section];
    for (std::size_t j = 0; j < m_; ++j)
      out[j] = place(section, j, turns_.is_reversed[i], sample, frames_[i], c, s, shape_.bend[at],
                     shape_.stretch[at]);
  }

  void reserve() {
    PolygonSoup& soup = result_.piece.soup;
    const std::size_t vertices = (last_ - first_ + 1) * m_;
    const std::size_t cells = (last_ - first_ + 1) * around_;
    const bool is_triangles = o_.faces == FaceShape::triangles;
    soup.positions.reserve(vertices);
    soup.face_vertices.reserve(cells * (is_triangles ? 6 : 4) + 2 * m_);  // and the caps
    soup.face_offsets.reserve(cells * (is_triangles ? 2 : 1) + 3);
  }

  // The next cell of a band, (i,j) (i,k) (i+1,k) (i+1,j): a quad or two triangles, into the arrays that run()
  // sized for them.
  void put_cell(const std::array<Index, 4>& quad) {
    if (o_.faces == FaceShape::quadrilaterals) {
      put_face(quad);
    } else {
      put_face(std::array<Index, 3>{quad[0], quad[1], quad[2]});
      put_face(std::array<Index, 3>{quad[0], quad[2], quad[3]});
    }
  }
  template <std::size_t N>
  void put_face(const std::array<Index, N>& face) {
    PolygonSoup& soup = result_.piece.soup;
    std::copy(face.begin(), face.end(), soup.face_vertices.begin() + corners_put_);
    corners_put_ += N;
    soup.face_offsets[++faces_put_] = Index(corners_put_);
  }

  // Which first-section point each point of a closed path's last section joins (warned about when no
  // symmetry of the cross-section makes the join exact).
  void join_correspondence(const Buffer<Vec3>& positions, std::vector<Index>& to) {
    std::vector<Vec3> end(m_), start(positions.begin() + vertex(0, 0), positions.begin() + vertex(0, 0) + m_);
    place_ring(n_, end.data());
    const double gap = nearest_correspondence(end, start, sections_[0].is_closed, to);
    double size = 0;
    for (const Vec3& p : start) size = std::max(size, glm::length(p - path_[0].position));
    if (gap > 1e-6 * std::max(size, 1e-12))
      result_.warnings.push_back("a twist of " + format_number(o_.twist) +
                                 " degrees is no symmetry of the cross-section: the path's end is joined to "
                                 "its start by the nearest match, points up to " +
                                 format_number(std::round(gap * 1e6) / 1e6) + " apart");
  }

  // Everything the faces and names depend on, hashed (FNV-1a): equal keys, equal faces and names.
  std::uint64_t topology_key(const std::vector<Index>& to) const {
    std::uint64_t h = 14695981039346656037ull;
    const auto mix = [&](std::uint64_t x) { h = (h ^ x) * 1099511628211ull; };
    for (std::size_t x : {n_, m_, first_, last_, around_}) mix(x);
    for (bool b : {o_.is_path_closed, o_.has_begin_cap, o_.has_end_cap, o_.faces == FaceShape::triangles})
      mix(b);
    for (Index t : to) mix(t);
    return h | 1;  // never 0, which means "no key"
  }

  // The last band of a closed path, to the first section by position.
  void join_ends(std::vector<Index>& to) {
    join_correspondence(result_.piece.soup.positions, to);
    for (std::size_t j = 0; j < around_; ++j) {
      const std::size_t k = (j + 1) % m_;
      put_cell({vertex(n_ - 1, j), vertex(n_ - 1, k), to[k], to[j]});
    }
  }

  // Caps close a closed section; on an open one (JIPCAD's files cap those too) they span its ends.
  void add_caps() {
    if (m_ < 3) return;
    PolygonSoup& soup = result_.piece.soup;
    std::vector<Index> cap(m_);
    if (o_.has_begin_cap) {
      for (std::size_t j = 0; j < m_; ++j) cap[j] = vertex(first_, m_ - 1 - j);
      soup.add_face(cap);
      soup.face_names.append(Names{"begincap"});
    }
    if (o_.has_end_cap) {
      for (std::size_t j = 0; j < m_; ++j) cap[j] = vertex(last_, j);
      soup.add_face(cap);
      soup.face_names.append(Names{"endcap"});
    }
  }

  std::span<const PathSample> path_;
  std::span<const CrossSection> sections_;
  const SweepOptions& o_;
  std::size_t n_, m_, first_ = 0, last_ = 0, around_ = 0;
  PathShape shape_;
  std::vector<Frame> frames_;
  SampleTurns turns_;
  SweepResult result_;
  std::size_t faces_put_ = 0, corners_put_ = 0;
};

}  // namespace

SweepResult sweep(std::span<const PathSample> path, std::span<const CrossSection> sections,
                  const SweepOptions& o) {
  check_input(path, sections, o);
  return Sweeper(path, sections, o).run();
}

SweepPositions sweep_positions(std::span<const PathSample> path, std::span<const CrossSection> sections,
                               const SweepOptions& o) {
  check_input(path, sections, o);
  return Sweeper(path, sections, o).positions();
}

}  // namespace nome::scene
