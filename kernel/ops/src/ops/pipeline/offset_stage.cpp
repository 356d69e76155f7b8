#include "ops/pipeline/offset_stage.hpp"

#include <cmath>
#include <string>

#include "nome/error.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/offset_normals.hpp"
#include "nome/ops/offset_report.hpp"

namespace nome {

void OffsetStage::check(const PipelineSettings& s) const {
  if (s.distance() != 0.0 && !(s.distance() > 0.0 && std::isfinite(s.distance())))
    throw InvalidInputError("pipeline: the offset distance must be positive and finite, got " +
                            std::to_string(s.distance()));
}

void OffsetStage::compute_input_normals(const Mesh& input, const StagePass& pass) {
  input_ = &input;
  pass.progress("offset", 0.0);
  compute_normals(input, normals_, pass.settings.threads);
  pass.progress("offset", 0.3);
  if (std::string warning = degeneracy_warning(input, normals_); !warning.empty())
    pass.warnings.push_back("offset: " + warning);
}

void OffsetStage::topology_pass(const Mesh& input, const StagePass& pass) {
  compute_input_normals(input, pass);
  offset_into(input, normals_, pass.settings.distance(), result_, pass.settings.threads);
  pass.progress("offset", 1.0);
}

Change OffsetStage::positions_pass(const Mesh& input, const StagePass& pass) {
  compute_input_normals(input, pass);
  offset_positions(input, normals_, pass.settings.distance(), result_.positions(), pass.settings.threads);
  pass.progress("offset", 1.0);
  return Change::positions;
}

bool OffsetStage::free_while_off() {
  normals_ = {};
  input_ = nullptr;
  result_ = {};
  return true;
}

std::optional<TopologyReport> OffsetStage::derived_report(const Mesh& input) const {
  return offset_topology_report(input);
}

bool OffsetStage::display_normals(Buffer<PackedNormal>& faces, Buffer<PackedNormal>& vertices,
                                  int threads) const {
  return input_ && offset_packed_normals(*input_, normals_, faces, vertices, threads);
}

}  // namespace nome
