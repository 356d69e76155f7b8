#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "nome/scene/piece.hpp"

namespace nome::scene {

// A cross-section: points in the plane of a path frame, x along the frame's normal N, y along its
// binormal B (the path's tangent T = N x B points out of the plane); closed when its last point joins
// its first.
struct CrossSection {
  std::vector<glm::dvec2> points;
  bool is_closed = true;
};

// One sample of a sweep path: where a cross-section is placed and how it is shaped there (a control
// point's `scale (sx sy 0)`, `rotate (rx ry rz)` in degrees, its own cross-section, `reverse`).
struct PathSample {
  Vec3 position{0.0};
  glm::dvec2 scale{1.0, 1.0};
  Vec3 rotate{0.0};
  Index section = 0;          // into the cross-sections given to sweep()
  bool is_reversing = false;  // reverses the cross-section's order (and its turning sense) from here on
};

// How the cross-section is carried along the path: Frenet frames (the normal towards the centre of
// curvature, carried over straight stretches), or rotation-minimising frames (`mintorsion`, the
// double-reflection method of Wang, Jüttler, Zheng and Liu, "Computation of rotation minimizing frames",
// ACM TOG 27(1), 2008).
enum class FrameKind { frenet, minimal_torsion };
enum class FaceShape { quadrilaterals, triangles };

struct SweepOptions {
  FrameKind frames = FrameKind::frenet;
  double azimuth = 0;  // degrees: the cross-section turned in every frame
  double twist = 0;    // degrees: the extra turn from the path's start to its end (once around a closed one)
  bool is_path_closed = false;
  bool is_reversed = false;  // the cross-section's order reversed (its faces face the other way)
  bool has_begin_cap = false, has_end_cap = false;
  bool is_cut_begin = false, is_cut_end = false;  // the first / last sample only aims the next one
  FaceShape faces = FaceShape::quadrilaterals;
};

// The swept surface: vertices v{i}_{j} (sample i, cross-section point j), faces f{i}_{j} (triangles
// f{i}_{j}a and b), caps `begincap` and `endcap`; a one-point cross-section gives a rim line instead.
// `warnings` explains a closed path's join that no symmetry of the cross-section makes exact.
struct SweepResult {
  Piece piece;
  std::vector<std::string> warnings;
};

// Sweeps the cross-sections along the sampled path (every section the same number of points). On a closed
// path the last section is joined to the first by position: the correspondence of their points (a cyclic
// shift, or a reversal, of the first) that lies nearest after the twist, so that half a turn of a segment
// gives a Möbius band. Throws InvalidInputError for too few samples or mismatched cross-sections.
SweepResult sweep(std::span<const PathSample> path, std::span<const CrossSection> sections,
                  const SweepOptions& options);

// The positions sweep() gives its vertices, alone, with the topology key its piece would carry: what a
// slider that moves the path or reshapes the cross-section changes (when the key is the last piece's, the
// faces and names stay), for a caller that updates positions in place.
struct SweepPositions {
  Buffer<Vec3> positions;
  std::uint64_t topology_key = 0;
  std::vector<std::string> warnings;
};
SweepPositions sweep_positions(std::span<const PathSample> path, std::span<const CrossSection> sections,
                               const SweepOptions& options);

// The frames alone (rows N, B, T per sample, then for a closed path one more: the first sample's frame
// carried once around), for the sweep and for a ribbon along a rim line.
struct Frame {
  Vec3 normal, binormal, tangent;
};
std::vector<Frame> path_frames(std::span<const Vec3> points, bool is_closed, FrameKind kind);

}  // namespace nome::scene
