#include <catch2/catch.hpp>

#include "app/viewer_support.hpp"
#include "nome/io/sif.hpp"
#include "support/shared_examples.hpp"
#include "viewer/window.hpp"

using namespace nome;

namespace {

// Frames until the window closes; the face counts of the stage shown at the end of a frame, each time
// they change (a reopened file shows nothing until its stage is computed).
std::vector<Index> sif_shown_faces(nome::test::TestViewer& viewer) {
  std::vector<Index> seen;
  for (int frames = 0; viewer.frame() && frames < 10000; ++frames)
    if (const viewer::StageResult* shown = viewer.window().shown())
      if (seen.empty() || seen.back() != shown->mesh->num_faces()) seen.push_back(shown->mesh->num_faces());
  return seen;
}

}  // namespace

TEST_CASE("the viewer pairs a .sif file's triangles into quads unless told not to", "[app]") {
  NOME_NEEDS_SHARED_EXAMPLES("original");
  const std::string zero = nome::test::shared_examples_dir("original") + "zero.sif";
  const Index triangles = read_sif(zero).num_faces();
  const Index paired = read_sif(zero, {true, SifOptions{}.max_fold_degrees}).num_faces();
  REQUIRE(paired < triangles);
  const std::string dir = nome::test::private_scratch_dir("sif_pairing");

  viewer::ViewerOptions options;
  options.file = zero;
  // `view` after each toggle: its result is on screen at the end of a frame before the next command.
  options.script = nome::test::write_script(
      dir, "action pair-triangles\nview 30 25\naction pair-triangles\nview 30 25\nquit\n");
  nome::test::TestViewer on(options);
  CHECK(sif_shown_faces(on) == std::vector<Index>{paired, triangles, paired});
  CHECK(on.window().exit_status() == 0);

  options.pair_sif_triangles = false;  // `nome zero.sif --triangles`
  options.script = nome::test::write_script(dir, "quit\n");
  nome::test::TestViewer off(options);
  CHECK(sif_shown_faces(off) == std::vector<Index>{triangles});
}
