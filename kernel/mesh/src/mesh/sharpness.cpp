#include "mesh/sharpness.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "nome/error.hpp"

namespace nome {
namespace {

// OpenSubdiv clamps negative weights to 0; a NaN weighs nothing either.
float clamped_sharpness(float weight) {
  return std::isnan(weight) ? 0.0f : std::max(weight, 0.0f);
}

}  // namespace

void Mesh::set_edge_sharpness(Index e, float weight) {
  weight = clamped_sharpness(weight);
  arrays_.edges[e].is_sharp = weight >= infinite_sharpness;
  const float semi = weight >= infinite_sharpness ? 0.0f : weight;
  if (arrays_.edge_sharpness.empty() && semi == 0.0f) return;
  arrays_.edge_sharpness.resize(num_edges(), 0.0f);
  arrays_.edge_sharpness[e] = semi;
}

void Mesh::set_vertex_sharpness(Index v, float weight) {
  weight = std::min(clamped_sharpness(weight), infinite_sharpness);
  if (arrays_.vertex_sharpness.empty() && weight == 0.0f) return;
  arrays_.vertex_sharpness.resize(num_vertices(), 0.0f);
  arrays_.vertex_sharpness[v] = weight;
}

bool Mesh::has_sharpness_weights() const {
  const auto positive = [](float w) { return w > 0.0f; };
  return std::any_of(arrays_.vertex_sharpness.begin(), arrays_.vertex_sharpness.end(), positive) ||
         std::any_of(arrays_.edge_sharpness.begin(), arrays_.edge_sharpness.end(), positive);
}

void Mesh::set_hole(Index f, bool hole) {
  if (arrays_.face_holes.empty() && !hole) return;
  arrays_.face_holes.resize(num_faces(), false);
  arrays_.face_holes[f] = hole;
}

bool Mesh::has_holes() const {
  return std::find(arrays_.face_holes.begin(), arrays_.face_holes.end(), true) != arrays_.face_holes.end();
}

void apply_soup_features(Mesh& m, const PolygonSoup& soup) {
  const Index nv = m.num_vertices();
  if (!soup.sharp_edge_weights.empty() && soup.sharp_edge_weights.size() != soup.sharp_edges.size())
    throw InvalidInputError("build_mesh: sharp_edge_weights must be empty or one per sharp edge");
  // Sharp marks name vertex pairs; the fan of the first vertex finds the edge.
  for (size_t i = 0; i < soup.sharp_edges.size(); ++i) {
    const auto [a, b] = soup.sharp_edges[i];
    Index found = no_index;
    if (a < nv && b < nv)
      for (Index e : m.vertex_edges(a))
        if (m.edge(e).other_vertex(a) == b) found = e;
    if (found == no_index)
      throw TopologyError("build_mesh: sharp edge (" + m.vertex_label(a) + ", " + m.vertex_label(b) +
                          ") is not an edge of any face");
    m.set_edge_sharpness(found,
                         soup.sharp_edge_weights.empty() ? infinite_sharpness : soup.sharp_edge_weights[i]);
  }
  for (const auto& [v, weight] : soup.sharp_vertices) {
    if (v >= nv)
      throw TopologyError("build_mesh: sharp corner " + std::to_string(v) +
                          " is not a vertex (the mesh has " + std::to_string(nv) + ")");
    m.set_vertex_sharpness(v, weight);
  }
  for (Index f : soup.hole_faces) {
    if (f >= m.num_faces())
      throw TopologyError("build_mesh: hole " + std::to_string(f) + " is not a face (the mesh has " +
                          std::to_string(m.num_faces()) + ")");
    m.set_hole(f, true);
  }
}

void add_features_to_soup(const Mesh& mesh, PolygonSoup& soup) {
  const bool has_weights = !mesh.edge_sharpness_weights().empty();
  for (Index e = 0; e < mesh.num_edges(); ++e) {
    const float weight = mesh.edge_sharpness(e);
    if (weight <= 0.0f) continue;
    soup.sharp_edges.emplace_back(mesh.edge(e).vertices[0], mesh.edge(e).vertices[1]);
    if (has_weights) soup.sharp_edge_weights.push_back(weight);
  }
  for (Index v = 0; v < Index(mesh.vertex_sharpness_weights().size()); ++v)
    if (mesh.vertex_sharpness(v) > 0.0f) soup.sharp_vertices.emplace_back(v, mesh.vertex_sharpness(v));
  for (Index f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_hole(f)) soup.hole_faces.push_back(f);
}

}  // namespace nome
