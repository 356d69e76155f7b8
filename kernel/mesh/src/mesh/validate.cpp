#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"

namespace nome {
namespace {

class Violations {
 public:
  void add(std::string what) {
    if (list_.size() < max_listed) list_.push_back(std::move(what));
    ++count_;
  }
  std::vector<std::string> take() {
    if (count_ > list_.size()) list_.push_back("and " + std::to_string(count_ - list_.size()) + " more");
    return std::move(list_);
  }
  bool empty() const { return count_ == 0; }

 private:
  static constexpr size_t max_listed = 50;
  std::vector<std::string> list_;
  size_t count_ = 0;
};

std::string str(Index i) {
  return i == no_index ? std::string("none") : std::to_string(i);
}

// Array sizes and CSR offsets: everything else indexes through them, so later checks need them sound.
void check_arrays(const Mesh& m, Violations& out) {
  const auto& fo = m.face_offsets();
  const Index nc = Index(m.corner_vertices().size());
  if (fo.empty() || fo.front() != 0 || fo.back() != nc) out.add("face_offsets do not span the corners");
  for (size_t f = 0; f + 1 < fo.size(); ++f)
    if (fo[f + 1] < fo[f] + 3) out.add("face " + std::to_string(f) + " has fewer than 3 corners");
  bool is_quads = true;
  for (size_t f = 0; f < fo.size(); ++f) is_quads &= fo[f] == 4 * f;
  if (m.corner_edges().size() != nc || m.corner_faces().size() != (is_quads ? 0 : nc) ||
      m.corner_signs().size() != nc)
    out.add("corner arrays differ in size");
  for (Index c = 0; c < nc; ++c)
    if (m.corner_vertices()[c] >= m.num_vertices() || m.corner_edges()[c] >= m.num_edges())
      out.add("corner " + str(c) + " refers to a missing vertex or edge");
  const size_t nv1 = size_t(m.num_vertices()) + 1;
  for (const auto* offsets : {&m.fan_corner_offsets(), &m.fan_edge_offsets()}) {
    if (offsets->size() != nv1 || offsets->front() != 0)
      out.add("fan offsets do not have one entry per vertex");
    for (size_t i = 0; i + 1 < offsets->size(); ++i)
      if ((*offsets)[i + 1] < (*offsets)[i]) out.add("fan offsets decrease at vertex " + std::to_string(i));
  }
  if (m.fan_corner_offsets().back() != m.fan_corners().size() ||
      m.fan_edge_offsets().back() != m.fan_edges().size())
    out.add("fan offsets do not span the fan lists");
  if (m.fan_corners().size() != nc) out.add("the fans do not list every corner once");
  for (const Edge& e : m.edges())
    for (int i = 0; i < 2; ++i)
      if (e.vertices[i] >= m.num_vertices() || (i == 0 && e.corners[0] >= nc) ||
          (e.corners[i] != no_index && e.corners[i] >= nc))
        out.add("an edge refers to a missing vertex or corner");
}

void check_corners_and_edges(const Mesh& m, Violations& out) {
  for (Index f = 0; f < m.num_faces(); ++f)
    for (Index c = m.face_offsets()[f]; c < m.face_offsets()[f + 1]; ++c)
      if (m.corner_face(c) != f) out.add("corner " + str(c) + " does not name its face " + str(f));
  for (Index c = 0; c < m.num_corners(); ++c) {
    const Edge& e = m.edge(m.corner_edge(c));
    if (e.corners[0] != c && e.corners[1] != c)
      out.add("corner " + str(c) + " is not listed by its edge " + str(m.corner_edge(c)));
  }
  for (Index i = 0; i < m.num_edges(); ++i) {
    const Edge& e = m.edge(i);
    const std::string name = "edge " + str(i);
    for (int side = 0; side < 2; ++side) {
      const Index c = e.corners[side];
      if (c == no_index) {
        if (side == 0 || e.faces[1] != no_index) out.add(name + " lacks a corner for a face");
        continue;
      }
      if (m.corner_edge(c) != i) out.add(name + ": its corner " + str(c) + " runs along another edge");
      if (m.corner_face(c) != e.faces[side])
        out.add(name + ": corner and face disagree on side " + str(side));
      const Index from = m.corner_vertex(c), to = m.corner_vertex(m.next_corner(c));
      const bool forward = from == e.vertices[0] && to == e.vertices[1];
      const bool backward = from == e.vertices[1] && to == e.vertices[0];
      if (!forward && !backward) out.add(name + ": corner " + str(c) + " joins other vertices");
      if (side == 0 && !forward) out.add(name + ": vertices are not in the direction of its first face");
      if (side == 1 && forward != e.is_mobius) out.add(name + ": Möbius flag disagrees with the directions");
    }
    if (e.faces[1] == no_index && e.is_mobius) out.add(name + " is a Möbius border edge");
  }
}

void check_fans(const Mesh& m, Violations& out) {
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const auto corners = m.vertex_corners(v);
    const auto edges = m.vertex_edges(v);
    const std::string name = "vertex " + str(v);
    if (corners.empty()) {
      if (!edges.empty()) out.add(name + " has edges but no faces");
      continue;
    }
    const bool boundary = m.edge(edges.front()).is_boundary();
    if (edges.size() != corners.size() + (boundary ? 1 : 0)) {
      out.add(name + ": fan has " + std::to_string(edges.size()) + " edges for " +
              std::to_string(corners.size()) + " corners");
      continue;
    }
    if (boundary && !m.edge(edges.back()).is_boundary())
      out.add(name + ": border fan does not end on a border");
    if (m.corner_sign(corners.front()) != 1) out.add(name + ": first corner's sign is not +1");
    for (size_t i = 0; i < corners.size(); ++i) {
      const Index c = corners[i];
      if (m.corner_vertex(c) != v) out.add(name + ": fan lists corner " + str(c) + " of another vertex");
      const Index before = edges[i], after = edges[(i + 1) % edges.size()];
      const Index in = m.corner_edge(m.prev_corner(c)), here = m.corner_edge(c);
      if (!((before == in && after == here) || (before == here && after == in)))
        out.add(name + ": fan is out of order at corner " + str(c));
      if (i > 0 && i + 1 < edges.size() && m.edge(edges[i]).is_boundary())
        out.add(name + ": border edge inside the fan");
      const Index next = corners[(i + 1) % corners.size()];
      if ((i + 1 < corners.size() || !boundary) &&
          m.corner_sign(next) != (m.edge(after).is_mobius ? -1 : 1) * m.corner_sign(c))
        out.add(name + ": sign does not flip exactly across Möbius edges at corner " + str(c));
    }
  }
}

void check_loops_and_components(const Mesh& m, Violations& out) {
  std::vector<char> in_loop(m.num_edges(), 0);
  for (Index l = 0; l < m.num_boundary_loops(); ++l) {
    const auto es = m.loop_edges(l);
    const auto vs = m.loop_vertices(l);
    for (size_t i = 0; i < es.size(); ++i) {
      const Edge& e = m.edge(es[i]);
      const Index a = vs[i], b = vs[(i + 1) % vs.size()];
      if (!e.is_boundary()) out.add("loop " + str(l) + " holds an interior edge");
      if (!((e.vertices[0] == a && e.vertices[1] == b) || (e.vertices[0] == b && e.vertices[1] == a)))
        out.add("loop " + str(l) + " is not a chain at edge " + str(es[i]));
      ++in_loop[es[i]];
    }
  }
  for (Index i = 0; i < m.num_edges(); ++i)
    if (m.edge(i).is_boundary() != (in_loop[i] == 1))
      out.add("edge " + str(i) + " is in the wrong number of loops");
  for (const Edge& e : m.edges())
    if (e.faces[1] != no_index && m.face_component(e.faces[0]) != m.face_component(e.faces[1]))
      out.add("faces " + str(e.faces[0]) + " and " + str(e.faces[1]) + " share an edge across components");
  for (Index f = 0; f < m.num_faces(); ++f)
    if (m.face_component(f) >= m.num_components()) out.add("face " + str(f) + " has no component");
}

}  // namespace

std::vector<std::string> validate(const Mesh& mesh) {
  Violations out;
  check_arrays(mesh, out);
  if (out.empty()) check_corners_and_edges(mesh, out);
  if (out.empty()) check_fans(mesh, out);
  if (out.empty()) check_loops_and_components(mesh, out);
  return out.take();
}

}  // namespace nome
