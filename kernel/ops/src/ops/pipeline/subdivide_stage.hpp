#pragma once

#include "ops/pipeline/subdivision_stage.hpp"

namespace nome {

// Catmull-Clark before the offset: the settings' subdivision_levels.
class SubdivideStage final : public SubdivisionStage {
 public:
  std::string_view name() const override { return "subdivided"; }

  int levels(const PipelineSettings& s) const override { return s.levels_before(); }
};

}  // namespace nome
