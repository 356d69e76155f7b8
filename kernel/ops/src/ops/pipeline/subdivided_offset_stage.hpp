#pragma once

#include "nome/error.hpp"
#include "ops/pipeline/subdivision_stage.hpp"

namespace nome {

// Catmull-Clark after the offset, on the solid: the settings' subdivision_after.
class SubdividedOffsetStage final : public SubdivisionStage {
 public:
  std::string_view name() const override { return "subdivided offset"; }
  void check(const PipelineSettings& s) const override {
    SubdivisionStage::check(s);
    if (s.levels_after() > 0 && s.distance() == 0.0)
      throw InvalidInputError("pipeline: subdivision after the offset needs an offset distance");
  }

  int levels(const PipelineSettings& s) const override { return s.levels_after(); }
};

}  // namespace nome
