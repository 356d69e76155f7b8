#pragma once

#include <array>
#include <span>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "nome/mesh/buffer.hpp"
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

struct MeshArrays;

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
  Index num_vertices() const { return static_cast<Index>(positions_.size()); }
  Index num_faces() const { return static_cast<Index>(face_offsets_.size() - 1); }
  Index num_edges() const { return static_cast<Index>(edges_.size()); }
  Index num_corners() const { return static_cast<Index>(corner_vertices_.size()); }
  Index num_boundary_loops() const { return static_cast<Index>(loop_offsets_.size() - 1); }
  Index num_components() const { return num_components_; }

  // Positions: a slider may move them without changing the topology.
  const Buffer<Vec3>& positions() const { return positions_; }
  Buffer<Vec3>& positions() { return positions_; }
  const Vec3& position(Index v) const { return positions_[v]; }

  // Faces, in their given cyclic order. face_edges(f)[i] joins face_vertices(f)[i] and [i+1].
  std::span<const Index> face_vertices(Index f) const { return corner_span(corner_vertices_, f); }
  std::span<const Index> face_edges(Index f) const { return corner_span(corner_edges_, f); }
  Index face_degree(Index f) const { return face_offsets_[f + 1] - face_offsets_[f]; }
  Index face_first_corner(Index f) const { return face_offsets_[f]; }
  Index next_corner(Index c) const {
    Index f = corner_faces_[c];
    return c + 1 == face_offsets_[f + 1] ? face_offsets_[f] : c + 1;
  }
  Index prev_corner(Index c) const {
    Index f = corner_faces_[c];
    return c == face_offsets_[f] ? face_offsets_[f + 1] - 1 : c - 1;
  }

  // Corners: the flat arrays behind faces and fans (CSR by face_offsets()).
  const Buffer<Index>& face_offsets() const { return face_offsets_; }
  const Buffer<Index>& corner_vertices() const { return corner_vertices_; }
  const Buffer<Index>& corner_edges() const { return corner_edges_; }
  const Buffer<Index>& corner_faces() const { return corner_faces_; }
  const Buffer<signed char>& corner_signs() const { return corner_signs_; }
  Index corner_vertex(Index c) const { return corner_vertices_[c]; }
  Index corner_edge(Index c) const { return corner_edges_[c]; }
  Index corner_face(Index c) const { return corner_faces_[c]; }
  int corner_sign(Index c) const { return corner_signs_[c]; }

  // Edges.
  const Buffer<Edge>& edges() const { return edges_; }
  const Edge& edge(Index e) const { return edges_[e]; }
  void set_sharp(Index e, bool sharp) { edges_[e].is_sharp = sharp; }

  // Vertex fans: corners (one per incident face) and edges in fan order, as documented above.
  std::span<const Index> vertex_corners(Index v) const {
    return {fan_corners_.data() + fan_corner_offsets_[v],
            fan_corner_offsets_[v + 1] - fan_corner_offsets_[v]};
  }
  std::span<const Index> vertex_edges(Index v) const {
    return {fan_edges_.data() + fan_edge_offsets_[v], fan_edge_offsets_[v + 1] - fan_edge_offsets_[v]};
  }
  Index vertex_valence(Index v) const { return fan_edge_offsets_[v + 1] - fan_edge_offsets_[v]; }
  bool is_boundary_vertex(Index v) const { return vertex_edges(v).size() > vertex_corners(v).size(); }
  bool is_isolated_vertex(Index v) const { return vertex_corners(v).empty(); }
  const Buffer<Index>& fan_corner_offsets() const { return fan_corner_offsets_; }
  const Buffer<Index>& fan_corners() const { return fan_corners_; }
  const Buffer<Index>& fan_edge_offsets() const { return fan_edge_offsets_; }
  const Buffer<Index>& fan_edges() const { return fan_edges_; }

  // Boundary loops: loop_edges(l)[i] joins loop_vertices(l)[i] and loop_vertices(l)[i+1] (cyclically).
  std::span<const Index> loop_edges(Index l) const {
    return {loop_edges_.data() + loop_offsets_[l], loop_offsets_[l + 1] - loop_offsets_[l]};
  }
  std::span<const Index> loop_vertices(Index l) const {
    return {loop_vertices_.data() + loop_offsets_[l], loop_offsets_[l + 1] - loop_offsets_[l]};
  }

  // Connected components (isolated vertices are in none: no_index).
  Index face_component(Index f) const { return face_components_[f]; }
  Index vertex_component(Index v) const;

  // Optional attributes carried from the soup: empty when not given.
  const std::vector<std::string>& vertex_names() const { return vertex_names_; }
  const std::vector<std::string>& face_names() const { return face_names_; }
  const std::vector<Color>& face_colors() const { return face_colors_; }
  std::vector<Color>& face_colors() { return face_colors_; }
  // "v12" or the vertex's name: for messages.
  std::string vertex_label(Index v) const;
  std::string face_label(Index f) const;

 private:
  friend Mesh build_mesh(PolygonSoup soup);
  friend Mesh assemble_mesh(MeshArrays arrays);

  // A mesh's arrays moved out, for a builder to refill and assemble again: they come out as in a default
  // MeshArrays (empty), but keep their blocks, so a rebuild no larger than the mesh it replaces touches no
  // fresh pages (a third of an offset's time). `mesh` is left empty.
  MeshArrays take_arrays(Mesh&& mesh);
  friend MeshArrays take_arrays(Mesh&& mesh);

  // Derived arrays shared by both builders: boundary loops from the fans, components by a walk over faces.
  void find_boundary_loops();
  void find_components();

  std::span<const Index> corner_span(const Buffer<Index>& a, Index f) const {
    return {a.data() + face_offsets_[f], face_offsets_[f + 1] - face_offsets_[f]};
  }

  Buffer<Vec3> positions_;
  Buffer<Index> face_offsets_{0};
  Buffer<Index> corner_vertices_;
  Buffer<Index> corner_edges_;
  Buffer<Index> corner_faces_;
  Buffer<signed char> corner_signs_;
  Buffer<Edge> edges_;
  Buffer<Index> fan_corner_offsets_{0};
  Buffer<Index> fan_corners_;
  Buffer<Index> fan_edge_offsets_{0};
  Buffer<Index> fan_edges_;
  std::vector<Index> loop_offsets_{0};
  std::vector<Index> loop_edges_;
  std::vector<Index> loop_vertices_;
  Buffer<Index> face_components_;
  Index num_components_ = 0;
  std::vector<std::string> vertex_names_;
  std::vector<std::string> face_names_;
  std::vector<Color> face_colors_;
};

// The arrays of a mesh whose adjacency is already known (a subdivision level, an offset solid), laid out
// as Mesh documents them. Corner faces and boundary loops are derived; components too unless given.
struct MeshArrays {
  Buffer<Index> corner_faces;  // written by assemble_mesh: given only as storage to reuse
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
  std::vector<Color> face_colors;  // empty, or one per face
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

// The mesh's polygons and attributes as a soup (round trip: build_mesh(to_soup(m)) equals m).
PolygonSoup to_soup(const Mesh& mesh);

// A copy with every position mapped by the affine 4x4 matrix; winding is kept as given (a mirror in
// the scene language reverses faces itself).
Mesh transformed(const Mesh& mesh, const glm::dmat4& matrix);

}  // namespace nome
