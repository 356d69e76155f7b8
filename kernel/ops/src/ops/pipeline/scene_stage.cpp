#include "ops/pipeline/scene_stage.hpp"

#include <algorithm>
#include <optional>

#include "nome/error.hpp"
#include "nome/mesh/glue_faces.hpp"
#include "ops/pipeline/located_problems.hpp"

namespace nome {
namespace {

// The faces [first, first + count) of `soup` with the vertices they use, for naming the part at fault.
PolygonSoup part_of(const PolygonSoup& soup, Index first, Index count) {
  PolygonSoup part;
  std::vector<Index> local(soup.num_vertices(), no_index);
  for (Index f = first; f < first + count; ++f) {
    for (Index c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c) {
      const Index v = soup.face_vertices[c];
      if (v < local.size() && local[v] == no_index) {
        local[v] = part.add_vertex(soup.positions[v]);
        if (!soup.vertex_names.empty()) part.vertex_names.push_back(soup.vertex_names[v]);
      }
      part.face_vertices.push_back(v < local.size() ? local[v] : v);
    }
    part.face_offsets.push_back(Index(part.face_vertices.size()));
    if (!soup.face_names.empty()) part.face_names.push_back(soup.face_names[f]);
  }
  return part;
}

// The part's error with each problem at the place in its file that wrote the face (one line each, the
// same problem listed once), or prefixed with the part's name where no place is known.
TopologyError located_in_part(const TopologyError& error, const InputPart& part) {
  std::vector<std::string> lines;
  for (const TopologyError::Problem& p : error.problems()) {
    const std::string where = part.locate_face && p.face != no_index ? part.locate_face(p.face) : "";
    if (where.empty()) return TopologyError(part.name + ": " + error.what(), error.problems());
    const std::string line = where + ": not a 2-manifold: " + p.text;
    if (std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
  }
  if (lines.empty()) return TopologyError(part.name + ": " + error.what(), error.problems());
  std::string text = lines.front();
  for (size_t i = 1; i < lines.size(); ++i) text += "\n" + lines[i];
  return TopologyError(text, error.problems());
}

// build_mesh on the whole input (its arrays move into the mesh); a topology error names the part at fault,
// with element numbers of that part alone: the parts are built one by one (only on this error path) to
// find it.
Mesh build_naming_the_part(PipelineInput& input) {
  try {
    return build_mesh_from(input.soup);
  } catch (const TopologyError& e) {
    if (std::optional<TopologyError> located = located_error(e, input.soup)) throw *located;
    if (input.parts.empty()) throw;
    Index first = 0;
    for (const InputPart& part : input.parts) {
      try {
        build_mesh(part_of(input.soup, first, part.faces));
      } catch (const TopologyError& in_part) {
        throw located_in_part(in_part, part);
      }
      first += part.faces;
    }
    throw;
  }
}

// The input joined across edges, when its only faults are vertices where faces of parts that may touch
// meet at a point; nothing otherwise (the caller then reports build_mesh's error). Adds one warning
// naming the vertices split.
std::optional<GluedFaces> split_touching_vertices(const PipelineInput& input,
                                                  std::vector<std::string>& warnings) {
  const PolygonSoup& soup = input.soup;
  std::vector<bool> is_fixed(soup.num_vertices(), false);  // used by a part that may not touch
  Index first = 0;
  for (const InputPart& part : input.parts) {
    if (!part.may_touch_at_vertices)
      for (Index c = soup.face_offsets[first]; c < soup.face_offsets[first + part.faces]; ++c)
        is_fixed[soup.face_vertices[c]] = true;
    first += part.faces;
  }
  if (input.parts.empty() || std::find(is_fixed.begin(), is_fixed.end(), false) == is_fixed.end())
    return std::nullopt;
  GluedFaces glued;
  try {
    glued = glue_faces(soup);
  } catch (const TopologyError&) {
    return std::nullopt;  // faces that are no polygons: build_mesh's error says which
  }
  if (!glued.problems.empty()) return std::nullopt;
  std::vector<Index> copies(soup.num_vertices(), 0);
  for (Index source : glued.vertex_sources) ++copies[source];
  std::vector<std::string> names;
  for (Index v = 0; v < copies.size(); ++v) {
    if (copies[v] < 2) continue;
    if (is_fixed[v]) return std::nullopt;
    names.push_back(v < soup.vertex_names.size() && !soup.vertex_names[v].empty() ? soup.vertex_names[v]
                                                                                  : "v" + std::to_string(v));
  }
  constexpr size_t names_shown = 8;
  std::string list;
  for (size_t i = 0; i < names.size() && i < names_shown; ++i) list += (i ? ", " : "") + names[i];
  if (names.size() > names_shown) list += " and " + std::to_string(names.size() - names_shown) + " more";
  warnings.push_back("scene: faces meet at " + std::to_string(names.size()) +
                     " vertices without sharing an edge there (" + list +
                     "): each is split, one vertex per fan of faces");
  return glued;
}

}  // namespace

bool SceneStage::faces_match(const Buffer<Index>& face_offsets, const Buffer<Index>& face_vertices) const {
  if (input_face_offsets_.empty())  // no copy kept: the mesh was built from the input's faces as they were
    return face_offsets == mesh_.face_offsets() && face_vertices == mesh_.corner_vertices();
  return face_offsets == input_face_offsets_ && face_vertices == input_face_vertices_;
}

Change SceneStage::update(PipelineInput input) {
  return take(std::move(input), true);
}

Change SceneStage::replace(PipelineInput input) {
  return take(std::move(input), false);
}

Change SceneStage::take(PipelineInput input, bool may_be_same) {
  PolygonSoup& soup = input.soup;
  Structure next{std::move(soup.sharp_edges),
                 std::move(soup.sharp_edge_weights),
                 std::move(soup.sharp_vertices),
                 std::move(soup.hole_faces),
                 std::move(soup.vertex_names),
                 std::move(soup.face_names),
                 soup.num_vertices(),
                 input.joining};
  if (may_be_same && has_input_ && next == structure_ && faces_match(soup.face_offsets, soup.face_vertices)) {
    take_positions(soup.positions);
    attributes_changed_ = !(mesh_.face_attributes() == soup.face_attributes);
    if (attributes_changed_) mesh_.face_attributes() = std::move(soup.face_attributes);
    return Change::positions;
  }
  attributes_changed_ = true;
  structure_ = std::move(next);
  soup.sharp_edges = structure_.sharp_edges;
  soup.sharp_edge_weights = structure_.sharp_edge_weights;
  soup.sharp_vertices = structure_.sharp_vertices;
  soup.hole_faces = structure_.hole_faces;
  soup.vertex_names = structure_.vertex_names;
  soup.face_names = structure_.face_names;
  try {
    rebuild(std::move(input));
  } catch (...) {
    *this = SceneStage();
    throw;
  }
  has_input_ = true;
  return Change::topology;
}

void SceneStage::take_positions(Buffer<Vec3>& input) {
  Buffer<Vec3>& positions = mesh_.positions();
  if (vertex_sources_.empty()) {
    positions = std::move(input);
  } else {
    for (Index v = 0; v < positions.size(); ++v) positions[v] = input[vertex_sources_[v]];
  }
}

Change SceneStage::move_vertices(Buffer<Vec3> positions) {
  if (!has_input_ || positions.size() != structure_.num_vertices)
    throw InvalidInputError("Pipeline::move_input_vertices: " + std::to_string(positions.size()) +
                            " positions for an input of " + std::to_string(structure_.num_vertices) +
                            " vertices (set_input first)");
  take_positions(positions);
  attributes_changed_ = false;
  return Change::positions;
}

Change SceneStage::set_face_attributes(Attributes faces) {
  if (!has_input_ && !has_mesh_)
    throw InvalidInputError("Pipeline::set_input_face_attributes: there is no input (set_input first)");
  for (const Attributes::Entry& e : faces.entries())
    if (e.column->size() > mesh_.num_faces())
      throw InvalidInputError("Pipeline::set_input_face_attributes: '" + e.name +
                              "' has more values than the " + std::to_string(mesh_.num_faces()) + " faces");
  attributes_changed_ = !(faces == mesh_.face_attributes());
  mesh_.face_attributes() = std::move(faces);
  return attributes_changed_ ? Change::positions : Change::none;
}

void SceneStage::keep_input_faces(PolygonSoup& soup) {
  input_face_offsets_ = std::move(soup.face_offsets);
  input_face_vertices_ = std::move(soup.face_vertices);
}

void SceneStage::rebuild(PipelineInput input) {
  problems_.clear();
  if (input.joining == Joining::across_edges) {
    GluedFaces glued;
    try {
      glued = glue_faces(input.soup);
    } catch (const TopologyError& e) {
      if (std::optional<TopologyError> located = located_error(e, input.soup)) throw *located;
      throw;
    }
    mesh_ = std::move(glued.mesh);
    vertex_sources_ = std::move(glued.vertex_sources);
    keep_input_faces(input.soup);
    for (std::string& p : glued.problems)
      problems_.push_back(input.soup.face_origins.empty() ? "scene: " + p : std::move(p));
  } else {
    try {
      mesh_ = build_naming_the_part(input);
      vertex_sources_.clear();
      input_face_offsets_ = {};
      input_face_vertices_ = {};
    } catch (const TopologyError&) {
      std::optional<GluedFaces> split = split_touching_vertices(input, problems_);
      if (!split) throw;
      mesh_ = std::move(split->mesh);
      vertex_sources_ = std::move(split->vertex_sources);
      keep_input_faces(input.soup);
    }
  }
  for (std::string& w : coinciding_vertex_warnings(mesh_, input.soup)) problems_.push_back(std::move(w));
  has_mesh_ = true;
}

Change SceneStage::update(const Mesh& mesh) {
  problems_.clear();
  const bool is_same_topology =
      has_mesh_ && mesh.face_offsets() == mesh_.face_offsets() &&
      mesh.corner_vertices() == mesh_.corner_vertices() && mesh.num_vertices() == mesh_.num_vertices() &&
      std::equal(mesh.edges().begin(), mesh.edges().end(), mesh_.edges().begin(),
                 [](const Edge& a, const Edge& b) { return a.is_sharp == b.is_sharp; }) &&
      mesh.edge_sharpness_weights() == mesh_.edge_sharpness_weights() &&
      mesh.vertex_sharpness_weights() == mesh_.vertex_sharpness_weights() &&
      mesh.face_holes() == mesh_.face_holes();
  attributes_changed_ = !(mesh.face_attributes() == mesh_.face_attributes());
  if (is_same_topology && mesh.positions() == mesh_.positions() && !attributes_changed_) return Change::none;
  if (is_same_topology) {
    mesh_.positions() = mesh.positions();
    mesh_.face_attributes() = mesh.face_attributes();
  } else {
    mesh_ = mesh;
  }
  has_mesh_ = true;
  vertex_sources_.clear();
  structure_ = {};
  has_input_ = false;
  input_face_offsets_ = {};
  input_face_vertices_ = {};
  return is_same_topology ? Change::positions : Change::topology;
}

void SceneStage::topology_pass(const Mesh&, const StagePass& pass) {
  for (const std::string& p : problems_) pass.warnings.push_back(p);
}

Change SceneStage::positions_pass(const Mesh& input, const StagePass& pass) {
  topology_pass(input, pass);
  return Change::positions;
}

}  // namespace nome
