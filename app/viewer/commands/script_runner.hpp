#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "viewer/commands/actions.hpp"
#include "viewer/commands/script.hpp"
#include "viewer/message_log.hpp"
#include "viewer/panels/panels.hpp"
#include "viewer/panels/prompt_dialog.hpp"

namespace nome::viewer {

// What a script can do to a window: each command of script.hpp is one call. A call returns false (or
// throws nome::Error) when the command failed; the runner then fails the session.
class ScriptHost {
 public:
  virtual ~ScriptHost() = default;
  virtual void click(glm::dvec2 pixel) = 0;
  // False when no surface is under the pixel.
  virtual bool double_click(glm::dvec2 pixel) = 0;
  virtual bool drop(const std::vector<std::filesystem::path>& paths) = 0;
  virtual void answer_unsaved(UnsavedAnswer answer) = 0;
  // False when no key has this label.
  virtual bool press_key(const std::string& label) = 0;
  virtual bool run_action(Action action) = 0;
  virtual void set_view(double azimuth, double elevation) = 0;
  virtual void take_screenshot(const std::filesystem::path& path) = 0;
  // False, with the reason in the log, when the file cannot be written.
  virtual bool export_mesh(const std::filesystem::path& path) = 0;
  virtual void answer_recovery(bool restore) = 0;
  virtual void set_parameter(const std::string& name, double value) = 0;
  virtual void save(const std::filesystem::path& path) = 0;
  virtual void set_subdivision(double levels) = 0;
  virtual void set_offset(double distance) = 0;
  // A colour of the Look panel by its script name (script.cpp's display-color names), as if picked there.
  virtual void set_display_color(const std::string& name, glm::vec3 color) = 0;
  // A control of the Stage or Edit section (script `setting NAME VALUE`); throws InvalidInputError for a
  // value it does not take.
  virtual void apply_setting(const std::string& name, const std::string& value) = 0;
  // Prints the layout report (script `layout`) once this frame's panels are drawn.
  virtual void print_layout() = 0;
  // Logs what the viewer shows (script `state`): the stage's topology line, the selection, and the scene's,
  // consolidated and temporary face counts, as one `state: ...` line.
  virtual void print_state() = 0;
  virtual void scroll(ScrolledPanel panel, double pixels) = 0;
  // A command the window's tools answer (mode, color, text-set, log-click, tool NAME); false when it
  // failed; throws InvalidInputError when no tool takes it.
  virtual bool run_tool_script(const ScriptCommand& command) = 0;
  virtual void quit() = 0;
};

// Replays a script one command per step; a failed command is logged as `file:line: ...` and fails the
// session (the exit status), and the rest still runs.
class ScriptRunner {
 public:
  ScriptRunner() = default;
  ScriptRunner(std::filesystem::path file, std::vector<ScriptCommand> commands);

  bool is_done() const { return next_ >= commands_.size(); }
  bool has_failed() const { return has_failed_; }
  bool has_commands() const { return !commands_.empty(); }
  // Runs the next command.
  void step(ScriptHost& host, MessageLog& log);
  // Commands that arrive while the window runs (a web page's script calls), run after those still queued.
  void append(std::filesystem::path file, std::vector<ScriptCommand> commands);

 private:
  std::filesystem::path file_;
  std::vector<ScriptCommand> commands_;
  std::size_t next_ = 0;
  bool has_failed_ = false;
};

// Runs one command on the host; false when it failed.
bool run_command(ScriptHost& host, const ScriptCommand& command);

}  // namespace nome::viewer
