#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "nome/ops/pipeline.hpp"
#include "viewer/session/session.hpp"

namespace nome::viewer {

// Hands a session's inputs to one pipeline by the change signal alone: a new topology version replaces
// the pipeline's input, new positions of the version it has move its vertices, new face attributes (a
// colour) replace the scene stage's, anything else changes nothing. No polygon is looked at to decide.
class SceneInputFeed {
 public:
  void feed(Pipeline& pipeline, const SceneInput& input);
  // The pipeline was given an input some other way: the next feed replaces it whole.
  void forget() {
    version_.reset();
    positions_.reset();
    face_attributes_.reset();
  }

 private:
  std::optional<std::uint64_t> version_;
  std::shared_ptr<const Buffer<Vec3>> positions_;
  std::shared_ptr<const Attributes> face_attributes_;
};

}  // namespace nome::viewer
