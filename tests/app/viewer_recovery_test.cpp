#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "app/viewer_support.hpp"
#include "viewer/session/autosave.hpp"
#include "viewer/session/session.hpp"

using namespace nome;
using nome::viewer::Autosave;
using nome::viewer::Session;
namespace fs = std::filesystem;

namespace {

const char* funnel_scene =
    "bank b set h 1 0.5 2 0.1 endbank\n"
    "funnel f (4 1 0.5 {expr $b_h}) endfunnel\n"
    "instance i f endinstance\n";

// A scene and the recovery file a viewer that crashed after moving its slider to 1.7 left behind, in
// the recovery folder the window under test is given.
struct CrashedSession {
  fs::path dir, document, recovery;
  Autosave autosave;

  explicit CrashedSession(const std::string& name)
      : dir(nome::test::private_scratch_dir(name)),
        document(dir / "funnel.nome"),
        autosave(dir / "state" / "nome" / "recovery") {
    std::ofstream(document) << funnel_scene;
    Session session = Session::open(document);
    session.set_parameter("b_h", 1.7);
    autosave.update(session, 0.0);
    recovery = autosave.recovery_file(document);
    const auto now = fs::file_time_type::clock::now();
    fs::last_write_time(document, now - std::chrono::minutes(5));
    fs::last_write_time(recovery, now);
  }

  nome::test::CommandResult run_viewer(const std::string& script_text) const {
    const fs::path script = dir / "script.txt";
    std::ofstream(script) << script_text;
    return nome::test::run_window(
        document.string() + " --script " + script.string(),
        {dir / "state" / "recent", dir / "state" / "nome" / "recovery", dir / "state" / "layout"});
  }
};

}  // namespace

TEST_CASE("after a crash the viewer offers the unsaved changes, and restoring and saving keeps them",
          "[app]") {
  const CrashedSession crashed("viewer_recovery_restore");
  const auto r = crashed.run_viewer("recover restore\nkey Ctrl+S\nquit\n");
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("restored the unsaved changes of funnel.nome"));
  CHECK(Session::open(crashed.document).scene()->parameters().front().value == 1.7);
  CHECK_FALSE(fs::exists(crashed.recovery));
  fs::remove_all(crashed.dir);
}

TEST_CASE("after a crash the offered changes can be discarded, and the file stays as saved", "[app]") {
  const CrashedSession crashed("viewer_recovery_discard");
  const auto r = crashed.run_viewer("recover discard\nquit\n");
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(Session::open(crashed.document).scene()->parameters().front().value == 1.0);
  CHECK_FALSE(fs::exists(crashed.recovery));

  // Nothing is offered any more, and a clean quit after a slider move leaves no recovery file.
  const auto again = crashed.run_viewer("recover restore\nset b_h 1.2\nquit\n");
  CHECK(again.status == 1);
  CHECK_THAT(again.err, Catch::Contains("recover: no unsaved changes are offered"));
  CHECK_FALSE(fs::exists(crashed.recovery));
  fs::remove_all(crashed.dir);
}
