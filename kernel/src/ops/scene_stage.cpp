#include "ops/scene_stage.hpp"

#include <algorithm>

#include "nome/error.hpp"
#include "nome/mesh/glue_faces.hpp"

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

// build_mesh on the whole input; a topology error names the part at fault, with element numbers of that
// part alone: the parts are built one by one (only on this error path) to find it.
Mesh build_naming_the_part(PipelineInput& input) {
  PolygonSoup whole = input.soup;
  try {
    return build_mesh(std::move(input.soup));
  } catch (const TopologyError&) {
    if (input.parts.empty()) throw;
    Index first = 0;
    for (const InputPart& part : input.parts) {
      try {
        build_mesh(part_of(whole, first, part.faces));
      } catch (const TopologyError& in_part) {
        throw TopologyError(part.name + ": " + in_part.what());
      }
      first += part.faces;
    }
    throw;
  }
}

}  // namespace

InputChange SceneStage::update(PipelineInput input) {
  PolygonSoup& soup = input.soup;
  Structure next{std::move(soup.face_offsets),
                 std::move(soup.face_vertices),
                 std::move(soup.sharp_edges),
                 std::move(soup.vertex_names),
                 std::move(soup.face_names),
                 soup.num_vertices(),
                 input.joining,
                 !soup.face_colors.empty()};
  if (has_mesh_ && next == structure_) {
    Buffer<Vec3>& positions = mesh_.positions();
    if (vertex_sources_.empty()) {
      positions = std::move(soup.positions);
    } else {
      for (Index v = 0; v < positions.size(); ++v) positions[v] = soup.positions[vertex_sources_[v]];
    }
    mesh_.face_colors() = std::move(soup.face_colors);
    problems_.clear();
    work_ = StageWork::positions;
    return InputChange::positions;
  }
  structure_ = std::move(next);
  soup.face_offsets = structure_.face_offsets;
  soup.face_vertices = structure_.face_vertices;
  soup.sharp_edges = structure_.sharp_edges;
  soup.vertex_names = structure_.vertex_names;
  soup.face_names = structure_.face_names;
  try {
    rebuild(std::move(input));
  } catch (...) {
    *this = SceneStage();
    throw;
  }
  return InputChange::topology;
}

void SceneStage::rebuild(PipelineInput input) {
  problems_.clear();
  if (input.joining == Joining::across_edges) {
    GluedFaces glued = glue_faces(input.soup);
    mesh_ = std::move(glued.mesh);
    vertex_sources_ = std::move(glued.vertex_sources);
    problems_ = std::move(glued.problems);
  } else {
    mesh_ = build_naming_the_part(input);
    vertex_sources_.clear();
  }
  has_mesh_ = true;
  work_ = StageWork::rebuilt;
}

InputChange SceneStage::update(const Mesh& mesh) {
  problems_.clear();
  const bool is_same_topology =
      has_mesh_ && mesh.face_offsets() == mesh_.face_offsets() &&
      mesh.corner_vertices() == mesh_.corner_vertices() && mesh.num_vertices() == mesh_.num_vertices() &&
      std::equal(mesh.edges().begin(), mesh.edges().end(), mesh_.edges().begin(),
                 [](const Edge& a, const Edge& b) { return a.is_sharp == b.is_sharp; });
  if (is_same_topology && mesh.positions() == mesh_.positions()) {
    work_ = StageWork::cached;
    return InputChange::none;
  }
  if (is_same_topology)
    mesh_.positions() = mesh.positions();
  else
    mesh_ = mesh;
  has_mesh_ = true;
  vertex_sources_.clear();
  structure_ = {};
  work_ = is_same_topology ? StageWork::positions : StageWork::rebuilt;
  return is_same_topology ? InputChange::positions : InputChange::topology;
}

}  // namespace nome
