#include <catch2/catch.hpp>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/cli_support.hpp"
#include "viewer/session/autosave.hpp"
#include "viewer/session/session.hpp"

using namespace nome;
using nome::viewer::Autosave;
using nome::viewer::Session;
namespace fs = std::filesystem;

namespace {

// A funnel whose height is a slider: four faces f0..f3 in instance i.
const char* funnel_scene =
    "bank b set h 1 0.5 2 0.1 endbank\n"
    "funnel f (4 1 0.5 {expr $b_h}) endfunnel\n"
    "instance i f endinstance\n";

void delete_first_face(Session& session) {
  const Mesh shown = build_mesh(session.polygons());
  const Index face = 0;
  REQUIRE(session.delete_faces(shown, {&face, 1}).applied);
}

}  // namespace

TEST_CASE("autosave keeps unsaved changes in a recovery file: at once per edit, every 30 s for sliders",
          "[app]") {
  const fs::path dir = nome::test::private_scratch_dir("autosave_write");
  const fs::path document = dir / "funnel.nome", folder = dir / "state";
  std::ofstream(document) << funnel_scene;
  Session session = Session::open(document);
  Autosave autosave(folder);
  const fs::path recovery = autosave.recovery_file(document);
  CHECK(recovery.parent_path() == folder);

  autosave.update(session, 0.0);
  CHECK_FALSE(fs::exists(recovery));  // nothing unsaved

  // The first change is kept at once; what the file holds opens as the changed scene.
  session.set_parameter("b_h", 1.5);
  autosave.update(session, 1.0);
  REQUIRE(fs::exists(recovery));
  CHECK(Session::restore(document, recovery).scene()->parameters().front().value == 1.5);

  // Slider moves wait for the interval...
  session.set_parameter("b_h", 1.8);
  autosave.update(session, 10.0);
  CHECK(Session::restore(document, recovery).scene()->parameters().front().value == 1.5);
  autosave.update(session, 1.0 + Autosave::interval_seconds);
  CHECK(Session::restore(document, recovery).scene()->parameters().front().value == 1.8);

  // ...an accepted edit does not.
  delete_first_face(session);
  autosave.update(session, 32.0);
  const Session restored = Session::restore(document, recovery);
  CHECK(restored.document().deleted_faces().size() == 1);
  CHECK(restored.polygons().num_faces() == 3);
  CHECK(restored.path() == document);
  CHECK(restored.is_modified());
  CHECK(fs::is_empty(folder) == false);
  CHECK(std::distance(fs::directory_iterator(folder), fs::directory_iterator()) == 1);  // no temporary left

  // Saving makes it obsolete: it goes.
  session.save(document);
  autosave.update(session, 33.0);
  CHECK_FALSE(fs::exists(recovery));
  fs::remove_all(dir);
}

TEST_CASE("a recovery file newer than its document is offered, and restoring it gives unsaved changes",
          "[app]") {
  const fs::path dir = nome::test::private_scratch_dir("autosave_offer");
  const fs::path document = dir / "funnel.nome", other = dir / "other" / "funnel.nome";
  fs::create_directories(other.parent_path());
  std::ofstream(document) << funnel_scene;
  std::ofstream(other) << funnel_scene;
  Autosave autosave(dir / "state");
  CHECK(autosave.recovery_file(document) != autosave.recovery_file(other));
  CHECK(autosave.recovery_file(document) == autosave.recovery_file(dir / "other" / ".." / "funnel.nome"));
  CHECK_FALSE(autosave.pending_recovery(document));

  {  // a viewer that changes the scene and never ends cleanly
    Session session = Session::open(document);
    session.set_parameter("b_h", 0.7);
    delete_first_face(session);
    autosave.update(session, 0.0);
  }
  const fs::path recovery = autosave.recovery_file(document);
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(document, now - std::chrono::minutes(5));
  fs::last_write_time(recovery, now);
  CHECK(autosave.pending_recovery(document) == recovery);
  CHECK_FALSE(autosave.pending_recovery(other));

  Session restored = Session::restore(document, recovery);
  CHECK(restored.is_modified());
  CHECK(restored.scene()->parameters().front().value == 0.7);
  CHECK(restored.polygons().num_faces() == 3);
  restored.save(document);  // Save writes the document itself
  const Session reopened = Session::open(document);
  CHECK(reopened.scene()->parameters().front().value == 0.7);
  CHECK(reopened.polygons().num_faces() == 3);

  // A document saved after the recovery file was written is not offered it.
  fs::last_write_time(recovery, now - std::chrono::minutes(10));
  CHECK_FALSE(autosave.pending_recovery(document));
  autosave.discard(document);
  CHECK_FALSE(fs::exists(recovery));
  fs::remove_all(dir);
}

TEST_CASE("opening, restoring and reloading evaluate the scene once; saving and autosaving not at all",
          "[app]") {
  const fs::path dir = nome::test::private_scratch_dir("autosave_evaluations");
  const fs::path document = dir / "funnel.nome";
  std::ofstream(document) << funnel_scene << "delete face i_f1 endface enddelete\n";
  std::uint64_t evaluations = scene::scene_evaluation_count();
  Session session = Session::open(document);
  CHECK(scene::scene_evaluation_count() == evaluations + 1);
  CHECK(session.document().deleted_faces() == std::vector<std::string>{"i_f1"});
  CHECK(session.polygons().num_faces() == 3);

  session.set_parameter("b_h", 1.5);
  delete_first_face(session);
  Autosave autosave(dir / "state");
  evaluations = scene::scene_evaluation_count();
  autosave.update(session, 0.0);
  session.save(dir / "saved.nome");
  CHECK(scene::scene_evaluation_count() == evaluations);
  const fs::path recovery = autosave.recovery_file(document);
  REQUIRE(fs::exists(recovery));

  const Session restored = Session::restore(document, recovery);
  CHECK(scene::scene_evaluation_count() == evaluations + 1);
  CHECK(restored.document().deleted_faces().size() == 2);
  CHECK(restored.polygons().num_faces() == 2);
  session.reload();
  CHECK(scene::scene_evaluation_count() == evaluations + 2);
  CHECK(session.document().deleted_faces().size() == 2);
  fs::remove_all(dir);
}

TEST_CASE("recovery files live in the user's state folder, and flat geometry has none", "[app]") {
  const char* state = std::getenv("XDG_STATE_HOME");
  const std::string saved_state = state ? state : "",
                    saved_home = std::getenv("HOME") ? std::getenv("HOME") : "";
  ::setenv("XDG_STATE_HOME", "/tmp/nome-state", 1);
  CHECK(Autosave::default_folder() == fs::path("/tmp/nome-state/nome/recovery"));
  ::unsetenv("XDG_STATE_HOME");
  ::setenv("HOME", "/home/someone", 1);
  CHECK(Autosave::default_folder() == fs::path("/home/someone/.local/state/nome/recovery"));
  ::setenv("HOME", saved_home.c_str(), 1);
  if (state) ::setenv("XDG_STATE_HOME", saved_state.c_str(), 1);

  const fs::path dir = nome::test::private_scratch_dir("autosave_flat");
  std::ofstream(dir / "square.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2 5 3\n";
  Session session = Session::open(dir / "square.obj");
  delete_first_face(session);
  Autosave autosave(dir / "state");
  autosave.update(session, 0.0);
  CHECK_FALSE(fs::exists(dir / "state"));
  fs::remove_all(dir);
}
