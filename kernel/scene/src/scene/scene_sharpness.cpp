// The scene's creases and corners over instances' vertices: the top-level `sharp` statements (a border is
// walked on its instance's own surface, so it follows a slider that changes its vertex count) and the
// viewer's sharp edits, marked by name on the combined soup, edits last so that they win.
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include "nome/mesh/mesh.hpp"
#include "nome/scene/scene.hpp"
#include "scene/index_sets.hpp"

namespace nome::scene {
namespace {

// The vertices of the border through vertex `v`, in order and closed (v first and last); empty when v is
// on no border (or the piece is no 2-manifold, which has no border to name).
std::vector<Index> border_through(const PolygonSoup& piece, Index v) {
  PolygonSoup faces;
  faces.positions = piece.positions;
  faces.face_offsets = piece.face_offsets;
  faces.face_vertices = piece.face_vertices;
  Mesh mesh;
  try {
    mesh = build_mesh(std::move(faces));
  } catch (const Error&) {
    return {};
  }
  for (Index l = 0; l < mesh.num_boundary_loops(); ++l) {
    const std::span<const Index> loop = mesh.loop_vertices(l);
    const auto at = std::find(loop.begin(), loop.end(), v);
    if (at == loop.end()) continue;
    std::vector<Index> out(at, loop.end());
    out.insert(out.end(), loop.begin(), at);
    out.push_back(v);
    return out;
  }
  return {};
}

// The combined soup's vertices by name and its faces' edges: where named sharp marks land.
struct NamedEdges {
  std::unordered_map<std::string, Index> ids;
  std::unordered_set<std::uint64_t> edges;

  static std::uint64_t key(Index u, Index w) {
    return (std::uint64_t(std::min(u, w)) << 32) | std::max(u, w);
  }
  explicit NamedEdges(const PolygonSoup& soup) {
    for (Index v = 0; v < soup.vertex_names.size(); ++v) ids.emplace(soup.vertex_names[v], v);
    for (Index f = 0; f < soup.num_faces(); ++f) {
      const Index b = soup.face_offsets[f], e = soup.face_offsets[f + 1];
      for (Index c = b; c < e; ++c)
        edges.insert(key(soup.face_vertices[c], soup.face_vertices[c + 1 == e ? b : c + 1]));
    }
  }
  Index id(const std::string& name) const {
    const auto it = ids.find(name);
    return it == ids.end() ? no_index : it->second;
  }
  // Marks the edge when both names are vertices and it is an edge of a face (a slider may have taken it).
  bool mark(PolygonSoup& soup, const std::string& a, const std::string& b, float weight) const {
    const Index u = id(a), w = id(b);
    if (u == no_index || w == no_index || !edges.count(key(u, w))) return false;
    soup.add_sharp_edge(u, w, weight);
    return true;
  }
};

// A top-level `sharp`'s chain, corner, or (given its instance's piece) the border through its vertex.
void mark_text_sharp(PolygonSoup& soup, const NamedEdges& named, const std::vector<std::string>& vertices,
                     const PolygonSoup* border_piece, float weight) {
  if (border_piece) {
    const std::vector<std::string>& names = border_piece->vertex_names;
    const auto at = std::find(names.begin(), names.end(), vertices[0]);
    if (at == names.end()) return;
    const std::vector<Index> loop = border_through(*border_piece, Index(at - names.begin()));
    for (size_t k = 0; k + 1 < loop.size(); ++k) named.mark(soup, names[loop[k]], names[loop[k + 1]], weight);
  } else if (vertices.size() == 1) {
    if (const Index v = named.id(vertices[0]); v != no_index) soup.sharp_vertices.emplace_back(v, weight);
  } else {
    for (size_t k = 0; k + 1 < vertices.size(); ++k) named.mark(soup, vertices[k], vertices[k + 1], weight);
  }
}

}  // namespace

void Scene::check_weight(const SharpDecl& s, std::vector<Diagnostic>& errors, ParameterReads* reads) const {
  if (!s.weight) return;
  try {
    if (const double w = evaluate(ast_.expressions, *s.weight, values_, reads); w < 0)
      errors.push_back(located(s.weight->location, "a sharpness is 0 or more, found " + format_number(w)));
  } catch (const EvaluationError& e) {
    errors.push_back(located(e.where(), e.what()));
  }
}

void Scene::check_text_sharp_weights(std::vector<Diagnostic>& errors) const {
  for (const SharpDecl& s : ast_.sharps) check_weight(s, errors, nullptr);
}

void Scene::resolve_text_sharps(std::vector<Diagnostic>& errors) {
  text_sharps_.clear();
  text_sharp_reads_.clear();
  if (ast_.sharps.empty()) return;
  const NamedEdges named(combined_soup());
  for (Index i = 0; i < ast_.sharps.size(); ++i) {
    const SharpDecl& s = ast_.sharps[i];
    check_weight(s, errors, &text_sharp_reads_);
    TextSharp t{i, {}, no_index};
    for (const Name& n : s.vertices) {
      const VertexRef* ref = lookup_vertex(n, errors);
      if (!ref) continue;
      const Placement& p = placements_[ref->placement];
      t.vertices.push_back(p.world.soup.vertex_names[ref->vertex]);
      if (s.is_border && border_through(p.world.soup, ref->vertex).empty())
        errors.push_back(located(n.location, "'" + n.text + "' is on no border of instance " + p.path));
      if (s.is_border) text_sharps_.push_back({i, {t.vertices.back()}, ref->placement});
      const size_t k = t.vertices.size();
      if (!s.is_border && k > 1 && named.id(t.vertices[k - 2]) != no_index &&
          !named.edges.count(NamedEdges::key(named.id(t.vertices[k - 2]), named.id(t.vertices[k - 1]))))
        errors.push_back(located(n.location, "(" + t.vertices[k - 2] + ", " + t.vertices[k - 1] +
                                                 ") is no edge of the scene's faces"));
    }
    if (!s.is_border && t.vertices.size() == s.vertices.size()) text_sharps_.push_back(std::move(t));
  }
  sort_unique(text_sharp_reads_);
}

void Scene::add_sharpness(PolygonSoup& soup) const {
  const std::vector<NamedSharpEdge>& sharp_edits = shown_sharp_edits();
  if (text_sharps_.empty() && sharp_edits.empty()) return;
  const NamedEdges named(soup);
  for (const TextSharp& t : text_sharps_) {
    const SharpDecl& s = ast_.sharps[t.decl];
    const float weight = s.weight ? float(std::max(0.0, current(*s.weight))) : infinite_sharpness;
    mark_text_sharp(soup, named, t.vertices,
                    t.placement == no_index ? nullptr : &placements_[t.placement].world.soup, weight);
  }
  for (const NamedSharpEdge& e : sharp_edits) named.mark(soup, e.a, e.b, e.weight);
}

}  // namespace nome::scene
