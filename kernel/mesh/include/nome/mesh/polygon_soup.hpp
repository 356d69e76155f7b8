#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nome/buffer.hpp"
#include "nome/mesh/attributes.hpp"
#include "nome/mesh/names.hpp"
#include "nome/mesh/soup_grid.hpp"
#include "nome/mesh/types.hpp"

namespace nome {

// Where faces were made, for messages about them: the faces from `first_face` up to the next origin's
// first face come from the statement at `where` ("file:line:col"; empty: unknown).
struct FaceOrigin {
  Index first_face = 0;
  std::string where;
};

// Positions and polygons as given, before any topology: the input of build_mesh.
// Optional per-element names and attributes travel with the elements into the Mesh.
struct PolygonSoup {
  Buffer<Vec3> positions;
  Buffer<Index> face_offsets{0};  // face f has corners [face_offsets[f], face_offsets[f+1])
  Buffer<Index> face_vertices;
  Names vertex_names;                                // empty, or one per vertex
  Names face_names;                                  // empty, or one per face
  Attributes face_attributes;                        // colours and what else faces carry
  std::vector<std::pair<Index, Index>> sharp_edges;  // vertex pairs whose edge is marked sharp
  // Empty: every sharp edge is infinitely sharp; otherwise one crease weight per sharp_edges pair
  // (OpenSubdiv's sharpness: from infinite_sharpness up, infinitely sharp).
  std::vector<float> sharp_edge_weights;
  std::vector<std::pair<Index, float>> sharp_vertices;  // corner vertices and their sharpness
  std::vector<Index> hole_faces;         // faces refined for their neighbours' sake but not output
  std::vector<FaceOrigin> face_origins;  // empty, or runs sorted by first_face
  std::optional<SoupGrid> grid;          // the faces' layout, when a generator made them as a grid

  Index add_vertex(const Vec3& p) {
    positions.push_back(p);
    return static_cast<Index>(positions.size() - 1);
  }
  template <typename Range>
  Index add_face(const Range& vertices) {
    for (Index v : vertices) face_vertices.push_back(v);
    face_offsets.push_back(static_cast<Index>(face_vertices.size()));
    return num_faces() - 1;
  }
  Index add_face(std::initializer_list<Index> vertices) {
    return add_face<std::initializer_list<Index>>(vertices);
  }
  // Marks the edge (a, b) sharp with `weight`; the weights stay empty while every mark is infinitely sharp.
  void add_sharp_edge(Index a, Index b, float weight = infinite_sharpness);
  // The faces added from now on come from `where` (an empty text on a soup without origins adds none).
  void note_origin(const std::string& where);
  // Where face f was made; empty when unknown.
  const std::string& origin(Index f) const;
  Index num_vertices() const { return static_cast<Index>(positions.size()); }
  Index num_faces() const { return static_cast<Index>(face_offsets.size() - 1); }
};

// Appends `part` to `into` as separate vertices and faces, keeping names, attributes, origins and sharp
// marks: where only one of them has names, the other's elements get empty ones; where only one has an
// attribute, the other's faces get its fallback. A grid layout is kept when `into` was empty.
void append_soup(PolygonSoup& into, const PolygonSoup& part);

}  // namespace nome
