#include "nome/edit/document.hpp"

#include <algorithm>
#include <atomic>
#include <span>
#include <unordered_set>

#include "nome/error.hpp"

namespace nome {
namespace {

std::uint64_t edge_key(Index u, Index w) {
  return (std::uint64_t(std::min(u, w)) << 32) | std::max(u, w);
}

template <typename T>
void erase_at(std::vector<T>& list, const std::vector<std::pair<size_t, T>>& removed) {
  for (auto it = removed.rbegin(); it != removed.rend(); ++it) list.erase(list.begin() + long(it->first));
}

// Gives the edge (a, b) its weight among `marked`: 0 takes it out.
void mark_sharp(std::vector<NamedSharpEdge>& marked, const std::string& a, const std::string& b,
                float weight) {
  const auto at = std::find_if(marked.begin(), marked.end(),
                               [&](const NamedSharpEdge& e) { return e.a == a && e.b == b; });
  if (at == marked.end()) {
    if (weight > 0) marked.push_back({a, b, weight});
  } else if (weight > 0) {
    at->weight = weight;
  } else {
    marked.erase(at);
  }
}

std::string sharp_outcome(size_t count, float weight) {
  const std::string what = weight == 0                    ? "marked smooth"
                           : weight >= infinite_sharpness ? "marked sharp"
                                                          : "given sharpness " + sharpness_text(weight);
  return std::to_string(count) + (count == 1 ? " edge " : " edges ") + what;
}

template <typename T>
void insert_at(std::vector<T>& list, const std::vector<std::pair<size_t, T>>& removed) {
  for (const auto& [at, item] : removed) list.insert(list.begin() + long(at), item);
}

}  // namespace

Document::Document(PolygonSoup scene_geometry) {
  set_scene_geometry(std::move(scene_geometry));
}

void Document::set_scene_geometry(PolygonSoup geometry) {
  scene_ = std::move(geometry);
  index_scene();
  note_new_topology();
}

void Document::update_scene_geometry(PolygonSoup geometry) {
  const PolygonSoup& now = scene_;
  const bool same_polygons =
      geometry.face_offsets == now.face_offsets && geometry.face_vertices == now.face_vertices &&
      geometry.positions.size() == now.positions.size() && geometry.vertex_names == now.vertex_names &&
      geometry.face_names == now.face_names && geometry.sharp_edges == now.sharp_edges &&
      geometry.sharp_edge_weights == now.sharp_edge_weights &&
      geometry.sharp_vertices == now.sharp_vertices && geometry.hole_faces == now.hole_faces;
  if (!same_polygons) return set_scene_geometry(std::move(geometry));
  scene_.face_origins = std::move(geometry.face_origins);
  if (!(geometry.face_attributes == scene_.face_attributes))
    set_scene_face_attributes(std::move(geometry.face_attributes));
  move_scene_vertices(std::move(geometry.positions));
}

void Document::move_scene_vertices(Buffer<Vec3> positions) {
  if (positions.size() != scene_.positions.size())
    throw InvalidInputError("Document::move_scene_vertices: " + std::to_string(positions.size()) +
                            " positions for " + std::to_string(scene_.positions.size()) + " vertices");
  scene_.positions = std::move(positions);
}

void Document::index_scene() {
  vertex_ids_.clear();
  face_ids_.clear();
  scene_edge_faces_.clear();
  for (Index v = 0; v < scene_.vertex_names.size(); ++v) vertex_ids_.emplace(scene_.vertex_names[v], v);
  for (Index f = 0; f < scene_.face_names.size(); ++f) face_ids_.emplace(scene_.face_names[f], f);
  for (Index f = 0; f < scene_.num_faces(); ++f) {
    const Index b = scene_.face_offsets[f], e = scene_.face_offsets[f + 1];
    for (Index c = b; c < e; ++c)
      scene_edge_faces_[edge_key(scene_.face_vertices[c], scene_.face_vertices[c + 1 == e ? b : c + 1])]
          .push_back(f);
  }
}

void Document::load_edits(const std::vector<std::vector<std::string>>& consolidated,
                          std::vector<std::string> deleted, std::vector<NamedSharpEdge> sharp_edges) {
  temporary_.clear();
  sharp_ = std::move(sharp_edges);
  consolidated_.clear();
  for (const auto& vertices : consolidated) consolidated_.push_back({next_face_name(), vertices});
  deleted_ = std::move(deleted);
  history_.clear();
  done_ = 0;
  note_new_topology();
}

void Document::note_new_topology() {
  // Numbered across all documents: a pipeline that goes on to another document never takes its first
  // version for the one it has.
  static std::atomic<std::uint64_t> versions{0};
  input_topology_version_ = ++versions;
  ++input_attributes_version_;
  edited_vertex_sources_ = edited_sources(consolidated_);
  const std::vector<Index> temporary = edited_sources(temporary_);
  edited_vertex_sources_.insert(edited_vertex_sources_.end(), temporary.begin(), temporary.end());
}

Index Document::vertex_id(const std::string& name) const {
  const auto it = vertex_ids_.find(name);
  return it == vertex_ids_.end() ? no_index : it->second;
}

std::vector<Document::EdgeUse> Document::uses_of(Index u, Index w) const {
  std::vector<EdgeUse> uses;
  auto runs_up = [](Index from, Index to) { return from < to; };
  if (const auto it = scene_edge_faces_.find(edge_key(u, w)); it != scene_edge_faces_.end()) {
    for (Index f : it->second) {
      const std::string name = f < scene_.face_names.size() ? scene_.face_names[f] : "f" + std::to_string(f);
      if (std::find(deleted_.begin(), deleted_.end(), name) != deleted_.end()) continue;
      const Index b = scene_.face_offsets[f], e = scene_.face_offsets[f + 1];
      for (Index c = b; c < e; ++c) {
        const Index from = scene_.face_vertices[c], to = scene_.face_vertices[c + 1 == e ? b : c + 1];
        if (edge_key(from, to) == edge_key(u, w)) uses.push_back({name, runs_up(from, to)});
      }
    }
  }
  for (const auto* list : {&temporary_, &consolidated_}) {
    for (const EditedFace& face : *list) {
      for (size_t k = 0; k < face.vertices.size(); ++k) {
        const Index from = vertex_id(face.vertices[k]),
                    to = vertex_id(face.vertices[(k + 1) % face.vertices.size()]);
        if (from != no_index && to != no_index && edge_key(from, to) == edge_key(u, w))
          uses.push_back({face.name, runs_up(from, to)});
      }
    }
  }
  return uses;
}

std::string Document::check_face(EditedFace& face, const std::vector<EditedFace>& pending, bool orient,
                                 int* votes_out) const {
  const size_t n = face.vertices.size();
  if (n < 3) return "a polygon needs at least 3 vertices, " + std::to_string(n) + " selected";
  std::vector<Index> ids;
  for (const std::string& name : face.vertices) {
    const Index v = vertex_id(name);
    if (v == no_index) return "no vertex named " + name;
    if (std::find(ids.begin(), ids.end(), v) != ids.end()) return "vertex " + name + " is selected twice";
    ids.push_back(v);
  }
  int votes = 0;
  for (size_t k = 0; k < n; ++k) {
    const Index u = ids[k], w = ids[(k + 1) % n];
    std::vector<EdgeUse> uses = uses_of(u, w);
    for (const EditedFace& other : pending)
      for (size_t i = 0; i < other.vertices.size(); ++i) {
        const Index from = vertex_id(other.vertices[i]),
                    to = vertex_id(other.vertices[(i + 1) % other.vertices.size()]);
        if (edge_key(from, to) == edge_key(u, w)) uses.push_back({other.name, from < to});
      }
    if (uses.size() >= 2)
      return "the edge (" + face.vertices[k] + ", " + face.vertices[(k + 1) % n] +
             ") already has two faces (" + uses[0].face + ", " + uses[1].face + ")";
    // A neighbour running the same way along the shared edge disagrees with this orientation.
    if (uses.size() == 1) votes += uses[0].runs_up == (u < w) ? -1 : 1;
  }
  if (orient && votes < 0) std::reverse(face.vertices.begin(), face.vertices.end());
  if (votes_out) *votes_out = votes;
  return {};
}

EditOutcome Document::add_polygon(const std::vector<std::string>& vertex_names) {
  EditedFace face{{}, vertex_names};
  if (std::string refused = check_face(face, {}, true); !refused.empty()) return {false, refused};
  face.name = next_face_name();
  const std::string message = "added " + face.name + " to the temporary mesh";
  execute(AddTemporary{{std::move(face)}});
  return {true, message};
}

EditOutcome Document::accept_temporary() {
  if (temporary_.empty()) return {false, "the temporary mesh is empty"};
  const size_t count = temporary_.size();
  execute(Accept{count});
  return {true, std::to_string(count) + " faces moved into the consolidated mesh"};
}

EditOutcome Document::clear_temporary() {
  if (temporary_.empty()) return {false, "the temporary mesh is empty"};
  execute(ClearTemporary{temporary_});
  return {true, "temporary mesh cleared"};
}

EditOutcome Document::delete_faces(const std::vector<std::string>& face_names) {
  if (face_names.empty()) return {false, "no face selected"};
  DeleteFaces command;
  for (const std::string& name : face_names) {
    auto find_in = [&](const std::vector<EditedFace>& list) {
      return std::find_if(list.begin(), list.end(), [&](const EditedFace& f) { return f.name == name; });
    };
    if (auto it = find_in(temporary_); it != temporary_.end()) {
      command.temporary.emplace_back(size_t(it - temporary_.begin()), *it);
    } else if (auto it2 = find_in(consolidated_); it2 != consolidated_.end()) {
      command.consolidated.emplace_back(size_t(it2 - consolidated_.begin()), *it2);
    } else if (face_ids_.count(name) && std::find(deleted_.begin(), deleted_.end(), name) == deleted_.end()) {
      command.scene_faces.push_back(name);
    } else {
      return {false, "no face named " + name};
    }
  }
  auto by_position = [](const auto& x, const auto& y) { return x.first < y.first; };
  std::sort(command.temporary.begin(), command.temporary.end(), by_position);
  std::sort(command.consolidated.begin(), command.consolidated.end(), by_position);
  const size_t count = face_names.size();
  execute(std::move(command));
  return {true, std::to_string(count) + (count == 1 ? " face" : " faces") + " deleted"};
}

EditOutcome Document::set_sharp(const std::vector<std::pair<std::string, std::string>>& edges, float weight) {
  if (!(weight >= 0)) return {false, "a sharpness is 0 or more, found " + sharpness_text(weight)};
  weight = std::min(weight, infinite_sharpness);
  SetSharp command;
  for (const auto& given : edges) {
    // Named copies, not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    std::string a = given.first, b = given.second;
    if (b < a) std::swap(a, b);
    const Index u = vertex_id(a), w = vertex_id(b);
    if (u == no_index || w == no_index) return {false, "no vertex named " + (u == no_index ? a : b)};
    const std::string edge = "(" + a + ", " + b + ")";
    if (!scene_edge_faces_.count(edge_key(u, w)))
      return {false, edge + " is no edge of the scene's faces (an added face's edges cannot be sharp yet)"};
    if (const float in_text = text_sharpness(u, w); in_text > 0) {
      if (in_text == weight) continue;
      return {false, edge + " is sharp in the scene's text: change its `sharp` there"};
    }
    const auto marked = std::find_if(sharp_.begin(), sharp_.end(),
                                     [&](const NamedSharpEdge& e) { return e.a == a && e.b == b; });
    const float before = marked == sharp_.end() ? 0.0f : marked->weight;
    if (before != weight) command.changes.push_back({a, b, before, weight});
  }
  const size_t count = command.changes.size();
  if (count == 0)
    return {false, "the edges are " +
                       (weight == 0                    ? std::string("smooth")
                        : weight >= infinite_sharpness ? std::string("sharp")
                                                       : "of sharpness " + sharpness_text(weight)) +
                       " already"};
  execute(std::move(command));
  return {true, sharp_outcome(count, weight)};
}

// The weight the scene's own text gives the edge (u, w): 0 when it marks it not.
float Document::text_sharpness(Index u, Index w) const {
  float weight = 0;
  for (size_t i = 0; i < scene_.sharp_edges.size(); ++i)
    if (edge_key(scene_.sharp_edges[i].first, scene_.sharp_edges[i].second) == edge_key(u, w))
      weight = scene_.sharp_edge_weights.empty() ? infinite_sharpness : scene_.sharp_edge_weights[i];
  return std::min(weight, infinite_sharpness);
}

void Document::execute(Command command) {
  history_.resize(done_);
  history_.push_back(std::move(command));
  apply(history_.back());
  ++done_;
  note_new_topology();
}

bool Document::undo() {
  if (!can_undo()) return false;
  revert(history_[--done_]);
  note_new_topology();
  return true;
}

bool Document::redo() {
  if (!can_redo()) return false;
  apply(history_[done_++]);
  note_new_topology();
  return true;
}

void Document::apply(const Command& command) {
  if (const auto* add = std::get_if<AddTemporary>(&command)) {
    temporary_.insert(temporary_.end(), add->faces.begin(), add->faces.end());
  } else if (std::holds_alternative<Accept>(command)) {
    consolidated_.insert(consolidated_.end(), temporary_.begin(), temporary_.end());
    temporary_.clear();
  } else if (std::holds_alternative<ClearTemporary>(command)) {
    temporary_.clear();
  } else if (const auto* sharp = std::get_if<SetSharp>(&command)) {
    for (const SetSharp::Change& c : sharp->changes) mark_sharp(sharp_, c.a, c.b, c.after);
  } else {
    const auto& del = std::get<DeleteFaces>(command);
    erase_at(temporary_, del.temporary);
    erase_at(consolidated_, del.consolidated);
    deleted_.insert(deleted_.end(), del.scene_faces.begin(), del.scene_faces.end());
  }
}

void Document::revert(const Command& command) {
  if (const auto* add = std::get_if<AddTemporary>(&command)) {
    temporary_.resize(temporary_.size() - add->faces.size());
  } else if (const auto* accept = std::get_if<Accept>(&command)) {
    temporary_.assign(consolidated_.end() - long(accept->count), consolidated_.end());
    consolidated_.resize(consolidated_.size() - accept->count);
  } else if (const auto* clear = std::get_if<ClearTemporary>(&command)) {
    temporary_ = clear->faces;
  } else if (const auto* sharp = std::get_if<SetSharp>(&command)) {
    for (const SetSharp::Change& c : sharp->changes) mark_sharp(sharp_, c.a, c.b, c.before);
  } else {
    const auto& del = std::get<DeleteFaces>(command);
    deleted_.resize(deleted_.size() - del.scene_faces.size());
    insert_at(consolidated_, del.consolidated);
    insert_at(temporary_, del.temporary);
  }
}

std::vector<UnresolvedEdit> Document::unresolved() const {
  std::vector<UnresolvedEdit> out;
  for (const auto* list : {&consolidated_, &temporary_}) {
    for (const EditedFace& face : *list) {
      UnresolvedEdit edit{face.name, {}};
      for (const std::string& name : face.vertices)
        if (vertex_id(name) == no_index) edit.missing.push_back(name);
      if (!edit.missing.empty()) out.push_back(std::move(edit));
    }
  }
  for (const std::string& name : deleted_)
    if (!face_ids_.count(name)) out.push_back({name, {}});
  for (const NamedSharpEdge& e : sharp_) {
    UnresolvedEdit edit{"sharp (" + e.a + ", " + e.b + ")", {}};
    for (const std::string* name : {&e.a, &e.b})
      if (vertex_id(*name) == no_index) edit.missing.push_back(*name);
    if (!edit.missing.empty()) out.push_back(std::move(edit));
  }
  return out;
}

void Document::set_scene_face_attributes(Attributes faces) {
  for (const Attributes::Entry& e : faces.entries())
    if (e.column->size() > scene_.num_faces())
      throw InvalidInputError("Document::set_scene_face_attributes: '" + e.name +
                              "' has more values than the " + std::to_string(scene_.num_faces()) +
                              " scene faces");
  scene_.face_attributes = std::move(faces);
  ++input_attributes_version_;
}

Attributes Document::pipeline_face_attributes() const {
  return carried(scene_.face_attributes, kept_scene_faces());
}

std::vector<Index> Document::kept_scene_faces() const {
  const std::unordered_set<std::string> deleted(deleted_.begin(), deleted_.end());
  std::vector<Index> kept;
  for (Index f = 0; f < scene_.num_faces(); ++f)
    if (f >= scene_.face_names.size() || !deleted.count(scene_.face_names[f])) kept.push_back(f);
  return kept;
}

PolygonSoup Document::scene_soup() const {
  PolygonSoup soup;
  soup.positions = scene_.positions;
  soup.vertex_names = scene_.vertex_names;
  soup.sharp_edges = scene_.sharp_edges;
  soup.sharp_edge_weights = scene_.sharp_edge_weights;
  soup.sharp_vertices = scene_.sharp_vertices;
  for (const NamedSharpEdge& e : sharp_) {
    const Index u = vertex_id(e.a), w = vertex_id(e.b);
    if (u != no_index && w != no_index && scene_edge_faces_.count(edge_key(u, w)))
      soup.add_sharp_edge(u, w, e.weight);
  }
  const std::unordered_set<Index> holes(scene_.hole_faces.begin(), scene_.hole_faces.end());
  const std::vector<Index> kept = kept_scene_faces();
  for (const Index f : kept) {
    if (holes.count(f)) soup.hole_faces.push_back(soup.num_faces());
    soup.note_origin(scene_.origin(f));
    soup.add_face(std::span(scene_.face_vertices)
                      .subspan(scene_.face_offsets[f], scene_.face_offsets[f + 1] - scene_.face_offsets[f]));
    if (!scene_.face_names.empty()) soup.face_names.push_back(scene_.face_names[f]);
  }
  soup.face_attributes = carried(scene_.face_attributes, kept);
  return soup;
}

PolygonSoup Document::edited_soup(const std::vector<EditedFace>& faces) const {
  PolygonSoup soup;
  std::unordered_map<Index, Index> local;
  for (const EditedFace& face : faces) {
    std::vector<Index> ids;
    for (const std::string& name : face.vertices) ids.push_back(vertex_id(name));
    if (std::find(ids.begin(), ids.end(), no_index) != ids.end()) continue;  // reported by unresolved()
    for (Index& v : ids) {
      const auto [it, is_new] = local.emplace(v, soup.num_vertices());
      if (is_new) {
        soup.add_vertex(scene_.positions[v]);
        soup.vertex_names.push_back(scene_.vertex_names[v]);
      }
      v = it->second;
    }
    soup.add_face(ids);
    soup.face_names.push_back(face.name);
  }
  return soup;
}

std::vector<Index> Document::edited_sources(const std::vector<EditedFace>& faces) const {
  std::vector<Index> sources;
  std::unordered_set<Index> seen;
  for (const EditedFace& face : faces) {
    std::vector<Index> ids;
    for (const std::string& name : face.vertices) ids.push_back(vertex_id(name));
    if (std::find(ids.begin(), ids.end(), no_index) != ids.end()) continue;
    for (Index v : ids)
      if (seen.insert(v).second) sources.push_back(v);
  }
  return sources;
}

Buffer<Vec3> Document::pipeline_positions() const {
  Buffer<Vec3> positions;
  positions.reserve(scene_.positions.size() + edited_vertex_sources_.size());
  positions.assign(scene_.positions.begin(), scene_.positions.end());
  for (Index v : edited_vertex_sources_) positions.push_back(scene_.positions[v]);
  return positions;
}

PolygonSoup Document::consolidated_soup() const {
  return edited_soup(consolidated_);
}

PolygonSoup Document::temporary_soup() const {
  return edited_soup(temporary_);
}

PipelineInput Document::pipeline_input() const {
  PipelineInput input;
  input.joining = Joining::across_edges;
  const std::pair<const char*, PolygonSoup> parts[] = {
      {"scene", scene_soup()}, {"consolidated", consolidated_soup()}, {"temporary", temporary_soup()}};
  for (const auto& [name, soup] : parts) {
    append_soup(input.soup, soup);
    input.parts.push_back({name, soup.num_faces()});
  }
  return input;
}

}  // namespace nome
