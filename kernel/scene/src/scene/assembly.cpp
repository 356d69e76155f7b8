// The placements of each top-level instance joined into its geometry (deleted faces left out), and all
// top-level instances as one soup.
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include "nome/assert.hpp"
#include "nome/scene/scene.hpp"

namespace nome::scene {
namespace {

bool is_same_topology(const PolygonSoup& a, const PolygonSoup& b) {
  return a.num_vertices() == b.num_vertices() && a.face_offsets == b.face_offsets &&
         a.face_vertices == b.face_vertices;
}

// Appends the whole piece: its arrays in bulk. Returns whether any of its faces has a colour of its own.
bool append_whole_piece(Piece& out, const Piece& piece) {
  const Index base = out.soup.num_vertices();
  append_soup(out.soup, piece.soup);
  for (const RimLine& r : piece.rims) {
    RimLine rim{r.name, r.vertices, r.is_loop, r.color};
    for (Index& v : rim.vertices) v += base;
    out.rims.push_back(std::move(rim));
  }
  return piece.has_face_colors();
}

// Appends the piece's faces but the deleted ones, and its vertices unless every face using them is
// deleted; returns whether any appended face carries its own colour.
bool append_piece(Piece& out, const Piece& piece, const std::unordered_set<std::string>& deleted) {
  const PolygonSoup& s = piece.soup;
  std::vector<unsigned char> is_deleted(s.num_faces(), 0);
  if (!deleted.empty())
    for (Index f = 0; f < s.num_faces(); ++f) is_deleted[f] = deleted.count(s.face_names[f]) ? 1 : 0;
  if (std::find(is_deleted.begin(), is_deleted.end(), 1) == is_deleted.end())
    return append_whole_piece(out, piece);
  std::vector<unsigned char> is_used(s.num_vertices(), 0), is_kept(s.num_vertices(), 0);
  for (Index f = 0; f < s.num_faces(); ++f) {
    for (Index c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c) {
      is_used[s.face_vertices[c]] = 1;
      if (!is_deleted[f]) is_kept[s.face_vertices[c]] = 1;
    }
  }
  std::vector<Index> new_id(s.num_vertices(), no_index);
  for (Index v = 0; v < s.num_vertices(); ++v)
    if (is_kept[v] || !is_used[v]) new_id[v] = out.add_vertex(s.positions[v], s.vertex_names[v]);
  const Index faces_before = out.soup.num_faces();
  std::vector<Index> kept_faces, corners;
  for (Index f = 0; f < s.num_faces(); ++f) {
    if (is_deleted[f]) continue;
    corners.clear();
    for (Index c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c)
      corners.push_back(new_id[s.face_vertices[c]]);
    out.soup.note_origin(s.origin(f));
    out.add_face(corners, s.face_names[f]);
    kept_faces.push_back(f);
  }
  out.soup.face_attributes.append(carried(s.face_attributes, kept_faces), faces_before);
  bool has_color = false;
  for (Index f : kept_faces) has_color = has_color || piece.has_face_color(f);
  for (size_t i = 0; i < s.sharp_edges.size(); ++i) {
    const auto [a, b] = s.sharp_edges[i];
    if (new_id[a] != no_index && new_id[b] != no_index)
      out.soup.add_sharp_edge(new_id[a], new_id[b],
                              s.sharp_edge_weights.empty() ? infinite_sharpness : s.sharp_edge_weights[i]);
  }
  for (auto [v, w] : s.sharp_vertices)
    if (new_id[v] != no_index) out.soup.sharp_vertices.emplace_back(new_id[v], w);
  for (const RimLine& r : piece.rims) {
    RimLine rim{r.name, {}, r.is_loop, r.color};
    for (Index v : r.vertices) rim.vertices.push_back(new_id[v]);
    out.rims.push_back(std::move(rim));
  }
  return has_color;
}

}  // namespace

void Scene::assemble(Index top) {
  const std::vector<std::string>& shown = shown_deletions();
  const std::unordered_set<std::string> deleted(shown.begin(), shown.end());
  Piece out;
  bool has_color = false;
  for (const Placement& p : placements_)
    if (p.top == top && is_leaf(p)) has_color = append_piece(out, p.world, deleted) || has_color;
  if (!has_color) out.soup.face_attributes.remove(color_attribute);
  SceneInstance& inst = instances_[top];
  if (!is_same_topology(inst.geometry.soup, out.soup) || inst.geometry_version == 0) ++inst.topology_version;
  ++inst.geometry_version;
  inst.geometry = std::move(out);
}

void Scene::assemble_positions(Index top) {
  SceneInstance& inst = instances_[top];
  Index at = 0;
  for (const Placement& p : placements_)
    if (p.top == top && is_leaf(p)) {
      const Buffer<Vec3>& moved = p.world.soup.positions;
      std::copy(moved.begin(), moved.end(), inst.geometry.soup.positions.begin() + at);
      at += Index(moved.size());
    }
  NOME_ASSERT(at == inst.geometry.soup.positions.size());
  ++inst.geometry_version;
}

void Scene::assemble_all() {
  for (Index t = 0; t < instances_.size(); ++t) assemble(t);
}

Buffer<Vec3> Scene::combined_positions() const {
  Buffer<Vec3> out;
  std::size_t count = 0;
  for (const SceneInstance& i : instances_) count += i.geometry.soup.positions.size();
  out.reserve(count);
  for (const SceneInstance& i : instances_)
    out.insert(out.end(), i.geometry.soup.positions.begin(), i.geometry.soup.positions.end());
  return out;
}

Attributes Scene::combined_face_attributes() const {
  Attributes out;
  Index faces = 0;
  for (const SceneInstance& i : instances_) {
    out.append(i.geometry.soup.face_attributes, faces);
    faces += i.geometry.soup.num_faces();
  }
  return out;
}

PolygonSoup Scene::combined_soup() const {
  PolygonSoup out;
  for (const SceneInstance& i : instances_) append_soup(out, i.geometry.soup);
  add_sharpness(out);
  return out;
}

}  // namespace nome::scene
