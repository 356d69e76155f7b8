#pragma once

// OpenSubdiv as a referee (Debian libosd-dev, linked into the kernel tests only when found).
#ifdef NOME_HAVE_OPENSUBDIV

#include <memory>
#include <vector>

#include <opensubdiv/far/topologyDescriptor.h>

#include "nome/mesh/polygon_soup.hpp"
#include "nome/ops/boundary_mode.hpp"
#include "nome/ops/crease_options.hpp"

namespace nome::test {

// OpenSubdiv's Catmark refiner for a soup with its holes, crease and corner weights, refined uniformly
// to `levels` (each level's vertices numbered face points first, as ours, when `faces_first`).
inline std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> opensubdiv_refiner(const PolygonSoup& soup,
                                                                            BoundaryMode mode,
                                                                            const CreaseOptions& creases,
                                                                            int levels, bool faces_first) {
  namespace Far = OpenSubdiv::Far;
  using Sdc = OpenSubdiv::Sdc::Options;
  std::vector<int> sizes, vertices(soup.face_vertices.begin(), soup.face_vertices.end());
  for (Index f = 0; f < soup.num_faces(); ++f)
    sizes.push_back(int(soup.face_offsets[f + 1] - soup.face_offsets[f]));
  Far::TopologyDescriptor d;
  d.numVertices = int(soup.num_vertices());
  d.numFaces = int(soup.num_faces());
  d.numVertsPerFace = sizes.data();
  d.vertIndicesPerFace = vertices.data();
  std::vector<int> crease_pairs, corners, holes(soup.hole_faces.begin(), soup.hole_faces.end());
  std::vector<float> crease_weights, corner_weights;
  for (size_t i = 0; i < soup.sharp_edges.size(); ++i) {
    crease_pairs.push_back(int(soup.sharp_edges[i].first));
    crease_pairs.push_back(int(soup.sharp_edges[i].second));
    crease_weights.push_back(soup.sharp_edge_weights.empty() ? infinite_sharpness
                                                             : soup.sharp_edge_weights[i]);
  }
  for (const auto& [v, w] : soup.sharp_vertices) corners.push_back(int(v)), corner_weights.push_back(w);
  d.numCreases = int(crease_weights.size());
  d.creaseVertexIndexPairs = crease_pairs.data();
  d.creaseWeights = crease_weights.data();
  d.numCorners = int(corners.size());
  d.cornerVertexIndices = corners.data();
  d.cornerWeights = corner_weights.data();
  d.numHoles = int(holes.size());
  d.holeIndices = holes.data();
  Sdc options;
  options.SetVtxBoundaryInterpolation(mode == BoundaryMode::none        ? Sdc::VTX_BOUNDARY_NONE
                                      : mode == BoundaryMode::edge_only ? Sdc::VTX_BOUNDARY_EDGE_ONLY
                                                                        : Sdc::VTX_BOUNDARY_EDGE_AND_CORNER);
  options.SetCreasingMethod(creases.method == CreaseMethod::chaikin ? Sdc::CREASE_CHAIKIN
                                                                    : Sdc::CREASE_UNIFORM);
  options.SetTriangleSubdivision(creases.smooth_triangles ? Sdc::TRI_SUB_SMOOTH : Sdc::TRI_SUB_CATMARK);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(d, Factory::Options(OpenSubdiv::Sdc::SCHEME_CATMARK, options)));
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.orderVerticesFromFacesFirst = faces_first;
  refiner->RefineUniform(uniform);
  return refiner;
}

}  // namespace nome::test

#endif
