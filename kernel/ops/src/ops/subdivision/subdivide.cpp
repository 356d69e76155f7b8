#include "nome/ops/subdivide.hpp"

#include <string>
#include <utility>

#include "nome/error.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "ops/subdivision/base_tiles.hpp"
#include "ops/subdivision/refinement_level.hpp"
#include "ops/subdivision/sharp_level.hpp"

namespace nome {
namespace {

std::vector<Index> sharp_edges(const Mesh& mesh) {
  std::vector<Index> sharp;
  for (Index e = 0; e < mesh.num_edges(); ++e)
    if (mesh.edge(e).is_sharp) sharp.push_back(e);
  return sharp;
}

// The faces marked as holes; empty when none is.
std::vector<bool> holes_of(const Mesh& mesh) {
  std::vector<bool> holes;
  if (!mesh.has_holes()) return holes;
  holes.resize(mesh.num_faces());
  for (Index f = 0; f < mesh.num_faces(); ++f) holes[f] = mesh.is_hole(f);
  return holes;
}

// Boundary mode none: as in OpenSubdiv, every face at a border vertex is a hole unless all the vertex's
// border edges are marked infinitely sharp. Empty when none is.
std::vector<bool> hole_faces(const Mesh& mesh, BoundaryMode boundary) {
  std::vector<bool> is_hole;
  if (boundary != BoundaryMode::none) return is_hole;
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    bool is_excluded = false;
    for (Index e : mesh.vertex_edges(v))
      is_excluded = is_excluded || (mesh.edge(e).is_boundary() && !mesh.edge(e).is_sharp);
    if (!is_excluded) continue;
    if (is_hole.empty()) is_hole.resize(mesh.num_faces(), false);
    for (Index c : mesh.vertex_corners(v)) is_hole[mesh.corner_face(c)] = true;
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
  }
  for (const Edge& e : full.edges())
    if (e.is_sharp && new_index[e.vertices[0]] != no_index && new_index[e.vertices[1]] != no_index)
      soup.sharp_edges.emplace_back(new_index[e.vertices[0]], new_index[e.vertices[1]]);
  return soup;
}

// The last of `levels` (refined from base) again with its edges and fans: the last two levels were built
// without them. (Templates: Refinement's levels are its own type.)
template <class Level>
Level full_last_level(const Mesh& base, const std::vector<Level>& levels, int threads) {
  const size_t k = levels.size();
  Level before_last, last;
  if (k == 1) {
    refine_topology(MeshLevelView(base), last, LevelDetail::full, threads);
    return last;
  }
  if (k == 2)
    refine_topology(MeshLevelView(base), before_last, LevelDetail::full, threads);
  else
    refine_topology(levels[k - 3], before_last, LevelDetail::full, threads);
  refine_topology(before_last, last, LevelDetail::full, threads);
  return last;
}

// The level's edges, and the corner signs: +1 at the first corner of each fan, flipped across every Möbius
// edge after it.
template <class Level>
void add_edges_and_signs(const Level& last, MeshArrays& a) {
  a.edges.resize(last.num_edges());
  for (Index e = 0; e < last.num_edges(); ++e) {
    Edge& edge = a.edges[e];
    edge.vertices = last.edge_ends(e);
    edge.corners = last.edge_corners[e];
    edge.faces = {edge.corners[0] >> 2, edge.corners[1] == no_index ? no_index : edge.corners[1] >> 2};
    edge.is_mobius = last.edge_flags[e] & mobius_flag;
    edge.is_sharp = last.edge_flags[e] & sharp_flag;
  }
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
}

}  // namespace

Refinement::Refinement(const Mesh& base, int levels, BoundaryMode boundary, int threads,
                       const CreaseOptions& creases) {
  rebuild(base, levels, boundary, threads, creases);
}

void Refinement::rebuild(const Mesh& base, int levels, BoundaryMode boundary, int threads,
                         const CreaseOptions& creases) {
  if (levels < 1)
    throw InvalidInputError("Refinement: levels must be at least 1, got " + std::to_string(levels));
  base_vertices_ = base.num_vertices();
  base_faces_ = base.num_faces();
  base_corners_ = base.num_corners();
  base_edges_ = base.num_edges();
  base_sharp_edges_ = sharp_edges(base);
  base_edge_weights_ = base.edge_sharpness_weights();
  base_vertex_weights_ = base.vertex_sharpness_weights();
  boundary_ = boundary;
  creases_ = creases;
  is_hole_ = hole_faces(base, boundary);
  levels_.resize(size_t(levels));
  base_holes_ = holes_of(base);
  if (!base_holes_.empty()) {
    is_hole_.resize(base.num_faces(), false);
    for (Index f = 0; f < base.num_faces(); ++f) is_hole_[f] = is_hole_[f] || base_holes_[f];
  }
  sharp_.clear();
  SharpLevel features = base_sharp_level(base, creases);
  if (!features.empty()) sharp_.push_back(std::move(features));
  build_levels(base, threads);
  if (levels >= 3) {
    if (!tiles_) tiles_ = std::make_unique<BaseTiles>();
    tiles_->build(base);
  }
  kept_vertices_.clear();
  output_vertices_.clear();
  if (!is_hole_.empty()) find_kept_vertices(base);
}

// The topology pass, level by level. The features of each level come from its parent's before the level
// is built, so that a level whose semi-sharp features need its edges and fans gets them in full.
void Refinement::build_levels(const Mesh& base, int threads) {
  const MeshLevelView view(base);
  Index corners = base.num_corners();  // of level k
  for (size_t k = 0; k < levels_.size(); ++k) {
    const Index child_faces = corners,
                child_edges = 2 * (k == 0 ? base.num_edges() : levels_[k - 1].edge_count) + corners;
    if (sharp_.size() == k + 1 && k + 1 < levels_.size()) {
      SharpLevel child =
          k == 0 ? child_sharp_level(view, sharp_[k], creases_.method, child_faces, child_edges)
                 : child_sharp_level(levels_[k - 1], sharp_[k], creases_.method, child_faces, child_edges);
      if (!child.empty()) sharp_.push_back(std::move(child));
    }
    corners = 4 * child_faces;
    if (k >= 1 && k + 1 == levels_.size()) {
      if (k == 1)
        refine_grandchild_quads(view, levels_[k], threads);
      else
        refine_grandchild_quads(levels_[k - 2], levels_[k], threads);
      continue;
    }
    const bool needs_full = sharp_.size() > k + 1 && sharp_[k + 1].needs_topology;
    const LevelDetail detail = needs_full                ? LevelDetail::full
                               : k + 1 == levels_.size() ? LevelDetail::quads
                               : k + 2 == levels_.size() ? LevelDetail::counts
                                                         : LevelDetail::full;
    if (k == 0)
      refine_topology(view, levels_[0], detail, threads);
    else
      refine_topology(levels_[k - 1], levels_[k], detail, threads);
  }
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
  output_vertices_ = kept_vertices_;
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
         sharp_edges(base) == base_sharp_edges_ && base.edge_sharpness_weights() == base_edge_weights_ &&
         base.vertex_sharpness_weights() == base_vertex_weights_ && holes_of(base) == base_holes_;
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
  const SharpRules sharp_rules{creases_.method, rules};
  const std::vector<LevelCounts> counts = level_counts(base, levels());
  for (size_t k = 0; k < levels_.size(); ++k) {
    std::span<Vec3> target = out;
    if (k + 1 < levels_.size()) {
      // One more position, read but never used by the vector steps of the next pass.
      resize_for_overwrite(levels_[k].positions, levels_[k].vertex_count + 1);
      levels_[k].positions.back() = Vec3(0.0);
      target = std::span(levels_[k].positions).first(levels_[k].vertex_count);
    }
    if (k == 0)
      nome::refine_positions(MeshLevelView(base), in, rules, target, threads);
    else if (k == 1)
      refine_child_positions(MeshLevelView(base), in, rules, target, threads);
    else if (rule == SubdivisionRule::classic)
      refine_child_positions_by_tile(levels_[k - 2], *tiles_, std::span(counts).first(k), in, rules, target,
                                     threads, is_vector_allowed_);
    else
      refine_child_positions(levels_[k - 2], in, rules, target, threads);
    if (k < sharp_.size()) {
      if (k == 0)
        refine_sharp_positions(MeshLevelView(base), sharp_[k], sharp_rules, in, target, threads);
      else
        refine_sharp_positions(levels_[k - 1], sharp_[k], sharp_rules, in, target, threads);
    }
    in = target;
  }
}

std::span<const Vec3> Refinement::refine_positions(const Mesh& base, SubdivisionRule rule, int threads) {
  resize_for_overwrite(levels_.back().positions, num_vertices());
  refine_positions(base, rule, levels_.back().positions, threads);
  return levels_.back().positions;
}

void Refinement::refine_positions(const Mesh& base, SubdivisionRule rule, Mesh& result, int threads) {
  if (is_hole_.empty()) return refine_positions(base, rule, result.positions(), threads);
  if (result.num_vertices() != output_vertices_.size())
    throw InvalidInputError("Refinement::refine_positions: the result was not made by this refinement");
  const std::span<const Vec3> all = refine_positions(base, rule, threads);
  for (size_t i = 0; i < output_vertices_.size(); ++i) result.positions()[i] = all[output_vertices_[i]];
}

Mesh Refinement::mesh(const Mesh& base, Buffer<Vec3> positions, int threads) const {
  if (!fits(base)) throw InvalidInputError("Refinement::mesh: the base mesh's topology changed");
  if (positions.size() != num_vertices())
    throw InvalidInputError("Refinement::mesh: expected " + std::to_string(num_vertices()) + " positions");
  auto last = full_last_level(base, levels_, threads);
  MeshArrays a;
  const Index nf = last.num_faces();
  a.positions = std::move(positions);
  a.face_offsets.resize(size_t(nf) + 1);
  for (Index f = 0; f <= nf; ++f) a.face_offsets[f] = 4 * f;
  add_edges_and_signs(last, a);
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
  if (is_hole_.empty()) {
    if (!base.face_attributes().empty())
      a.face_attributes = carried(base.face_attributes(), face_origins(base));
    return assemble_mesh(std::move(a));
  }
  PolygonSoup soup = without_holes(assemble_mesh(std::move(a)), is_hole_, shift, base, kept_vertices_);
  if (!base.face_attributes().empty())
    soup.face_attributes = carried(base.face_attributes(), face_origins(base));
  output_vertices_ = kept_vertices_;
  try {
    return build_mesh(soup);
  } catch (const TopologyError&) {
    // Holes may leave faces that touch at a vertex only (a hole at a border): one vertex per fan there.
    GluedFaces glued = glue_faces(soup);
    output_vertices_.resize(glued.vertex_sources.size());
    std::vector<Index> first_copy(soup.num_vertices(), no_index), origins(glued.vertex_sources.size());
    for (size_t i = 0; i < glued.vertex_sources.size(); ++i) {
      const Index source = glued.vertex_sources[i];
      output_vertices_[i] = kept_vertices_[source];
      if (first_copy[source] == no_index) first_copy[source] = Index(i);
      origins[i] = first_copy[source];
    }
    glued.mesh.set_vertex_origins(std::move(origins));
    return std::move(glued.mesh);
  }
}

ElementOrigins Refinement::face_origins(const Mesh& base) const {
  const unsigned shift = 2 * unsigned(levels_.size() - 1);
  ElementOrigins origins;
  origins.parents.reserve(num_faces());
  for (Index f = 0; f < num_faces(); ++f) {
    const Index ancestor = base.corner_face(f >> shift);
    if (is_hole_.empty() || !is_hole_[ancestor]) origins.parents.push_back(ancestor);
  }
  return origins;
}

Mesh subdivide(const Mesh& mesh, const SubdivisionOptions& options) {
  if (options.levels == 0) return mesh;
  Refinement refinement(mesh, options.levels, options.boundary, 1, options.creases);
  Buffer<Vec3> positions(refinement.num_vertices());
  refinement.refine_positions(mesh, options.rule, positions);
  return refinement.mesh(mesh, std::move(positions));
}

}  // namespace nome
