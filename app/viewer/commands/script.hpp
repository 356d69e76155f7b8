#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace nome::viewer {

// One line of a viewer script (`nome FILE --script S.txt`): the command word and its arguments.
struct ScriptCommand {
  enum class Kind {
    set,
    mode,
    click,
    double_click,
    key,
    action,
    color,
    display_color,
    subdiv,
    offset,
    setting,
    view,
    screenshot,
    save,
    export_file,
    recover,
    drop,
    prompt,
    layout,
    scroll,
    state,
    text_set,
    log_click,
    tool,
    drag,
    drag_hold,
    quit
  };
  Kind kind = Kind::quit;
  std::vector<std::string> words;  // the arguments after the command word
  std::vector<double> numbers;     // the numeric arguments (set: value; click: x y; view: az el; ...)
  int line = 0;
};

// Parses a script: one command a line, `#` comments and blank lines ignored. Every malformed line is
// reported as `file:line:col: expected ...` in one InvalidInputError (nothing runs on a bad script).
std::vector<ScriptCommand> parse_script(const std::string& text, const std::string& file);
std::vector<ScriptCommand> read_script(const std::filesystem::path& path);

// The commands and their arguments, for --help and error messages.
const char* script_synopsis();

}  // namespace nome::viewer
