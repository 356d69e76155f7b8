#include "viewer/commands/script_runner.hpp"

#include "nome/error.hpp"

namespace nome::viewer {
namespace {

ScrolledPanel panel_named(const std::string& word) {
  if (word == "controls") return ScrolledPanel::controls;
  if (word == "log") return ScrolledPanel::log;
  return ScrolledPanel::parameters;
}

UnsavedAnswer answer_named(const std::string& word) {
  if (word == "save") return UnsavedAnswer::save;
  if (word == "discard") return UnsavedAnswer::discard;
  return UnsavedAnswer::cancel;
}

}  // namespace

ScriptRunner::ScriptRunner(std::filesystem::path file, std::vector<ScriptCommand> commands)
    : file_(std::move(file)), commands_(std::move(commands)) {}

void ScriptRunner::append(std::filesystem::path file, std::vector<ScriptCommand> commands) {
  if (is_done()) {
    commands_.clear();
    next_ = 0;
  }
  file_ = std::move(file);
  commands_.insert(commands_.end(), std::make_move_iterator(commands.begin()),
                   std::make_move_iterator(commands.end()));
}

void ScriptRunner::step(ScriptHost& host, MessageLog& log) {
  if (is_done()) return;
  const ScriptCommand& command = commands_[next_++];
  const std::string where = file_.string() + ":" + std::to_string(command.line) + ": ";
  try {
    if (run_command(host, command)) return;
    log.error(where + "the command failed");
  } catch (const std::exception& e) {
    log.error(where + e.what());
  }
  has_failed_ = true;
}

namespace {

// What a person does with the mouse and keys.
bool run_input_command(ScriptHost& host, const ScriptCommand& c) {
  using Kind = ScriptCommand::Kind;
  const glm::dvec2 pixel = c.numbers.size() == 2 ? glm::dvec2(c.numbers[0], c.numbers[1]) : glm::dvec2(0.0);
  switch (c.kind) {
    case Kind::click:
      host.click(pixel);
      return true;
    case Kind::double_click:
      return host.double_click(pixel);
    case Kind::drop:
      return host.drop({c.words[0]});
    case Kind::prompt:
      host.answer_unsaved(answer_named(c.words[0]));
      return true;
    case Kind::key:
      if (host.press_key(c.words[0])) return true;
      throw InvalidInputError("no key '" + c.words[0] + "' (press ? in the viewer for the list)");
    case Kind::action:
      return host.run_action(*find_action(c.words[0]));
    case Kind::view:
      host.set_view(c.numbers[0], c.numbers[1]);
      return true;
    case Kind::scroll:
      host.scroll(panel_named(c.words[0]), c.numbers[0]);
      return true;
    default:
      return false;
  }
}

}  // namespace

bool run_command(ScriptHost& host, const ScriptCommand& c) {
  using Kind = ScriptCommand::Kind;
  switch (c.kind) {
    case Kind::mode:
    case Kind::color:
    case Kind::text_set:
    case Kind::log_click:
    case Kind::tool:
    case Kind::drag:
    case Kind::drag_hold:
      return host.run_tool_script(c);
    case Kind::screenshot:
      host.take_screenshot(c.words[0]);
      return true;
    case Kind::export_file:
      return host.export_mesh(c.words[0]);
    case Kind::recover:
      host.answer_recovery(c.words[0] == "restore");
      return true;
    case Kind::set:
      host.set_parameter(c.words[0], c.numbers[0]);
      return true;
    case Kind::save:
      host.save(c.words[0]);
      return true;
    case Kind::subdiv:
      host.set_subdivision(c.numbers[0]);
      return true;
    case Kind::offset:
      host.set_offset(c.numbers[0]);
      return true;
    case Kind::display_color:
      host.set_display_color(c.words[0], glm::vec3(c.numbers[0], c.numbers[1], c.numbers[2]));
      return true;
    case Kind::setting:
      host.apply_setting(c.words[0], c.words[1]);
      return true;
    case Kind::layout:
      host.print_layout();
      return true;
    case Kind::state:
      host.print_state();
      return true;
    case Kind::quit:
      host.quit();
      return true;
    case Kind::click:
    case Kind::double_click:
    case Kind::drop:
    case Kind::prompt:
    case Kind::key:
    case Kind::action:
    case Kind::view:
    case Kind::scroll:
      return run_input_command(host, c);
  }
  return false;
}

}  // namespace nome::viewer
