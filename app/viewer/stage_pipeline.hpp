#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "nome/mesh/mesh.hpp"
#include "nome/mesh/topology_report.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/query/border_lookup.hpp"
#include "render/mesh_display_data.hpp"
#include "viewer/session.hpp"

namespace nome::viewer {

// The stage the window shows (report 7.2's operations; DESIGN.md's data flow).
enum class Stage { scene, merged, subdivided, offset, subdivided_offset };

const char* to_string(Stage stage);

// Edits name the scene's vertices and faces, which only the scene and merged stages show: the later
// stages are computed from them (pick there to look, switch back to edit).
bool is_editable(Stage stage);

// The control panel's pipeline settings: which stage the window shows and how it is made.
struct StageSettings {
  Stage stage = Stage::scene;
  double merge_tolerance = 0.0;  // 0: relative to the size of the scene (MergeOptions)
  bool subdivide_merged = true;  // the later stages start from the merged mesh, else from the scene's
  int subdivision_levels = 2;    // 0-6, before the offset
  SubdivisionRule rule = SubdivisionRule::classic;
  double offset_distance = 0.05;
  int subdivision_after = 1;  // levels after the offset, for the subdivided offset stage

  bool operator==(const StageSettings&) const = default;
};

// Everything a frame needs of a new displayed mesh, computed off the UI thread: the mesh, its GPU-ready
// arrays, its borders and its topology report. Only the upload to GL is left to the UI thread, and the
// picking BVH to the first pick (a slider drag shows many meshes and picks on none).
struct StageResult {
  Stage stage = Stage::scene;  // which stage the mesh is
  std::shared_ptr<const Mesh> mesh;
  render::MeshDisplayData display;
  std::shared_ptr<const BorderLookup> borders;
  TopologyReport topology;
  std::vector<std::string> warnings;
  std::vector<std::string> notes;  // what the stages did, for the log
  FaceParts parts;                 // of the scene soup it was made from (faces keep their order)
  double seconds = 0.0;
};

// Turns the scene's polygons into the displayed stage. Safe to call from background jobs: runs are
// serialised, and a run whose stop was requested before it began, or between two stages, gives up and
// returns none. The kernel Pipeline's caches outlive a run: a slider that only moves vertices re-runs
// the subdivision and offset position passes over the cached topology.
class StagePipeline {
 public:
  // Throws the kernel's errors (TopologyError naming the elements, BudgetError).
  std::optional<StageResult> run(const PolygonSoup& scene, const StageSettings& settings,
                                 std::stop_token stop);

 private:
  std::mutex mutex_;
  Pipeline pipeline_;
};

}  // namespace nome::viewer
