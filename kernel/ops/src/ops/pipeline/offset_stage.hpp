#pragma once

#include "nome/mesh/normals.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/pipeline_stage.hpp"

namespace nome {

// The offset into a solid: both passes compute the input's normals (warning of degenerate faces); the
// topology pass builds the two copies and the rim, the positions pass moves the kept solid's vertices.
// Another distance needs the positions pass only.
class OffsetStage final : public PipelineStage {
 public:
  std::string_view name() const override { return "offset"; }
  void check(const PipelineSettings& s) const override;
  bool is_on(const PipelineSettings& s) const override { return s.distance() > 0; }
  bool changes_positions(const PipelineSettings& last, const PipelineSettings& next) const override {
    return last.distance() != next.distance();
  }
  void topology_pass(const Mesh& input, const StagePass& pass) override;
  Change positions_pass(const Mesh& input, const StagePass& pass) override;
  ElementOrigins face_origins(const Mesh& input) const override { return offset_face_origins(input); }
  Mesh& result() override { return result_; }
  bool free_while_off() override;
  std::optional<TopologyReport> derived_report(const Mesh& input) const override;
  // The surface's normals, already computed for the offset (offset_packed_normals).
  bool display_normals(Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices,
                       int threads) const override;

 private:
  // The normals of `input`, with a warning naming its degenerate faces.
  void compute_input_normals(const Mesh& input, const StagePass& pass);

  Normals normals_;              // of the last pass's input; kept for their blocks, as is the result's
  const Mesh* input_ = nullptr;  // of the last pass (valid as long as the result)
  Mesh result_;
};

}  // namespace nome
