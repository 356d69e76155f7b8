#include <catch2/catch.hpp>

#include <span>
#include <string_view>

#include "nome/ops/pipeline.hpp"
#include "nome/ops/pipeline_stage.hpp"
#include "support/shapes.hpp"

using namespace nome;

// A stage added through the public interface alone, as a user of the kernel would: the positions times a
// factor. It counts its passes, so that a test can tell which one a run took.
namespace {

struct PassCounts {
  int topology = 0;
  int positions = 0;
};

class ScaleStage final : public PipelineStage {
 public:
  ScaleStage(double factor, PassCounts& counts) : factor_(factor), counts_(counts) {}

  std::string_view name() const override { return "scaled"; }
  bool is_on(const PipelineSettings&) const override { return true; }
  void topology_pass(const Mesh& input, const StagePass&) override {
    ++counts_.topology;
    result_ = input;
    for (Vec3& p : result_.positions()) p *= factor_;
  }
  Change positions_pass(const Mesh& input, const StagePass&) override {
    ++counts_.positions;
    for (Index v = 0; v < input.num_vertices(); ++v) result_.positions()[v] = input.positions()[v] * factor_;
    return Change::positions;
  }
  Mesh& result() override { return result_; }

 private:
  double factor_;
  PassCounts& counts_;
  Mesh result_;
};

// The built-in list with the scale stage right after the subdivision.
Pipeline scaling_pipeline(PassCounts& counts) {
  return Pipeline([&counts] {
    std::vector<std::unique_ptr<PipelineStage>> stages = builtin_stages();
    stages.insert(stages.begin() + 3, std::make_unique<ScaleStage>(2.0, counts));
    return stages;
  });
}

PipelineSettings subdivided_twice() {
  PipelineSettings s;
  s.stage = Stage::subdivided_offset;  // through the scale stage; no offset, nothing after it
  s.subdivision_levels = 2;
  return s;
}

Buffer<Vec3> scaled(Buffer<Vec3> positions, double factor) {
  for (Vec3& p : positions) p *= factor;
  return positions;
}

}  // namespace

TEST_CASE("the stage order and the editable stages are read from the built-in list", "[kernel]") {
  const std::vector<std::unique_ptr<PipelineStage>> stages = builtin_stages();
  const std::span<const Stage> order = builtin_stage_order();
  REQUIRE(stages.size() == order.size());
  for (size_t i = 0; i < stages.size(); ++i) {
    CHECK(stages[i]->name() == to_string(order[i]));
    CHECK(stages[i]->is_editable() == is_editable(order[i]));
    CHECK(parse_stage(stages[i]->name()) == order[i]);
  }
  CHECK(is_editable(Stage::merged));
  CHECK_FALSE(is_editable(Stage::subdivided));
  CHECK(parse_stage("subdivided-offset") == Stage::subdivided_offset);
  CHECK_FALSE(parse_stage("smoothed"));
  CHECK(passes_through(Stage::offset, Stage::subdivided));
  CHECK_FALSE(passes_through(Stage::subdivided, Stage::offset));
  CHECK(is_solid(Stage::subdivided_offset));
  CHECK_FALSE(is_solid(Stage::merged));
}

TEST_CASE("a stage added after the subdivision scales its result, and moved vertices take its positions pass",
          "[kernel]") {
  const PolygonSoup band = test::mobius_band(12, 2);
  PassCounts counts;
  Pipeline pipeline = scaling_pipeline(counts);
  pipeline.set_input(PipelineInput{band, {}, {}});
  const PipelineSettings s = subdivided_twice();

  Pipeline plain;
  plain.set_input(PipelineInput{band, {}, {}});
  PipelineSettings subdivided = s;
  subdivided.stage = Stage::subdivided;
  const Mesh expected = plain.run(subdivided);

  const Mesh& result = pipeline.run(s);
  CHECK(result.positions() == scaled(expected.positions(), 2.0));
  CHECK(result.corner_vertices() == expected.corner_vertices());
  CHECK(pipeline.work("scaled") == StageWork::rebuilt);
  CHECK((counts.topology == 1 && counts.positions == 0));

  // Nothing changed: the stage is not run.
  pipeline.run(s);
  CHECK(pipeline.work("scaled") == StageWork::cached);
  CHECK((counts.topology == 1 && counts.positions == 0));

  // A slider that moves vertices: the positions pass, not the topology pass.
  PolygonSoup dragged = band;
  for (Vec3& p : dragged.positions) p += Vec3(0.2 * p.y, 0.0, 0.1 * p.x * p.x);
  pipeline.move_input_vertices(dragged.positions);
  const Buffer<Vec3> moved = pipeline.run(s).positions();
  CHECK(pipeline.work("scaled") == StageWork::positions);
  CHECK(pipeline.result_change() == Change::positions);
  CHECK((counts.topology == 1 && counts.positions == 1));
  plain.move_input_vertices(dragged.positions);
  CHECK(moved == scaled(plain.run(subdivided).positions(), 2.0));

  // A stop before it leaves it out.
  CHECK(pipeline.run(subdivided).positions() == plain.run(subdivided).positions());
  CHECK(pipeline.work("scaled") == StageWork::skipped);
}

TEST_CASE("the offset after an added stage reads that stage's result", "[kernel]") {
  const PolygonSoup band = test::mobius_band(12, 2);
  PassCounts counts;
  Pipeline pipeline = scaling_pipeline(counts);
  pipeline.set_input(PipelineInput{band, {}, {}});
  PipelineSettings s = subdivided_twice();
  s.offset_distance = 0.04;
  s.stage = Stage::offset;
  // Doubling is exact in floating point, and so Catmull-Clark of the doubled band is its doubled result.
  PolygonSoup doubled = band;
  doubled.positions = scaled(doubled.positions, 2.0);
  Pipeline plain;
  plain.set_input(PipelineInput{doubled, {}, {}});
  CHECK(pipeline.run(s).positions() == plain.run(s).positions());
  CHECK(pipeline.work(Stage::offset) == StageWork::rebuilt);
  s.offset_distance = 0.08;
  CHECK(pipeline.run(s).positions() == plain.run(s).positions());
  CHECK(pipeline.work("scaled") == StageWork::cached);
  CHECK(pipeline.work(Stage::offset) == StageWork::positions);
}

TEST_CASE("a writer's surface runs a stage added after the subdivision or before the offset", "[kernel]") {
  const PolygonSoup band = test::mobius_band(12, 2);
  for (const Stage stop : {Stage::subdivided_offset, Stage::offset}) {
    PipelineSettings s = subdivided_twice();
    s.stage = stop;
    s.offset_distance = stop == Stage::offset ? 0.05 : 0.0;
    CAPTURE(to_string(stop));
    PassCounts counts;
    Pipeline pipeline = scaling_pipeline(counts);
    pipeline.set_input(PipelineInput{band, {}, {}});
    // run()'s mesh is the oracle: the writer's quads or offset surface must hold the same positions.
    const Buffer<Vec3> expected = pipeline.run(s).positions();
    Pipeline streamed = scaling_pipeline(counts);
    streamed.set_input(PipelineInput{band, {}, {}});
    const PipelineSurface surface = streamed.run_surface(s);
    CHECK(streamed.work("scaled") != StageWork::skipped);
    if (surface.mesh) {
      CHECK(surface.mesh->positions() == expected);
    } else if (surface.solid) {
      REQUIRE(surface.solid->num_vertices() == expected.size());
      for (Index v = 0; v < expected.size(); ++v) CHECK(surface.solid->position(v) == expected[v]);
    } else {
      REQUIRE(surface.quads);
      CHECK(std::equal(surface.quads->positions.begin(), surface.quads->positions.end(), expected.begin(),
                       expected.end()));
    }
  }
}
