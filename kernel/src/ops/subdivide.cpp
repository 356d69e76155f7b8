#include "nome/ops/subdivide.hpp"

#include <string>
#include <utility>

#include "nome/error.hpp"
#include "ops/refinement_level.hpp"

namespace nome {
namespace {

std::vector<Index> sharp_edges(const Mesh& mesh) {
  std::vector<Index> sharp;
  for (Index e = 0; e < mesh.num_edges(); ++e)
    if (mesh.edge(e).is_sharp) sharp.push_back(e);
  return sharp;
}

// Boundary mode none: as in OpenSubdiv, every face with a border vertex is a hole. Empty when none is.
std::vector<bool> hole_faces(const Mesh& mesh, BoundaryMode boundary) {
  std::vector<bool> is_hole;
  if (boundary != BoundaryMode::none) return is_hole;
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    bool has_border_vertex = false;
    for (Index v : mesh.face_vertices(f)) has_border_vertex = has_border_vertex || mesh.is_boundary_vertex(v);
    if (has_border_vertex && is_hole.empty()) is_hole.resize(mesh.num_faces(), false);
    if (has_border_vertex) is_hole[f] = true;
  }
  return is_hole;
}

// The last level's faces whose base ancestor is not a hole, and the vertices they use, as a soup.
PolygonSoup without_holes(const Mesh& full, const std::vector<bool>& is_base_face_hole, unsigned shift,
                          const Mesh& base, std::span<const Index> kept_vertices) {
  std::vector<Index> new_index(full.num_vertices(), no_index);
  PolygonSoup soup;
  for (Index v : kept_vertices) new_index[v] = soup.add_vertex(full.position(v));
  std::vector<Index> face;
  for (Index f = 0; f < full.num_faces(); ++f) {
    const Index ancestor = base.corner_face(f >> shift);
    if (is_base_face_hole[ancestor]) continue;
    face.clear();
    for (Index v : full.face_vertices(f)) face.push_back(new_index[v]);
    soup.add_face(face);
    if (!full.face_colors().empty()) soup.face_colors.push_back(full.face_colors()[f]);
  }
  for (const Edge& e : full.edges())
    if (e.is_sharp && new_index[e.vertices[0]] != no_index && new_index[e.vertices[1]] != no_index)
      soup.sharp_edges.emplace_back(new_index[e.vertices[0]], new_index[e.vertices[1]]);
  return soup;
}

}  // namespace

Refinement::Refinement(const Mesh& base, int levels, BoundaryMode boundary, int threads)
    : base_vertices_(base.num_vertices()),
      base_faces_(base.num_faces()),
      base_corners_(base.num_corners()),
      base_edges_(base.num_edges()),
      base_sharp_edges_(sharp_edges(base)),
      boundary_(boundary),
      is_hole_(hole_faces(base, boundary)) {
  if (levels < 1)
    throw InvalidInputError("Refinement: levels must be at least 1, got " + std::to_string(levels));
  levels_.resize(size_t(levels));
  const MeshLevelView view(base);
  for (size_t k = 0; k < levels_.size(); ++k) {
    if (k >= 1 && k + 1 == levels_.size()) {
      if (k == 1)
        refine_grandchild_quads(view, levels_[k], threads);
      else
        refine_grandchild_quads(levels_[k - 2], levels_[k], threads);
      continue;
    }
    const LevelDetail detail = k + 1 == levels_.size()   ? LevelDetail::quads
                               : k + 2 == levels_.size() ? LevelDetail::counts
                                                         : LevelDetail::full;
    if (k == 0)
      refine_topology(view, levels_[0], detail, threads);
    else
      refine_topology(levels_[k - 1], levels_[k], detail, threads);
  }
  if (!is_hole_.empty()) find_kept_vertices(base);
}

void Refinement::find_kept_vertices(const Mesh& base) {
  const unsigned shift = 2 * unsigned(levels_.size() - 1);
  const auto quads = quad_vertices();
  std::vector<bool> is_used(num_vertices(), false);
  for (Index f = 0; f < num_faces(); ++f)
    if (!is_hole_[base.corner_face(f >> shift)])
      for (Index k = 0; k < 4; ++k) is_used[quads[4 * f + k]] = true;
  kept_vertices_.clear();
  for (Index v = 0; v < num_vertices(); ++v)
    if (is_used[v]) kept_vertices_.push_back(v);
}

Refinement::Refinement(Refinement&&) noexcept = default;
Refinement& Refinement::operator=(Refinement&&) noexcept = default;
Refinement::~Refinement() = default;

int Refinement::levels() const {
  return static_cast<int>(levels_.size());
}

bool Refinement::fits(const Mesh& base) const {
  return base.num_vertices() == base_vertices_ && base.num_faces() == base_faces_ &&
         base.num_corners() == base_corners_ && base.num_edges() == base_edges_ &&
         sharp_edges(base) == base_sharp_edges_;
}

Index Refinement::num_vertices() const {
  return levels_.back().vertex_count;
}
Index Refinement::num_faces() const {
  return levels_.back().num_faces();
}
std::span<const Index> Refinement::quad_vertices() const {
  return levels_.back().corner_vertices;
}

void Refinement::refine_positions(const Mesh& base, SubdivisionRule rule, std::span<Vec3> out, int threads) {
  if (!fits(base)) throw InvalidInputError("Refinement::refine_positions: the base mesh's topology changed");
  if (out.size() != num_vertices())
    throw InvalidInputError("Refinement::refine_positions: output holds " + std::to_string(out.size()) +
                            " positions, the last level has " + std::to_string(num_vertices()));
  std::span<const Vec3> in = base.positions();
  const VertexRules rules{rule, boundary_ == BoundaryMode::edge_and_corner};
  for (size_t k = 0; k < levels_.size(); ++k) {
    std::span<Vec3> target = out;
    if (k + 1 < levels_.size()) {
      levels_[k].positions.resize(levels_[k].vertex_count);
      target = levels_[k].positions;
    }
    if (k == 0)
      nome::refine_positions(MeshLevelView(base), in, rules, target, threads);
    else if (k == 1)
      refine_child_positions(MeshLevelView(base), in, rules, target, threads);
    else
      refine_child_positions(levels_[k - 2], in, rules, target, threads);
    in = target;
  }
}

std::span<const Vec3> Refinement::refine_positions(const Mesh& base, SubdivisionRule rule, int threads) {
  levels_.back().positions.resize(num_vertices());
  refine_positions(base, rule, levels_.back().positions, threads);
  return levels_.back().positions;
}

void Refinement::refine_positions(const Mesh& base, SubdivisionRule rule, Mesh& result, int threads) {
  if (is_hole_.empty()) return refine_positions(base, rule, result.positions(), threads);
  if (result.num_vertices() != kept_vertices_.size())
    throw InvalidInputError("Refinement::refine_positions: the result was not made by this refinement");
  const std::span<const Vec3> all = refine_positions(base, rule, threads);
  for (size_t i = 0; i < kept_vertices_.size(); ++i) result.positions()[i] = all[kept_vertices_[i]];
}

Mesh Refinement::mesh(const Mesh& base, Buffer<Vec3> positions, int threads) const {
  if (!fits(base)) throw InvalidInputError("Refinement::mesh: the base mesh's topology changed");
  if (positions.size() != num_vertices())
    throw InvalidInputError("Refinement::mesh: expected " + std::to_string(num_vertices()) + " positions");
  // The last two levels were built without edges and fans: build them again, in full.
  const size_t k = levels_.size();
  Level before_last, last;
  if (k == 1) {
    refine_topology(MeshLevelView(base), last, LevelDetail::full, threads);
  } else {
    if (k == 2)
      refine_topology(MeshLevelView(base), before_last, LevelDetail::full, threads);
    else
      refine_topology(levels_[k - 3], before_last, LevelDetail::full, threads);
    refine_topology(before_last, last, LevelDetail::full, threads);
    before_last = {};  // freed before the mesh's arrays are made
  }

  MeshArrays a;
  const Index nf = last.num_faces();
  a.positions = std::move(positions);
  a.face_offsets.resize(size_t(nf) + 1);
  for (Index f = 0; f <= nf; ++f) a.face_offsets[f] = 4 * f;
  a.edges.resize(last.num_edges());
  for (Index e = 0; e < last.num_edges(); ++e) {
    Edge& edge = a.edges[e];
    edge.vertices = last.edge_ends(e);
    edge.corners = last.edge_corners[e];
    edge.faces = {edge.corners[0] >> 2, edge.corners[1] == no_index ? no_index : edge.corners[1] >> 2};
    edge.is_mobius = last.edge_flags[e] & mobius_flag;
    edge.is_sharp = last.edge_flags[e] & sharp_flag;
  }
  // Corner signs: +1 at the first corner of each fan, flipped across every Möbius edge after it.
  a.corner_signs.resize(last.corner_vertices.size());
  for (Index v = 0; v < last.num_vertices(); ++v) {
    const auto corners = last.vertex_corners(v);
    const auto edges = last.vertex_edges(v);
    signed char sign = 1;
    for (size_t i = 0; i < corners.size(); ++i) {
      if (i > 0 && (last.edge_flags[edges[i]] & mobius_flag)) sign = static_cast<signed char>(-sign);
      a.corner_signs[corners[i]] = sign;
    }
  }
  // The last level's own arrays become the mesh's.
  a.corner_vertices = std::move(last.corner_vertices);
  a.corner_edges = std::move(last.corner_edges);
  a.fan_corner_offsets = std::move(last.fan_corner_offsets);
  a.fan_corners = std::move(last.fan_corners);
  a.fan_edge_offsets = std::move(last.fan_edge_offsets);
  a.fan_edges = std::move(last.fan_edges);
  // A level-k face's level-1 ancestor is face >> 2(k-1), which is a base corner.
  const unsigned shift = 2 * unsigned(levels_.size() - 1);
  a.face_components.resize(nf);
  for (Index f = 0; f < nf; ++f) a.face_components[f] = base.face_component(base.corner_face(f >> shift));
  a.num_components = base.num_components();
  if (!base.face_colors().empty()) {
    a.face_colors.resize(nf);
    for (Index f = 0; f < nf; ++f) a.face_colors[f] = base.face_colors()[base.corner_face(f >> shift)];
  }
  if (is_hole_.empty()) return assemble_mesh(std::move(a));
  return build_mesh(without_holes(assemble_mesh(std::move(a)), is_hole_, shift, base, kept_vertices_));
}

Mesh subdivide(const Mesh& mesh, const SubdivisionOptions& options) {
  if (options.levels == 0) return mesh;
  Refinement refinement(mesh, options.levels, options.boundary);
  Buffer<Vec3> positions(refinement.num_vertices());
  refinement.refine_positions(mesh, options.rule, positions);
  return refinement.mesh(mesh, std::move(positions));
}

}  // namespace nome
