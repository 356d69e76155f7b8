#include "viewer/commands/script.hpp"

#include <fstream>
#include <sstream>

#include "nome/error.hpp"
#include "nome/number_text.hpp"
#include "viewer/commands/actions.hpp"

namespace nome::viewer {
namespace {

struct Word {
  std::string text;
  int column;
};

std::vector<Word> split(const std::string& line) {
  std::vector<Word> words;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == '#') break;
    if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    words.push_back({line.substr(start, i - start), int(start) + 1});
  }
  return words;
}

bool parse_number(const std::string& s, double& out) {
  const char* end = s.data() + s.size();
  const auto result = number_from_chars(s.data(), end, out);
  return result.ec == std::errc() && result.ptr == end;
}

struct Syntax {
  const char* word;
  ScriptCommand::Kind kind;
  int words;    // leading word arguments
  int numbers;  // numeric arguments after them
  const char* expected;
};

const Syntax syntaxes[] = {
    {"set", ScriptCommand::Kind::set, 1, 1, "set BANK_PARAM VALUE"},
    {"mode", ScriptCommand::Kind::mode, 1, 0, "mode vertex|face|border|border-partial|edge|instance"},
    {"color", ScriptCommand::Kind::color, 0, 3, "color R G B (0..1)"},
    {"display-color", ScriptCommand::Kind::display_color, 1, 3, "display-color NAME R G B (0..1)"},
    {"click", ScriptCommand::Kind::click, 0, 2, "click X Y (window pixels)"},
    {"double-click", ScriptCommand::Kind::double_click, 0, 2, "double-click X Y (window pixels)"},
    {"key", ScriptCommand::Kind::key, 1, 0, "key LABEL (W, Ctrl+Z, F1, ...)"},
    {"action", ScriptCommand::Kind::action, 1, 0, "action NAME (add-polygon, zip, undo, ...)"},
    {"subdiv", ScriptCommand::Kind::subdiv, 0, 1, "subdiv LEVEL"},
    {"offset", ScriptCommand::Kind::offset, 0, 1, "offset DISTANCE"},
    {"setting", ScriptCommand::Kind::setting, 2, 0, "setting NAME VALUE"},
    {"view", ScriptCommand::Kind::view, 0, 2, "view AZIMUTH ELEVATION (degrees)"},
    {"screenshot", ScriptCommand::Kind::screenshot, 1, 0, "screenshot PATH.png"},
    {"save", ScriptCommand::Kind::save, 1, 0, "save PATH.nome"},
    {"export", ScriptCommand::Kind::export_file, 1, 0, "export PATH.stl|.obj|.glb|.ply"},
    {"recover", ScriptCommand::Kind::recover, 1, 0, "recover restore|discard"},
    {"drop", ScriptCommand::Kind::drop, 1, 0, "drop PATH"},
    {"prompt", ScriptCommand::Kind::prompt, 1, 0, "prompt save|discard|cancel"},
    {"layout", ScriptCommand::Kind::layout, 0, 0, "layout"},
    {"scroll", ScriptCommand::Kind::scroll, 1, 1, "scroll controls|parameters|log PIXELS"},
    {"state", ScriptCommand::Kind::state, 0, 0, "state (logs the topology line, selection and edit counts)"},
    {"text-set", ScriptCommand::Kind::text_set, 1, 0, "text-set PATH (the text pane's text, not applied)"},
    {"log-click", ScriptCommand::Kind::log_click, 0, 1, "log-click N (the N-th newest log message)"},
    {"tool", ScriptCommand::Kind::tool, 1, 0, "tool NAME (a command a tool adds)"},
    {"drag", ScriptCommand::Kind::drag, 1, 3, "drag SELECTION DX DY DZ"},
    {"drag", ScriptCommand::Kind::drag, 2, 1, "drag SELECTION x|y|z DISTANCE"},
    {"drag-hold", ScriptCommand::Kind::drag_hold, 1, 3, "drag-hold SELECTION DX DY DZ"},
    {"drag-hold", ScriptCommand::Kind::drag_hold, 2, 1, "drag-hold SELECTION x|y|z DISTANCE"},
    {"quit", ScriptCommand::Kind::quit, 0, 0, "quit"},
};

const char* const modes[] = {"vertex", "face", "border", "border-partial", "edge", "instance"};
const char* const recovery_answers[] = {"restore", "discard"};
const char* const settings[] = {"creases", "smooth-triangles", "border", "sharpness"};
const char* const unsaved_answers[] = {"save", "discard", "cancel"};
const char* const scrolled_panels[] = {"controls", "parameters", "log"};
const char* const axes[] = {"x", "y", "z"};
const char* const display_colors[] = {"default",   "back-faces", "selected",    "background",
                                      "rim-lines", "temporary",  "consolidated"};

template <typename List>
bool is_one_of(const std::string& word, const List& list) {
  for (const char* item : list)
    if (word == item) return true;
  return false;
}

// What the command's word argument should have been, or empty when it is one of its choices.
std::string expected_word(const ScriptCommand& command) {
  using Kind = ScriptCommand::Kind;
  if (command.words.empty()) return {};
  const std::string& word = command.words[0];
  if (command.kind == Kind::mode && !is_one_of(word, modes))
    return "vertex, face, border, border-partial, edge or instance";
  if (command.kind == Kind::action && !find_action(word)) return "an action (" + action_names() + ")";
  if (command.kind == Kind::recover && !is_one_of(word, recovery_answers)) return "restore or discard";
  if (command.kind == Kind::setting && !is_one_of(word, settings))
    return "creases, smooth-triangles, border or sharpness";
  if (command.kind == Kind::prompt && !is_one_of(word, unsaved_answers)) return "save, discard or cancel";
  if (command.kind == Kind::scroll && !is_one_of(word, scrolled_panels)) return "controls, parameters or log";
  if (command.kind == Kind::display_color && !is_one_of(word, display_colors))
    return "default, back-faces, selected, background, rim-lines, temporary or consolidated";
  return {};
}

// A colour's components are fractions of full brightness; anything else is a typing mistake. The first
// number outside 0..1, if any.
const Word* outside_unit_range(const ScriptCommand& command, const std::vector<Word>& words, int word_count) {
  using Kind = ScriptCommand::Kind;
  if (command.kind != Kind::color && command.kind != Kind::display_color) return nullptr;
  for (std::size_t i = 0; i < command.numbers.size(); ++i)
    if (!(command.numbers[i] >= 0.0 && command.numbers[i] <= 1.0)) return &words[1 + word_count + i];
  return nullptr;
}

std::string command_words() {
  std::string list;
  for (const Syntax& s : syntaxes)
    if (list.find(s.word) == std::string::npos) list += std::string(list.empty() ? "" : ", ") + s.word;
  return list;
}

}  // namespace

const char* script_synopsis() {
  return "script commands, one a line (# comments):\n"
         "  set BANK_PARAM VALUE      move a slider\n"
         "  mode vertex|face|border|border-partial|edge|instance\n"
         "  color R G B               give the selected instances this colour (0..1 each)\n"
         "  display-color NAME R G B  a colour of the Look panel: default, back-faces, selected,\n"
         "                            background, rim-lines, temporary or consolidated\n"
         "  click X Y                 left click at window pixel (X, Y), origin top-left\n"
         "  double-click X Y          move the orbit centre to the surface under pixel (X, Y)\n"
         "  key LABEL                 press a key of the help overlay (W, S, X, Ctrl+Z, ...)\n"
         "  action NAME               run an action: add-polygon, accept, clear, delete, zip, merge,\n"
         "                            undo, redo, or any of the help overlay's (wireframe, frame, ...)\n"
         "  subdiv LEVEL              subdivision level 0-6\n"
         "  offset DISTANCE           offset distance (0 turns offsetting off)\n"
         "  setting NAME VALUE        a Stage or Edit control: creases uniform|chaikin,\n"
         "                            smooth-triangles on|off, border none|edge-only|edge-and-corner,\n"
         "                            sharpness W|infinite (the weight K gives the selected edges)\n"
         "  view AZ EL                look from azimuth AZ and elevation EL (degrees), framed\n"
         "  screenshot PATH.png       save the window as a PNG\n"
         "  save PATH.nome            save the scene, slider values and edits\n"
         "  export PATH.stl|.obj|...  write the stage on screen (.glb, .ply too)\n"
         "  recover restore|discard   answer the offer to restore unsaved changes after a crash\n"
         "  drop PATH                 open PATH as if dropped on the window\n"
         "  prompt save|discard|cancel  answer the question about unsaved changes (quit, open)\n"
         "  layout                    print the viewport, each panel and each visible bank header as\n"
         "                            NAME X Y W H (window pixels; banks as bank NAME X Y W H)\n"
         "  scroll PANEL PIXELS       scroll controls, parameters or log (negative: up)\n"
         "  state                     log what is shown: topology, selection, edits, the text pane\n"
         "  text-set PATH             the text pane's text becomes PATH's, as if typed (not applied:\n"
         "                            action apply-text, action save-text)\n"
         "  log-click N               click the N-th newest log message (1: the newest): a located\n"
         "                            one puts the text pane's cursor at its line and column\n"
         "  tool NAME                 run a command a tool adds (listed with its key in the help)\n"
         "  drag SELECTION DX DY DZ   drag vertices or instances by that offset, as G and the mouse do:\n"
         "                            SELECTION is `selection` (the selected vertices or instances), a\n"
         "                            vertex's name or an instance's path; the text or sliders follow\n"
         "  drag SELECTION x|y|z D    the same along one axis\n"
         "  drag-hold SELECTION ...   the same, the drag left held as by the mouse (the handle and the\n"
         "                            changed numbers show): key Enter keeps it, key Esc cancels,\n"
         "                            keys X Y Z and digits act as while dragging\n"
         "  quit                      end the session (without asking: key Ctrl+Q asks)\n";
}

std::vector<ScriptCommand> parse_script(const std::string& text, const std::string& file) {
  std::vector<ScriptCommand> commands;
  std::string errors;
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  auto fail = [&](int column, const std::string& message) {
    errors += file + ":" + std::to_string(line_number) + ":" + std::to_string(column) + ": " + message + "\n";
  };
  while (std::getline(in, line)) {
    ++line_number;
    const std::vector<Word> words = split(line);
    if (words.empty()) continue;
    // A command with several forms takes the one its word count fits (else its first form is expected).
    const Syntax* syntax = nullptr;
    for (const Syntax& s : syntaxes)
      if (words[0].text == s.word && (!syntax || words.size() == std::size_t(1 + s.words + s.numbers)))
        syntax = syntax && words.size() == std::size_t(1 + syntax->words + syntax->numbers) ? syntax : &s;
    if (!syntax) {
      fail(words[0].column, "expected a command (" + command_words() + "), found '" + words[0].text + "'");
      continue;
    }
    const std::size_t wanted = 1 + syntax->words + syntax->numbers;
    if (words.size() != wanted) {
      const int column = words.size() > wanted ? words[wanted].column : int(line.size()) + 1;
      fail(column, std::string("expected '") + syntax->expected + "'");
      continue;
    }
    ScriptCommand command;
    command.kind = syntax->kind;
    command.line = line_number;
    bool is_valid = true;
    for (int i = 0; i < syntax->words; ++i) command.words.push_back(words[1 + i].text);
    for (int i = 0; i < syntax->numbers; ++i) {
      const Word& w = words[1 + syntax->words + i];
      double value = 0.0;
      if (!parse_number(w.text, value)) {
        fail(w.column,
             std::string("expected a number in '") + syntax->expected + "', found '" + w.text + "'");
        is_valid = false;
        break;
      }
      command.numbers.push_back(value);
    }
    if (!is_valid) continue;
    if (const std::string expected = expected_word(command); !expected.empty()) {
      fail(words[1].column, "expected " + expected + ", found '" + command.words[0] + "'");
      continue;
    }
    const bool is_drag =
        command.kind == ScriptCommand::Kind::drag || command.kind == ScriptCommand::Kind::drag_hold;
    if (is_drag && command.words.size() == 2 && !is_one_of(command.words[1], axes)) {
      fail(words[2].column, "expected an axis x, y or z, found '" + command.words[1] + "'");
      continue;
    }
    if (const Word* w = outside_unit_range(command, words, syntax->words)) {
      fail(w->column, "expected a colour component in 0..1, found '" + w->text + "'");
      continue;
    }
    commands.push_back(std::move(command));
  }
  if (!errors.empty()) {
    errors.pop_back();
    throw InvalidInputError(errors);
  }
  return commands;
}

std::vector<ScriptCommand> read_script(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path.string() + ": cannot read the script");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_script(text.str(), path.string());
}

}  // namespace nome::viewer
