#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>

#include "nome/buffer.hpp"
#include "nome/mesh/attributes.hpp"
#include "nome/mesh/polygon_soup.hpp"
#include "nome/mesh/types.hpp"

namespace nome {

// An edge joins two vertices and has one face (boundary) or two. `corners[i]` is the global corner id
// in faces[i] where the edge starts (the face runs corner -> next corner along it). vertices[0] ->
// vertices[1] is the direction faces[0] runs along the edge. A Möbius edge is one whose two faces run
// along it in the same direction: their given orientations disagree across it.
struct Edge {
  std::array<Index, 2> vertices{no_index, no_index};
  std::array<Index, 2> faces{no_index, no_index};
  std::array<Index, 2> corners{no_index, no_index};
  bool is_mobius = false;
  bool is_sharp = false;

  bool is_boundary() const { return faces[1] == no_index; }
  Index other_vertex(Index v) const { return vertices[0] == v ? vertices[1] : vertices[0]; }
  Index other_face(Index f) const { return faces[0] == f ? faces[1] : faces[0]; }
};

// The arrays of a mesh, laid out as Mesh documents them: what a builder that knows the adjacency (a
// subdivision level, an offset solid) fills for assemble_mesh, and what a Mesh holds besides its loops and
// names. Corner faces and boundary loops are derived; components too unless given.
struct MeshArrays {
  // Derived, by assemble_mesh: empty when every face is a quad (corner c's face is then c / 4: a subdivided
  // mesh or its offset saves 16 bytes a face).
  Buffer<Index> corner_faces;
  Buffer<Vec3> positions;
  Buffer<Index> face_offsets{0};
  Buffer<Index> corner_vertices;
  Buffer<Index> corner_edges;
  Buffer<signed char> corner_signs;
  Buffer<Edge> edges;
  Buffer<Index> fan_corner_offsets{0};
  Buffer<Index> fan_corners;
  Buffer<Index> fan_edge_offsets{0};
  Buffer<Index> fan_edges;
  Buffer<Index> face_components;  // empty: found by a walk over faces
  Index num_components = 0;
  Attributes face_attributes;  // colours and whatever else a caller attaches to faces
  // Semi-sharp crease weights (see Mesh::edge_sharpness), corner weights and hole marks: each empty, or
  // one per edge / vertex / face.
  std::vector<float> edge_sharpness;
  std::vector<float> vertex_sharpness;
  std::vector<bool> face_holes;

  Index corner_face(Index c) const { return corner_faces.empty() ? c >> 2 : corner_faces[c]; }
};

// A 2-manifold polygon mesh, possibly with borders, possibly non-orientable, as index arrays.
//
// Faces keep the orientation they were given (the corner order). A corner is one (face, vertex)
// incidence; corner c of face f has global id face_offsets()[f] + i. Every vertex has its incident
// corners and edges in fan order: interior fan e0 c0 e1 c1 ... e(k-1) c(k-1) (e0 follows c(k-1));
// boundary fan e0 c0 e1 ... c(k-1) ek with e0 and ek the two border edges. So edge i of a fan lies
// between corners i-1 and i. Each corner carries the orientation sign of its face relative to the
// first face of its vertex's fan, flipped at every Möbius edge crossed (well defined: a disk fan
// crosses an even number of Möbius edges).
//
// Build with build_mesh() (from polygons) or assemble_mesh() (from arrays whose adjacency is already
// known); the topology is immutable afterwards, positions and sharp flags may change.
class Mesh {
 public:
  Index num_vertices() const { return static_cast<Index>(arrays_.positions.size()); }
  Index num_faces() const { return static_cast<Index>(arrays_.face_offsets.size() - 1); }
  Index num_edges() const { return static_cast<Index>(arrays_.edges.size()); }
  Index num_corners() const { return static_cast<Index>(arrays_.corner_vertices.size()); }
  Index num_boundary_loops() const { return static_cast<Index>(loop_offsets_.size() - 1); }
  Index num_components() const { return arrays_.num_components; }

  // Positions: a slider may move them without changing the topology.
  const Buffer<Vec3>& positions() const { return arrays_.positions; }
  Buffer<Vec3>& positions() { return arrays_.positions; }
  const Vec3& position(Index v) const { return arrays_.positions[v]; }

  // Faces, in their given cyclic order. face_edges(f)[i] joins face_vertices(f)[i] and [i+1].
  std::span<const Index> face_vertices(Index f) const { return corner_span(arrays_.corner_vertices, f); }
  std::span<const Index> face_edges(Index f) const { return corner_span(arrays_.corner_edges, f); }
  Index face_degree(Index f) const { return arrays_.face_offsets[f + 1] - arrays_.face_offsets[f]; }
  Index face_first_corner(Index f) const { return arrays_.face_offsets[f]; }
  Index next_corner(Index c) const {
    Index f = arrays_.corner_face(c);
    return c + 1 == arrays_.face_offsets[f + 1] ? arrays_.face_offsets[f] : c + 1;
  }
  Index prev_corner(Index c) const {
    Index f = arrays_.corner_face(c);
    return c == arrays_.face_offsets[f] ? arrays_.face_offsets[f + 1] - 1 : c - 1;
  }

  // Corners: the flat arrays behind faces and fans (CSR by face_offsets()).
  const Buffer<Index>& face_offsets() const { return arrays_.face_offsets; }
  const Buffer<Index>& corner_vertices() const { return arrays_.corner_vertices; }
  const Buffer<Index>& corner_edges() const { return arrays_.corner_edges; }
  // Empty when every face is a quad (see corner_face).
  const Buffer<Index>& corner_faces() const { return arrays_.corner_faces; }
  // Every face is a quad (every subdivided mesh and its offset): face f has corners 4f .. 4f+3.
  bool is_quad_mesh() const { return arrays_.corner_faces.empty(); }
  const Buffer<signed char>& corner_signs() const { return arrays_.corner_signs; }
  Index corner_vertex(Index c) const { return arrays_.corner_vertices[c]; }
  Index corner_edge(Index c) const { return arrays_.corner_edges[c]; }
  Index corner_face(Index c) const { return arrays_.corner_face(c); }
  int corner_sign(Index c) const { return arrays_.corner_signs[c]; }

  // Edges.
  const Buffer<Edge>& edges() const { return arrays_.edges; }
  const Edge& edge(Index e) const { return arrays_.edges[e]; }
  void set_sharp(Index e, bool sharp) { arrays_.edges[e].is_sharp = sharp; }
  // Crease weights with OpenSubdiv's meaning (Catmark, uniform refinement): an edge of weight w >= 1 is
  // a crease for the first floor(w) levels, a fractional rest blends, infinite_sharpness never decays.
  // An is_sharp edge weighs infinite_sharpness; setting a weight sets is_sharp exactly when it is
  // infinite. Storage is allocated with the first non-zero weight.
  float edge_sharpness(Index e) const {
    if (arrays_.edges[e].is_sharp) return infinite_sharpness;
    return arrays_.edge_sharpness.empty() ? 0.0f : arrays_.edge_sharpness[e];
  }
  void set_edge_sharpness(Index e, float weight);
  // A corner weight: the vertex stays put for as many levels (fractional rest blended); 0 by default.
  float vertex_sharpness(Index v) const {
    return arrays_.vertex_sharpness.empty() ? 0.0f : arrays_.vertex_sharpness[v];
  }
  void set_vertex_sharpness(Index v, float weight);
  // True when some edge has a finite non-zero weight or some vertex a corner weight.
  bool has_sharpness_weights() const;
  // Semi-sharp weights: empty, or one per edge (is_sharp edges' entries are not read).
  const std::vector<float>& edge_sharpness_weights() const { return arrays_.edge_sharpness; }
  const std::vector<float>& vertex_sharpness_weights() const { return arrays_.vertex_sharpness; }
  // Hole faces are subdivided like any other (their neighbours keep their shape) but not output.
  bool is_hole(Index f) const { return !arrays_.face_holes.empty() && arrays_.face_holes[f]; }
  void set_hole(Index f, bool hole);
  bool has_holes() const;
  const std::vector<bool>& face_holes() const { return arrays_.face_holes; }  // empty, or one per face
  // Where one vertex of a surface became one per fan (faces touching at it only, as holes leave them): per
  // vertex, the lowest-numbered copy of the vertex it was split from (itself when none was), so that a
  // writer writes such a vertex once. Empty when no vertex was split. Copies share their position.
  const std::vector<Index>& vertex_origins() const { return vertex_origins_; }
  void set_vertex_origins(std::vector<Index> origins) { vertex_origins_ = std::move(origins); }

  // Vertex fans: corners (one per incident face) and edges in fan order, as documented above.
  std::span<const Index> vertex_corners(Index v) const {
    return {arrays_.fan_corners.data() + arrays_.fan_corner_offsets[v],
            arrays_.fan_corner_offsets[v + 1] - arrays_.fan_corner_offsets[v]};
  }
  std::span<const Index> vertex_edges(Index v) const {
    return {arrays_.fan_edges.data() + arrays_.fan_edge_offsets[v],
            arrays_.fan_edge_offsets[v + 1] - arrays_.fan_edge_offsets[v]};
  }
  Index vertex_valence(Index v) const {
    return arrays_.fan_edge_offsets[v + 1] - arrays_.fan_edge_offsets[v];
  }
  bool is_boundary_vertex(Index v) const { return vertex_edges(v).size() > vertex_corners(v).size(); }
  bool is_isolated_vertex(Index v) const { return vertex_corners(v).empty(); }
  const Buffer<Index>& fan_corner_offsets() const { return arrays_.fan_corner_offsets; }
  const Buffer<Index>& fan_corners() const { return arrays_.fan_corners; }
  const Buffer<Index>& fan_edge_offsets() const { return arrays_.fan_edge_offsets; }
  const Buffer<Index>& fan_edges() const { return arrays_.fan_edges; }

  // Boundary loops: loop_edges(l)[i] joins loop_vertices(l)[i] and loop_vertices(l)[i+1] (cyclically).
  std::span<const Index> loop_edges(Index l) const {
    return {loop_edges_.data() + loop_offsets_[l], loop_offsets_[l + 1] - loop_offsets_[l]};
  }
  std::span<const Index> loop_vertices(Index l) const {
    return {loop_vertices_.data() + loop_offsets_[l], loop_offsets_[l + 1] - loop_offsets_[l]};
  }

  // Connected components (isolated vertices are in none: no_index).
  Index face_component(Index f) const { return arrays_.face_components[f]; }
  Index vertex_component(Index v) const;

  // Optional attributes carried from the soup: empty when not given.
  const Names& vertex_names() const { return vertex_names_; }
  const Names& face_names() const { return face_names_; }
  // Per-face data (colours and what else a caller attaches), carried through every operation.
  const Attributes& face_attributes() const { return arrays_.face_attributes; }
  Attributes& face_attributes() { return arrays_.face_attributes; }
  // "v12" or the vertex's name: for messages.
  std::string vertex_label(Index v) const;
  std::string face_label(Index f) const;

 private:
  friend Mesh build_mesh_from(PolygonSoup& soup);
  friend Mesh assemble_mesh(MeshArrays arrays);

  friend MeshArrays take_arrays(Mesh&& mesh);

  // Derived arrays shared by both builders: each corner's face from the face offsets, boundary loops from
  // the fans, components by a walk over faces.
  void find_corner_faces();
  void find_boundary_loops();
  void find_components();

  std::span<const Index> corner_span(const Buffer<Index>& a, Index f) const {
    return {a.data() + arrays_.face_offsets[f], arrays_.face_offsets[f + 1] - arrays_.face_offsets[f]};
  }

  MeshArrays arrays_;
  std::vector<Index> loop_offsets_{0};
  std::vector<Index> loop_edges_;
  std::vector<Index> loop_vertices_;
  Names vertex_names_;
  Names face_names_;
  std::vector<Index> vertex_origins_;
};

// Assembles a mesh from arrays in O(corners), without build_mesh's search and checks: the caller
// guarantees the invariants (tests check them with validate()).
Mesh assemble_mesh(MeshArrays arrays);

// A mesh's arrays moved out, for a builder to refill and assemble again: they come out as in a default
// MeshArrays (empty), but keep their blocks, so a rebuild no larger than the mesh it replaces touches no
// fresh pages (a third of an offset's time). `mesh` is left empty.
MeshArrays take_arrays(Mesh&& mesh);

// Every broken invariant of the mesh, described (empty for a valid mesh): array sizes, edge records
// against corners, Möbius flags against directions, fans in order with their signs, loops, components.
std::vector<std::string> validate(const Mesh& mesh);

// Builds the mesh in O(corners). Throws TopologyError naming the elements when the polygons are not a
// 2-manifold: a face with fewer than 3 vertices, a vertex repeated in a face, an index out of range, a
// third face on an edge, a vertex whose faces do not form one fan. Vertices used by no face are kept
// as isolated vertices (they belong to no component).
Mesh build_mesh(PolygonSoup soup);
// build_mesh on the soup's own arrays, without a copy: they move into the mesh, or stay in the soup when it
// throws (for a caller that explains the error from them).
Mesh build_mesh_from(PolygonSoup& soup);

// How many meshes build_mesh has been asked to build in this process: the interactive paths build none
// when only positions move, and tests hold them to it.
std::uint64_t build_mesh_count();
// How many of them found their edges from the soup's grid layout rather than by searching.
std::uint64_t build_mesh_grid_count();

// The mesh's polygons and attributes as a soup (round trip: build_mesh(to_soup(m)) equals m).
PolygonSoup to_soup(const Mesh& mesh);

// A copy with every position mapped by the affine 4x4 matrix; winding is kept as given (a mirror in
// the scene language reverses faces itself).
Mesh transformed(const Mesh& mesh, const glm::dmat4& matrix);

}  // namespace nome
