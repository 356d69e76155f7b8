// Hierarchical names (`kb_t3_hc2`) looked up by any unique suffix that starts after a `_` (report 6.2:
// `fun3_hc3` names vertex hc3 of instance fun3, whichever group holds it).
#include <algorithm>

#include "nome/scene/parser.hpp"
#include "nome/scene/scene.hpp"

namespace nome::scene {
namespace {

// Every suffix of a hierarchical name that starts after a `_`, the name itself included.
template <typename F>
void for_each_suffix(const std::string& name, F f) {
  f(name);
  for (size_t i = name.find('_'); i != std::string::npos; i = name.find('_', i + 1))
    if (i + 1 < name.size()) f(name.substr(i + 1));
}

}  // namespace

void Scene::build_vertex_index() const {
  vertex_suffixes_.clear();
  is_vertex_index_current_ = true;
  for (Index p = 0; p < placements_.size(); ++p) {
    if (!is_leaf(placements_[p]) || placements_[p].references) continue;
    const auto& names = placements_[p].world.soup.vertex_names;
    for (Index v = 0; v < names.size(); ++v)
      for_each_suffix(names[v], [&](const std::string& s) { vertex_suffixes_[s].push_back({p, v}); });
  }
}

std::string Scene::without_definition_names(std::string name) const {
  for (const auto& [definition, _] : definitions_) {
    const std::string segment = "_" + definition + "_";
    for (size_t at = name.find(segment); at != std::string::npos; at = name.find(segment, at))
      name.erase(at, definition.size() + 1);
  }
  return name;
}

const Scene::VertexRef* Scene::lookup_vertex(const Name& name, std::vector<Diagnostic>& errors) const {
  if (!is_vertex_index_current_) build_vertex_index();
  auto it = vertex_suffixes_.find(name.text);
  if (it == vertex_suffixes_.end()) it = vertex_suffixes_.find(without_definition_names(name.text));
  if (it != vertex_suffixes_.end() && it->second.size() == 1) return &it->second.front();
  const auto full_name = [&](const VertexRef& r) -> std::string {
    return placements_[r.placement].world.soup.vertex_names[r.vertex];
  };
  if (it == vertex_suffixes_.end()) {
    std::vector<std::string> names;
    for (const auto& [s, refs] : vertex_suffixes_)
      if (refs.size() == 1 && full_name(refs[0]) == s) names.push_back(s);
    std::sort(names.begin(), names.end());
    errors.push_back(
        located(name.location, "unknown vertex '" + name.text + "'" + did_you_mean(name.text, names)));
  } else {
    std::string list;
    for (size_t i = 0; i < it->second.size() && i < 6; ++i)
      list += (i ? ", " : "") + full_name(it->second[i]);
    if (it->second.size() > 6) list += ", ...";
    errors.push_back(located(name.location, "ambiguous vertex name '" + name.text + "': " +
                                                std::to_string(it->second.size()) + " candidates: " + list));
  }
  return nullptr;
}

std::string Scene::resolve_vertex_name(const std::string& name) const {
  std::vector<Diagnostic> errors;
  const VertexRef* ref = lookup_vertex({normalize_name(name), {}}, errors);
  if (!ref) throw SceneError(std::move(errors));
  return placements_[ref->placement].world.soup.vertex_names[ref->vertex];
}

std::vector<ParameterId> Scene::parameters_of_vertex(const std::string& name) const {
  if (!is_vertex_index_current_) build_vertex_index();
  const auto it = vertex_suffixes_.find(name);
  if (it == vertex_suffixes_.end() || it->second.size() != 1) return {};
  return placements_[it->second.front().placement].reads;
}

void Scene::resolve_sharp_edits(std::vector<Diagnostic>& errors) {
  edits_.sharp.clear();
  for (const SharpEdgeDecl& edge : ast_.sharp_edges) {
    const VertexRef* a = lookup_vertex(edge.edge.vertices[0], errors);
    const VertexRef* b = lookup_vertex(edge.edge.vertices[1], errors);
    if (a && b)
      edits_.sharp.push_back({placements_[a->placement].world.soup.vertex_names[a->vertex],
                              placements_[b->placement].world.soup.vertex_names[b->vertex], edge.weight});
  }
}

void Scene::resolve_consolidated(std::vector<Diagnostic>& errors) {
  edits_.consolidated.clear();
  const size_t first_error = errors.size();
  for (const NamedFace& face : ast_.consolidated_faces) {
    std::vector<std::string> names;
    for (const Name& n : face.vertices) {
      if (options_.shows_edits)
        names.push_back(n.text);
      else if (const VertexRef* ref = lookup_vertex(n, errors))
        names.push_back(placements_[ref->placement].world.soup.vertex_names[ref->vertex]);
    }
    edits_.consolidated.push_back(std::move(names));
  }
  // The names are located in the file that gave them: the scene, or an .anom file's working mesh.
  if (!consolidated_file_.empty())
    for (size_t e = first_error; e < errors.size(); ++e) errors[e].file = consolidated_file_;
}

// Faces are deleted by a unique suffix of their hierarchical names too.
std::vector<std::string> Scene::resolve_deleted(const std::vector<Name>& names,
                                                std::vector<Diagnostic>& errors) {
  if (names.empty()) return {};
  std::unordered_map<std::string, std::vector<std::string>> suffixes;
  std::vector<std::string> all;
  for (const Placement& p : placements_)
    for (const std::string& f : p.world.soup.face_names) {
      all.push_back(f);
      for_each_suffix(f, [&](const std::string& s) { suffixes[s].push_back(f); });
    }
  std::vector<std::string> out;
  for (const Name& n : names) {
    const auto it = suffixes.find(n.text);
    if (it == suffixes.end()) {
      errors.push_back(located(n.location, "unknown face '" + n.text + "'" + did_you_mean(n.text, all)));
    } else if (it->second.size() > 1) {
      std::string list;
      for (size_t i = 0; i < it->second.size() && i < 6; ++i) list += (i ? ", " : "") + it->second[i];
      errors.push_back(located(n.location, "ambiguous face name '" + n.text + "': " +
                                               std::to_string(it->second.size()) + " candidates: " + list));
    } else {
      out.push_back(it->second.front());
    }
  }
  return out;
}

}  // namespace nome::scene
