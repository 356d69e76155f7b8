#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <sstream>
#include <string>

#include "mesh/grid_mesh.hpp"
#include "mesh/sharpness.hpp"
#include "nome/error.hpp"
#include "nome/mesh/mesh.hpp"
#include "support/union_find.hpp"

namespace nome {
namespace {

// Collects topology problems so one error can name several elements.
class Problems {
 public:
  // A problem about `face` (no_index: about a vertex alone).
  void add(std::string message, Index face) {
    if (messages_.size() < max_listed) messages_.push_back({std::move(message), face});
    ++count_;
  }
  void throw_if_any() const {
    if (count_ == 0) return;
    std::ostringstream out;
    out << "build_mesh: not a 2-manifold: " << messages_.front().text;
    for (size_t i = 1; i < messages_.size(); ++i) out << "; " << messages_[i].text;
    if (count_ > messages_.size()) out << "; and " << (count_ - messages_.size()) << " more";
    throw TopologyError(out.str(), messages_);
  }

 private:
  static constexpr size_t max_listed = 8;
  std::vector<TopologyError::Problem> messages_;
  size_t count_ = 0;
};

std::string label(const Names& names, const char* prefix, Index i) {
  if (i < names.size() && !names[i].empty()) return names[i];
  return prefix + std::to_string(i);
}

// Counting sort of `keys` into CSR offsets: offsets[k]..offsets[k+1] will hold the items with key k.
Buffer<Index> csr_offsets(std::span<const Index> keys, Index num_keys) {
  Buffer<Index> offsets(size_t(num_keys) + 1, 0);
  for (Index k : keys) ++offsets[k + 1];
  for (Index k = 0; k < num_keys; ++k) offsets[k + 1] += offsets[k];
  return offsets;
}

// Element names for messages: the soup's own, or `v12` / `f3`.
struct Labels {
  const Names& vertex_names;
  const Names& face_names;
  std::string vertex(Index v) const { return label(vertex_names, "v", v); }
  std::string face(Index f) const { return label(face_names, "f", f); }
};

Index next_corner(const MeshArrays& a, Index c) {
  const Index f = a.corner_face(c);
  return c + 1 == a.face_offsets[f + 1] ? a.face_offsets[f] : c + 1;
}

Index prev_corner(const MeshArrays& a, Index c) {
  const Index f = a.corner_face(c);
  return c == a.face_offsets[f] ? a.face_offsets[f + 1] - 1 : c - 1;
}

void check_arrays(const PolygonSoup& soup) {
  const Index nv = soup.num_vertices(), nf = soup.num_faces();
  if (soup.face_offsets.empty() || soup.face_offsets.front() != 0 ||
      soup.face_offsets.back() != soup.face_vertices.size())
    throw InvalidInputError("build_mesh: face_offsets do not describe face_vertices");
  if (!soup.vertex_names.empty() && soup.vertex_names.size() != nv)
    throw InvalidInputError("build_mesh: vertex_names must be empty or one per vertex");
  if (!soup.face_names.empty() && soup.face_names.size() != nf)
    throw InvalidInputError("build_mesh: face_names must be empty or one per face");
  for (const Attributes::Entry& e : soup.face_attributes.entries())
    if (e.column->size() > nf)
      throw InvalidInputError("build_mesh: face attribute '" + e.name + "' has more values than faces");
}

// Degree, index range, repeated vertices (a stamp array makes the check O(degree)).
void check_faces(const MeshArrays& m, const Labels& labels, Problems& problems) {
  const Index nv = Index(m.positions.size()), nf = Index(m.face_offsets.size() - 1);
  std::vector<Index> stamp(nv, no_index);
  for (Index f = 0; f < nf; ++f) {
    const Index b = m.face_offsets[f], e = m.face_offsets[f + 1];
    if (e < b) throw InvalidInputError("build_mesh: face_offsets are not increasing");
    if (e - b < 3) {
      problems.add(
          "face " + labels.face(f) + " has " + std::to_string(e - b) + " vertices (at least 3 needed)", f);
      continue;
    }
    for (Index c = b; c < e; ++c) {
      const Index v = m.corner_vertices[c];
      if (v >= nv) {
        problems.add("face " + labels.face(f) + " refers to vertex " + std::to_string(v) +
                         " but there are only " + std::to_string(nv) + " vertices",
                     f);
      } else if (stamp[v] == f) {
        problems.add("face " + labels.face(f) + " repeats vertex " + labels.vertex(v), f);
      } else {
        stamp[v] = f;
      }
    }
  }
}

void check_positions(const Buffer<Vec3>& positions, const Labels& labels, Problems& problems) {
  for (size_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      problems.add("vertex " + labels.vertex(Index(i)) + " has a non-finite position", no_index);
  }
}

// Half-edges (corner c runs from its vertex to the next corner's) are bucketed by their smaller end
// vertex; within a bucket a stamp array indexed by the larger end finds the partner. No hashing,
// O(corners).
void find_edges(MeshArrays& m, Index nv, const Labels& labels, Problems& problems) {
  const Index nc = Index(m.corner_vertices.size());
  Buffer<Index> min_vertex(nc);
  for (Index c = 0; c < nc; ++c)
    min_vertex[c] = std::min(m.corner_vertices[c], m.corner_vertices[next_corner(m, c)]);
  const Buffer<Index> bucket_offsets = csr_offsets(min_vertex, nv);
  Buffer<Index> bucket(nc);
  {
    std::vector<Index> fill(bucket_offsets.begin(), bucket_offsets.end() - 1);
    for (Index c = 0; c < nc; ++c) bucket[fill[min_vertex[c]]++] = c;
  }
  min_vertex = {};
  m.corner_edges.assign(nc, no_index);
  m.edges.reserve(nc / 2 + 1);
  std::vector<Index> stamp(nv, no_index);
  for (Index a = 0; a < nv; ++a) {
    for (Index i = bucket_offsets[a]; i < bucket_offsets[a + 1]; ++i) {
      const Index c = bucket[i];
      const Index from = m.corner_vertices[c], to = m.corner_vertices[next_corner(m, c)];
      const Index other = from == a ? to : from;
      Index e = stamp[other];
      if (e == no_index || m.edges[e].vertices[0] + m.edges[e].vertices[1] != a + other ||
          std::min(m.edges[e].vertices[0], m.edges[e].vertices[1]) != a) {
        e = static_cast<Index>(m.edges.size());
        Edge edge;
        edge.vertices = {from, to};
        edge.faces[0] = m.corner_face(c);
        edge.corners[0] = c;
        m.edges.push_back(edge);
        stamp[other] = e;
      } else {
        Edge& edge = m.edges[e];
        if (edge.faces[1] != no_index) {
          problems.add("edge (" + labels.vertex(edge.vertices[0]) + ", " + labels.vertex(edge.vertices[1]) +
                           ") has a third face " + labels.face(m.corner_face(c)) + " besides " +
                           labels.face(edge.faces[0]) + " and " + labels.face(edge.faces[1]),
                       m.corner_face(c));
          continue;
        }
        edge.faces[1] = m.corner_face(c);
        edge.corners[1] = c;
        edge.is_mobius = from == edge.vertices[0];
      }
      m.corner_edges[c] = e;
    }
  }
}

// Edges are numbered by their smaller vertex; renumber them by first appearance in face order so that
// numbering follows the input, as users expect when reading messages and files.
void number_edges_in_face_order(MeshArrays& m) {
  std::vector<Index> order(m.edges.size(), no_index);
  Index next = 0;
  for (Index e : m.corner_edges)
    if (order[e] == no_index) order[e] = next++;
  Buffer<Edge> sorted(m.edges.size());
  for (Index e = 0; e < m.edges.size(); ++e) sorted[order[e]] = m.edges[e];
  m.edges = std::move(sorted);
  for (Index& e : m.corner_edges) e = order[e];
}

// Walks the fan of vertex v (its corners fan_corners[b, b + k)) face to face across edges, from a corner
// whose incoming edge is a border if there is one; false when the faces do not form one fan.
// Its edges go to m.fan_edges from `out` on, which moves past them.
bool walk_fan(MeshArrays& m, Index v, std::span<const Index> corners, std::vector<char>& visited,
              Index& out) {
  const Index b = m.fan_corner_offsets[v], k = Index(corners.size());
  Index start = corners[0];
  Index start_edge = m.corner_edges[prev_corner(m, start)];
  Index borders_here = 0;
  for (const Index c : corners) {
    for (Index e : {m.corner_edges[c], m.corner_edges[prev_corner(m, c)]}) {
      if (m.edges[e].is_boundary() && borders_here++ == 0) {
        start = c;
        start_edge = e;
      }
    }
  }
  Index c = start, entered = start_edge;
  int sign = 1;
  Index count = 0;
  for (;;) {
    visited[c] = 1;
    m.fan_edges[out++] = entered;
    m.fan_corners[b + count] = c;
    m.corner_signs[c] = static_cast<signed char>(sign);
    ++count;
    // Leave through the other edge of this face at v.
    const Index e_out = m.corner_edges[c] == entered ? m.corner_edges[prev_corner(m, c)] : m.corner_edges[c];
    const Edge& edge = m.edges[e_out];
    if (edge.is_boundary()) {
      m.fan_edges[out++] = e_out;
      break;
    }
    const Index f_next = edge.other_face(m.corner_face(c));
    const Index side = edge.faces[0] == f_next ? 0 : 1;
    Index c_next = edge.corners[side];
    if (m.corner_vertices[c_next] != v) c_next = next_corner(m, c_next);
    if (edge.is_mobius) sign = -sign;
    if (c_next == start || visited[c_next] || count == k) break;
    c = c_next;
    entered = e_out;
  }
  return count == k && (borders_here == 0 || borders_here == 2);
}

// Which vertices' fans are walked: all, or in a grid all but the inner ones (written out instead).
std::vector<char> walked_vertices(Index nv, const SoupGrid* grid) {
  std::vector<char> walked(nv, 1);
  if (!grid) return walked;
  for (Index i = 0, v = 0; i < grid->rings; ++i)
    for (Index j = 0; j < grid->ring_points; ++j, ++v) walked[v] = is_grid_inner_vertex(*grid, i, j) ? 0 : 1;
  return walked;
}

// The corners of each walked vertex, in increasing order, at its fan_corner_offsets (a grid's inner
// vertices have theirs from the layout, and only the grid's border faces can hold the others).
Buffer<Index> walked_vertex_corners(const MeshArrays& m, const SoupGrid* grid,
                                    const std::vector<char>& walked) {
  Buffer<Index> list(m.corner_vertices.size());
  std::vector<Index> fill(m.fan_corner_offsets.begin(), m.fan_corner_offsets.end() - 1);
  const auto add = [&](Index c) {
    const Index v = m.corner_vertices[c];
    if (walked[v]) list[fill[v]++] = c;
  };
  if (!grid || grid->is_triangles) {
    for (Index c = 0; c < m.corner_vertices.size(); ++c) add(c);
  } else {
    for_each_grid_border_face(*grid, Index(m.face_offsets.size() - 1), [&](Index f) {
      for (Index c = m.face_offsets[f]; c < m.face_offsets[f + 1]; ++c) add(c);
    });
  }
  return list;
}

// Corners bucketed by vertex, then each vertex's fan walked (or, inside a grid, written out).
void find_fans(MeshArrays& m, Index nv, const SoupGrid* grid, const Labels& labels, Problems& problems) {
  const Index nc = Index(m.corner_vertices.size());
  const std::vector<char> walked = walked_vertices(nv, grid);
  m.fan_corner_offsets = csr_offsets(m.corner_vertices, nv);
  const Buffer<Index> vertex_corner_list = walked_vertex_corners(m, grid, walked);
  resize_for_overwrite(m.fan_corners, nc);
  resize_for_overwrite(m.corner_signs, nc);  // each corner is in one fan, which writes its sign
  m.fan_edge_offsets.assign(size_t(nv) + 1, 0);
  resize_for_overwrite(m.fan_edges, size_t(nc) + nv);  // a fan has as many edges as corners, or one more
  Index out = 0;
  std::vector<char> visited(nc, 0);
  std::array<Index, 4> corners, edges;
  const Index points = grid ? grid->ring_points : 1;
  // (i, j): v's ring and point in the grid.
  for (Index v = 0, i = 0, j = 0; v < nv; ++v, j = j + 1 == points ? 0 : j + 1, i += j == 0 ? 1 : 0) {
    const Index b = m.fan_corner_offsets[v], k = m.fan_corner_offsets[v + 1] - b;
    if (k == 0) {
      m.fan_edge_offsets[v + 1] = out;
      continue;
    }
    if (!walked[v]) {
      find_grid_inner_fan(m, *grid, i, j, corners, edges);
      for (Index t = 0; t < 4; ++t) {
        m.fan_corners[b + t] = corners[t];
        m.corner_signs[corners[t]] = 1;
        m.fan_edges[out + t] = edges[t];
      }
      out += 4;
    } else if (!walk_fan(m, v, std::span<const Index>(vertex_corner_list.data() + b, k), visited, out)) {
      problems.add("vertex " + labels.vertex(v) + ": its " + std::to_string(k) +
                       " faces do not form one fan (the surface touches itself there)",
                   m.corner_face(vertex_corner_list[b]));
    }
    m.fan_edge_offsets[v + 1] = out;
  }
  m.fan_edges.resize(out);
}

std::atomic<std::uint64_t> meshes_built{0};
std::atomic<std::uint64_t> grid_meshes_built{0};

}  // namespace

std::uint64_t build_mesh_count() {
  return meshes_built.load(std::memory_order_relaxed);
}

std::uint64_t build_mesh_grid_count() {
  return grid_meshes_built.load(std::memory_order_relaxed);
}

Mesh build_mesh(PolygonSoup soup) {
  return build_mesh_from(soup);
}

Mesh build_mesh_from(PolygonSoup& soup) {
  meshes_built.fetch_add(1, std::memory_order_relaxed);
  check_arrays(soup);
  Mesh m;
  m.vertex_names_ = std::move(soup.vertex_names);
  m.face_names_ = std::move(soup.face_names);
  m.arrays_.face_attributes = std::move(soup.face_attributes);
  m.arrays_.positions = std::move(soup.positions);
  m.arrays_.face_offsets = std::move(soup.face_offsets);
  m.arrays_.corner_vertices = std::move(soup.face_vertices);
  const Labels labels{m.vertex_names_, m.face_names_};
  const Index nv = m.num_vertices();
  try {
    // A grid layout, checked against the faces, gives the edges without the search (and the faces' checks).
    const bool is_grid = soup.grid && find_grid_edges(m.arrays_, *soup.grid);
    if (is_grid) grid_meshes_built.fetch_add(1, std::memory_order_relaxed);
    Problems problems;
    if (!is_grid) check_faces(m.arrays_, labels, problems);
    check_positions(m.arrays_.positions, labels, problems);
    problems.throw_if_any();
    m.find_corner_faces();
    if (!is_grid) {
      find_edges(m.arrays_, nv, labels, problems);
      problems.throw_if_any();
      number_edges_in_face_order(m.arrays_);
    }
    find_fans(m.arrays_, nv, is_grid ? &*soup.grid : nullptr, labels, problems);
    problems.throw_if_any();
    apply_soup_features(m, soup);
    m.find_boundary_loops();
    if (is_grid) {  // bands join every ring to the next: one component
      m.arrays_.face_components.assign(m.num_faces(), 0);
      m.arrays_.num_components = 1;
    } else {
      m.find_components();
    }
  } catch (...) {
    soup.vertex_names = std::move(m.vertex_names_);
    soup.face_names = std::move(m.face_names_);
    soup.face_attributes = std::move(m.arrays_.face_attributes);
    soup.positions = std::move(m.arrays_.positions);
    soup.face_offsets = std::move(m.arrays_.face_offsets);
    soup.face_vertices = std::move(m.arrays_.corner_vertices);
    throw;
  }
  return m;
}

void Mesh::find_corner_faces() {
  Buffer<Index>& corner_faces = arrays_.corner_faces;
  const Buffer<Index>& offsets = arrays_.face_offsets;
  bool is_quads = true;
  for (Index f = 0; f <= num_faces(); ++f) is_quads &= offsets[f] == 4 * f;
  if (is_quads) {
    Buffer<Index>().swap(corner_faces);  // its block goes back for other arrays
    return;
  }
  resize_for_overwrite(corner_faces, num_corners());
  for (Index f = 0; f < num_faces(); ++f)
    std::fill(corner_faces.begin() + face_first_corner(f), corner_faces.begin() + arrays_.face_offsets[f + 1],
              f);
}

void Mesh::find_boundary_loops() {
  // From a border edge, step to the other border edge at its far vertex (the last edge of that
  // vertex's fan if we came in by the first, and vice versa).
  loop_offsets_.assign(1, 0);
  loop_edges_.clear();
  loop_vertices_.clear();
  // The border edges are the two ends of the border vertices' fans: found from the fan offsets, a seventh
  // of the bytes of the edge records (and nothing more to do for a closed mesh, such as every offset).
  std::vector<Index> border;
  for (Index v = 0; v < num_vertices(); ++v)
    if (is_boundary_vertex(v)) {
      border.push_back(vertex_edges(v).front());
      border.push_back(vertex_edges(v).back());
    }
  if (border.empty()) return;
  // Loops in the order of their smallest edge, each starting there: as a scan of the edges would find them.
  std::sort(border.begin(), border.end());
  std::vector<char> used(arrays_.edges.size(), 0);
  for (Index e0 : border) {
    if (used[e0]) continue;
    Index e = e0, v = arrays_.edges[e0].vertices[0];
    do {
      used[e] = 1;
      loop_edges_.push_back(e);
      loop_vertices_.push_back(v);
      v = arrays_.edges[e].other_vertex(v);
      const auto fan = vertex_edges(v);
      e = fan.front() == e ? fan.back() : fan.front();
    } while (e != e0);
    loop_offsets_.push_back(static_cast<Index>(loop_edges_.size()));
  }
}

void Mesh::find_components() {
  // Faces joined across each interior edge in one pass over the edges (faster than a walk, whose steps
  // jump between faces and edges), then numbered by their smallest face, as a walk from face 0 would.
  const Index nf = num_faces();
  UnionFind sets(nf);
  for (const Edge& e : arrays_.edges)
    if (!e.is_boundary()) sets.unite(e.faces[0], e.faces[1]);
  std::vector<Index> number(nf, no_index);
  resize_for_overwrite(arrays_.face_components, nf);
  arrays_.num_components = 0;
  for (Index f = 0; f < nf; ++f) {
    Index& n = number[sets.find(f)];
    if (n == no_index) n = arrays_.num_components++;
    arrays_.face_components[f] = n;
  }
}

Index Mesh::vertex_component(Index v) const {
  const auto corners = vertex_corners(v);
  return corners.empty() ? no_index : arrays_.face_components[corner_face(corners.front())];
}

std::string Mesh::vertex_label(Index v) const {
  return label(vertex_names_, "v", v);
}
std::string Mesh::face_label(Index f) const {
  return label(face_names_, "f", f);
}

PolygonSoup to_soup(const Mesh& mesh) {
  PolygonSoup soup;
  soup.positions = mesh.positions();
  soup.face_offsets = mesh.face_offsets();
  soup.face_vertices = mesh.corner_vertices();
  soup.vertex_names = mesh.vertex_names();
  soup.face_names = mesh.face_names();
  soup.face_attributes = mesh.face_attributes();
  add_features_to_soup(mesh, soup);
  return soup;
}

Mesh transformed(const Mesh& mesh, const glm::dmat4& matrix) {
  Mesh out = mesh;
  for (Vec3& p : out.positions()) p = Vec3(matrix * glm::dvec4(p, 1.0));
  return out;
}

}  // namespace nome
