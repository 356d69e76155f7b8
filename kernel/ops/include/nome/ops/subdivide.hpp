#pragma once

#include <memory>
#include <span>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/ops/boundary_mode.hpp"
#include "nome/ops/crease_options.hpp"

namespace nome {

struct SharpLevel;
struct BaseTiles;

// The smooth-vertex rule of Catmull-Clark (Wang's 2016 report, UCB/EECS-2016-65, section 4.1.3, which
// calls its second rule DeRose's: it is not, so it is named for the report here).
enum class SubdivisionRule {
  classic,  // ((n-3) v + 2 avg(edge midpoints) + avg(face points)) / n: Catmull-Clark, OpenSubdiv, OpenMesh
  report,   // ((n-2) v + avg(new edge points) + avg(face points)) / n: the 2016 report's stiffer rule
};

struct SubdivisionOptions {
  int levels = 1;
  SubdivisionRule rule = SubdivisionRule::classic;
  BoundaryMode boundary = BoundaryMode::edge_only;
  CreaseOptions creases = {};
};

// Catmull-Clark subdivision (Wang's 2016 report, section 4), `levels` times, on any mesh the kernel accepts:
// polygons of any degree, borders, Möbius edges, several components. Border and sharp edges keep their
// midpoints; a vertex with >= 3 sharp edges stays put, with 2 it follows the crease (6v + a + b) / 8;
// `boundary` decides the vertices of a single face and whether border faces are output. Crease and
// corner weights (Mesh::edge_sharpness, vertex_sharpness) follow OpenSubdiv's Catmark rules: a weight
// decays by one per level (or by `creases.method`), a vertex takes its parent's and its child's rule
// blended by the weights that decayed to zero. Hole faces are refined but not output.
// Each n-gon becomes n quads with its orientation; children of Möbius and sharp edges keep the flag.
// Positions never depend on face orientation or numbering.
Mesh subdivide(const Mesh& mesh, const SubdivisionOptions& options);

// The refined topology of one base topology, built once (the topology pass), and the position pass
// that can run again whenever the base positions change without changing the topology: the
// interactive fast path. Children are numbered arithmetically, as in OpenSubdiv's Vtr: the child
// vertices of a level are its parent's face points, then edge points, then vertex points; the child
// faces of parent corner c are face c (so a face's children are consecutive), the two children of
// parent edge e are edges 2e and 2e+1. The last level keeps only its quads' corners unless mesh() is
// asked for, which builds its edges and fans the same way. The boundary mode is part of the topology: it
// decides which vertices are corners and which faces are holes.
class Refinement {
 public:
  // The topology pass, on up to `threads` threads. Throws InvalidInputError unless levels >= 1.
  // The crease weights of `base` are part of the topology, and so are `creases`.
  Refinement(const Mesh& base, int levels, BoundaryMode boundary = BoundaryMode::edge_only, int threads = 1,
             const CreaseOptions& creases = {});
  Refinement(Refinement&&) noexcept;
  Refinement& operator=(Refinement&&) noexcept;
  ~Refinement();

  // The topology pass again, for `base` (any topology), into this refinement's blocks: the result and
  // the throws of a new Refinement, without the fresh pages (first touches cost far more than writes)
  // where the new levels fit in the old blocks.
  void rebuild(const Mesh& base, int levels, BoundaryMode boundary = BoundaryMode::edge_only, int threads = 1,
               const CreaseOptions& creases = {});

  int levels() const;
  BoundaryMode boundary() const { return boundary_; }
  const CreaseOptions& creases() const { return creases_; }
  // True when `base` has the counts, sharp flags, weights and holes of the mesh this refinement was built
  // from.
  bool fits(const Mesh& base) const;

  // The last level: every face is a quad, quad f has corners quad_vertices()[4f .. 4f+3].
  Index num_vertices() const;
  Index num_faces() const;
  std::span<const Index> quad_vertices() const;

  // The position pass: gathers every level from the one before into reused buffers and writes the
  // last level into `out` (num_vertices() entries). `base` must fit. Uses up to `threads` threads.
  void refine_positions(const Mesh& base, SubdivisionRule rule, std::span<Vec3> out, int threads = 1);
  // The same into the refinement's own buffer, reused by every call (no fresh pages, no zero-fill pass):
  // valid until the next call.
  std::span<const Vec3> refine_positions(const Mesh& base, SubdivisionRule rule, int threads = 1);

  // Whether the position pass may use vector instructions beyond the architecture's baseline (AVX2) where
  // the CPU has them; they are by default. The results are the same bits either way.
  void allow_vector_instructions(bool is_allowed) { is_vector_allowed_ = is_allowed; }

  // The last level as a full Mesh with the given positions (from refine_positions), built from the
  // level before it without any search; faces keep the attributes and components of their ancestors. The
  // descendants of hole faces are left out, with the vertices only they use; where that leaves faces
  // touching at a vertex only, the vertex becomes one per fan.
  Mesh mesh(const Mesh& base, Buffer<Vec3> positions, int threads = 1) const;
  // For each face of mesh(): its base face (its ancestor), holes' descendants left out as mesh() does.
  ElementOrigins face_origins(const Mesh& base) const;
  // The position pass into `result`, the mesh this refinement's mesh() made last (the fast path).
  void refine_positions(const Mesh& base, SubdivisionRule rule, Mesh& result, int threads = 1);

  struct Level;

 private:
  void find_kept_vertices(const Mesh& base);
  void build_levels(const Mesh& base, int threads);

  std::vector<Level> levels_;  // levels 1..k: only the last two lack edges and fans
  Index base_vertices_ = 0, base_faces_ = 0, base_corners_ = 0, base_edges_ = 0;
  std::vector<Index> base_sharp_edges_;
  std::vector<float> base_edge_weights_, base_vertex_weights_;
  std::vector<bool> base_holes_;
  BoundaryMode boundary_ = BoundaryMode::edge_only;
  CreaseOptions creases_;
  std::vector<SharpLevel> sharp_;     // per parent level from the base while it has semi-sharp features
  std::unique_ptr<BaseTiles> tiles_;  // the base's elements by face, for the tiled position pass
  std::vector<bool> is_hole_;         // per base face; empty when there is none
  std::vector<Index> kept_vertices_;  // with holes: the last level's vertices mesh() keeps, in order
  // With holes: the last level's vertex of each vertex of the mesh() made last (kept_vertices_, unless
  // faces touching at a vertex made it split the vertex).
  mutable std::vector<Index> output_vertices_;
  bool is_vector_allowed_ = true;
};

}  // namespace nome
