#include "slide/tcl_script.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include <tcl.h>

#include "nome/error.hpp"
#include "nome/scene/expression.hpp"
#include "slide/scene_tcl.hpp"
#include "slide/slide_command.hpp"
#include "slide/slide_library.hpp"

namespace nome::slide {
namespace {

// A place inside a braced text that starts at `open` (its `{`): Tcl counts lines from 1 there.
scene::SourceLocation located(scene::SourceLocation open, int line) {
  return line <= 1 ? open : scene::SourceLocation{open.line + line - 1, 1};
}

std::string parameter_word(const std::string& text) {
  std::string word;
  for (char c : text) word += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  while (!word.empty() && word.back() == '_') word.pop_back();
  word.erase(0, word.find_first_not_of('_'));
  return word.empty() ? "slider" : word;
}

bool parse_number(const std::string& text, double& out) {
  std::istringstream in(text);
  in >> out;
  return in && (in >> std::ws).eof();
}

// SLIDE's library files, which Nome replaces with its own when a scene has no copy beside it.
bool is_library_file(const std::string& name) {
  const std::string file = std::filesystem::path(name).filename().string();
  return file == "SLIDEUI.tcl" || file == "MATH.tcl" || file == "SLFCONSTS.tcl" || file == "MOVIE.tcl";
}

}  // namespace

TclScript::TclScript(const scene::SceneAst& ast, std::filesystem::path folder, const TclReading& reading)
    : folder_(std::move(folder)), read_polygons_(reading.read_polygons) {
  interpreter_.limits = reading.limits;
  for (const scene::ScriptText& v : ast.script_values) values_.push_back({v.text, v.location, nullptr});
  add_commands();
  std::string result;
  TclFailure failure;
  interpreter_.eval(slide_constants_script(), result, failure);
  for (const auto& [variable, clock] :
       {std::pair{"SLF_TIME", scene::time_parameter}, std::pair{"SLF_FRAME", scene::frame_parameter}}) {
    Tcl_SetVar2(interpreter_.interp(), variable, nullptr, "0", TCL_GLOBAL_ONLY);
    bindings_.push_back(std::make_unique<Binding>(Binding{variable, clock, false, {}, 0.0, this, {}, {}}));
  }
}

TclScript::~TclScript() {
  for (CompiledValue& v : values_)
    if (v.script) Tcl_DecrRefCount(v.script);
}

void TclScript::add_commands() {
  interpreter_.add_command("source", [this](std::span<Tcl_Obj* const> args) {
    if (args.size() != 2) throw TclCommandError{"wrong # args: should be \"source fileName\""};
    return source(tcl_string(args[1]));
  });
  interpreter_.add_command("package", [this](std::span<Tcl_Obj* const> args) { return package(args); });
  for (const char* command : {"CreateSTLObject", "CreateSIFObject"})
    interpreter_.add_command(command, [this, command](std::span<Tcl_Obj* const> args) {
      if (args.size() != 3)
        throw TclCommandError{std::string("wrong # args: should be \"") + command + " name file\""};
      return mesh_file_object(tcl_string(args[1]), tcl_string(args[2]));
    });
  // SLIDE printed to its console; a scene's messages have no place in Nome's.
  interpreter_.add_command("puts", [](std::span<Tcl_Obj* const>) { return std::string(); });
  interpreter_.add_command("slide", [this](std::span<Tcl_Obj* const> args) -> std::string {
    if (!building_)
      throw TclCommandError{
          "'slide' after the scene was read (from a slider's command) is not supported yet"};
    scene::SceneAst& ast = *building_;
    SlideCommand command(ast, running_block_, [this, &ast](std::string text, scene::SourceLocation at) {
      ast.script_values.push_back({text, at});
      values_.push_back({std::move(text), at, nullptr});
      scene::ExprNode node;
      node.op = scene::ExprOp::script;
      node.script_expression = Index(ast.script_values.size() - 1);
      node.location = at;
      return ast.expressions.add(std::move(node));
    });
    return command.run(args);
  });
}

// `source NAME`: a file in the scene's folder, or Nome's own library in place of SLIDE's.
std::filesystem::path TclScript::scene_file(const std::string& name) const {
  const std::filesystem::path folder = std::filesystem::weakly_canonical(folder_.empty() ? "." : folder_);
  const std::filesystem::path file = std::filesystem::weakly_canonical(folder / name);
  const std::filesystem::path inside = file.lexically_relative(folder);
  const bool is_inside = !inside.empty() && *inside.begin() != "..";
  if (!is_inside || !std::filesystem::is_regular_file(file))
    throw TclCommandError{
        "couldn't read file \"" + name + "\": " +
        (is_inside ? "no such file beside the scene" : "a scene reads files in its own folder only")};
  return file;
}

std::string TclScript::source(const std::string& name) {
  std::filesystem::path file;
  try {
    file = scene_file(name);
  } catch (const TclCommandError&) {
    if (!is_library_file(name)) throw;
    load_library();
    return {};
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string script = text.str();
  Tcl_Interp* interp = interpreter_.interp();
  if (Tcl_EvalEx(interp, script.data(), int(script.size()), 0) != TCL_OK)
    throw TclCommandError{name + ":" + std::to_string(Tcl_GetErrorLine(interp)) + ": " +
                          tcl_string(Tcl_GetObjResult(interp))};
  return tcl_string(Tcl_GetObjResult(interp));
}

// `package require slideui` (or parselib, whose mesh readers are commands) loads Nome's version of SLIDE's
// library; Tk and Tcl are there already.
std::string TclScript::package(std::span<Tcl_Obj* const> args) {
  const std::string verb = args.size() > 1 ? tcl_string(args[1]) : "";
  const std::string name = args.size() > 2 ? tcl_string(args[2]) : "";
  if (verb != "require") return {};
  if (name == "slideui" || name == "parselib") {
    load_library();
    return "1.0";
  }
  if (name == "Tk" || name == "Tcl") return "8.6";
  throw TclCommandError{"can't find package " + name + " (Nome's SLIDE has slideui, parselib, Tk and Tcl)"};
}

std::string TclScript::mesh_file_object(const std::string& name, const std::string& file) {
  if (!building_) throw TclCommandError{"CreateSTLObject after the scene was read is not supported yet"};
  const std::filesystem::path path = scene_file(file);
  if (!read_polygons_) throw TclCommandError{"this program reads no mesh files from a scene's Tcl"};
  PolygonSoup soup;
  try {
    soup = read_polygons_(path);
  } catch (const Error& e) {
    throw TclCommandError{e.what()};
  }
  scene::SceneAst& ast = *building_;
  const scene::SourceLocation at = running_block_;
  for (Index v = 0; v < soup.num_vertices(); ++v) {
    const Vec3& p = soup.positions[v];
    ast.points.push_back({{name + "_v" + std::to_string(v), at},
                          {{p.x, no_index, at}, {p.y, no_index, at}, {p.z, no_index, at}}});
  }
  scene::ObjectDecl object{{"o" + name, at}, {}};
  for (Index f = 0; f < soup.num_faces(); ++f) {
    scene::FaceDecl face{{name + "_f" + std::to_string(f), at}, {}, std::nullopt};
    for (Index c = soup.face_offsets[f]; c < soup.face_offsets[f + 1]; ++c)
      face.vertices.push_back({name + "_v" + std::to_string(soup.face_vertices[c]), at});
    object.faces.push_back(face.name);
    ast.faces.push_back(std::move(face));
  }
  // Files instance the object (`instance oSURF`) and the name itself (`instance af`): the name is a group
  // of the object.
  ast.groups.push_back({{name, at}, {{{"o" + name, at}, {"o" + name, at}, {}, std::nullopt, at}}});
  ast.objects.push_back(std::move(object));
  return "o" + name;
}

void TclScript::load_library() {
  if (has_library_) return;
  has_library_ = true;
  const std::string_view script = slide_library_script();
  Tcl_Interp* interp = interpreter_.interp();
  if (Tcl_EvalEx(interp, script.data(), int(script.size()), TCL_EVAL_GLOBAL) != TCL_OK)
    throw TclCommandError{"Nome's SLIDE library failed: " + tcl_string(Tcl_GetObjResult(interp))};
}

void TclScript::run_blocks(scene::SceneAst& ast, scene::Diagnostics& diagnostics) {
  building_ = &ast;
  const std::vector<scene::ScriptText> blocks = ast.script_blocks;
  for (const scene::ScriptText& block : blocks) {
    running_block_ = block.location;
    tk_.running_block = block.location;
    std::string result;
    TclFailure failure;
    if (!interpreter_.eval(block.text, result, failure))
      diagnostics.error(located(block.location, failure.line), "Tcl: " + failure.message);
  }
  building_ = nullptr;
}

void TclScript::run_slider_commands(scene::SceneAst& ast, scene::Diagnostics& diagnostics) {
  building_ = &ast;
  for (const std::unique_ptr<Binding>& b : bindings_) {
    running_block_ = b->at;
    TclFailure failure;
    if (!run_slider_command(*b, failure))
      diagnostics.error(b->at, "Tcl: the command of slider '" + b->parameter_name + "': " + failure.message);
  }
  building_ = nullptr;
}

std::vector<scene::BankDecl> TclScript::slider_banks() {
  std::vector<scene::BankDecl> banks;
  std::vector<std::string> variables;
  Tcl_Interp* interp = interpreter_.interp();
  for (const TkWidget& w : tk_.widgets()) {
    const std::string variable = w.option("variable");
    if (w.type != "scale" || variable.empty()) continue;
    if (std::find(variables.begin(), variables.end(), variable) != variables.end()) continue;
    variables.push_back(variable);
    double from = 0, to = 100, resolution = 1, value = 0;
    parse_number(w.option("from", "0"), from);
    parse_number(w.option("to", "100"), to);
    parse_number(w.option("resolution", "1"), resolution);
    if (from > to) std::swap(from, to);
    if (!(resolution > 0)) resolution = to > from ? (to - from) / 100 : 1;
    const char* text = Tcl_GetVar2(interp, variable.c_str(), nullptr, TCL_GLOBAL_ONLY);
    if (!text || !parse_number(text, value)) value = from;
    const std::string toplevel = tk_.toplevel_of(w.path);
    const std::string bank_name =
        toplevel.empty() ? "sliders" : parameter_word(toplevel.substr(toplevel.rfind('.') + 1));
    auto bank = std::find_if(banks.begin(), banks.end(),
                             [&](const scene::BankDecl& b) { return b.name.text == bank_name; });
    if (bank == banks.end()) {
      banks.push_back({{bank_name, w.at}, {}, std::nullopt});
      bank = banks.end() - 1;
    }
    std::string name = parameter_word(variable);
    for (int k = 2; std::any_of(bank->sliders.begin(), bank->sliders.end(),
                                [&](const scene::SliderDecl& s) { return s.name.text == name; });
         ++k)
      name = parameter_word(variable) + "_" + std::to_string(k);
    const auto literal = [](double x) { return scene::Value{x, no_index, {}}; };
    bank->sliders.push_back(
        {{name, w.at}, literal(value), literal(from), literal(to), literal(resolution), w.option("label")});
    const bool is_whole = std::floor(resolution) == resolution && std::floor(from) == from;
    bindings_.push_back(std::make_unique<Binding>(
        Binding{variable, bank_name + "_" + name, is_whole, {}, value, this, w.option("command"), w.at}));
  }
  return banks;
}

char* TclScript::on_read(void* data, Tcl_Interp*, const char*, const char*, int) {
  const auto* binding = static_cast<const Binding*>(data);
  if (binding->script->reads_) binding->script->reads_->push_back(binding->parameter);
  return nullptr;
}

void TclScript::bind(const std::function<std::optional<scene::ParameterId>(const std::string&)>& find) {
  for (const std::unique_ptr<Binding>& b : bindings_) {
    if (b->parameter.is_valid()) continue;
    const std::optional<scene::ParameterId> id = find(b->parameter_name);
    if (!id) continue;
    b->parameter = *id;
    Tcl_TraceVar2(interpreter_.interp(), b->variable.c_str(), nullptr, TCL_TRACE_READS | TCL_GLOBAL_ONLY,
                  on_read, b.get());
  }
}

void TclScript::write_moved_sliders(std::span<const double> parameters, scene::SourceLocation at) {
  for (const std::unique_ptr<Binding>& b : bindings_) {
    if (!b->parameter.is_valid() || b->parameter.index() >= parameters.size()) continue;
    const double v = parameters[b->parameter.index()];
    if (v == b->written) continue;
    Tcl_Obj* value =
        b->is_whole && std::floor(v) == v ? Tcl_NewWideIntObj(Tcl_WideInt(v)) : Tcl_NewDoubleObj(v);
    Tcl_SetVar2Ex(interpreter_.interp(), b->variable.c_str(), nullptr, value, TCL_GLOBAL_ONLY);
    b->written = v;
    TclFailure failure;
    if (!run_slider_command(*b, failure))
      throw scene::EvaluationError(
          at, "Tcl: the command of slider '" + b->parameter_name + "': " + failure.message);
  }
}

bool TclScript::run_slider_command(const Binding& b, TclFailure& failure) {
  if (b.command.empty()) return true;
  const char* value = Tcl_GetVar2(interpreter_.interp(), b.variable.c_str(), nullptr, TCL_GLOBAL_ONLY);
  std::string result;
  return interpreter_.eval(b.command + " " + (value ? value : "0"), result, failure);
}

// A braced value is a Tcl command (`{ expr $a * 2 }`) or, as most files write it, an expression
// (`{$r}`, `{ -$thickness }`): SLIDE computed the latter as `expr` does.
double TclScript::evaluate(Index expression, std::span<const double> parameters,
                           scene::ParameterReads* reads) {
  CompiledValue& v = values_[expression];
  Tcl_Interp* interp = interpreter_.interp();
  if (!v.script) {
    const std::size_t start = v.text.find_first_not_of(" \t\r\n");
    const std::string first = start == std::string::npos
                                  ? ""
                                  : v.text.substr(start, v.text.find_first_of(" \t\r\n", start) - start);
    const bool is_command = !first.empty() &&
                            (std::isalpha(static_cast<unsigned char>(first[0])) || first[0] == '[') &&
                            first.find('(') == std::string::npos;
    const std::string text = is_command ? v.text : "expr {" + v.text + "}";
    v.script = Tcl_NewStringObj(text.data(), int(text.size()));
    Tcl_IncrRefCount(v.script);
  }
  write_moved_sliders(parameters, v.at);
  reads_ = reads;
  // What a slider's command computes (globals other values read) follows that slider: such a value is
  // taken to read every slider that has a command.
  if (reads)
    for (const std::unique_ptr<Binding>& b : bindings_)
      if (!b->command.empty() && b->parameter.is_valid()) reads->push_back(b->parameter);
  std::string result;
  TclFailure failure;
  const bool ok = interpreter_.eval(v.script, result, failure);
  reads_ = nullptr;
  if (!ok) throw scene::EvaluationError(located(v.at, failure.line), "Tcl: " + failure.message);
  double number = 0;
  if (Tcl_GetDouble(interp, result.c_str(), &number) != TCL_OK || !std::isfinite(number)) {
    Tcl_ResetResult(interp);
    throw scene::EvaluationError(v.at, "Tcl gave '" + result + "' where a number is expected");
  }
  return number;
}

void run_scene_tcl(scene::SceneAst& ast, const std::filesystem::path& folder, const TclReading& reading,
                   scene::Diagnostics& diagnostics) {
  auto script = std::make_shared<TclScript>(ast, folder, reading);
  script->run_blocks(ast, diagnostics);
  for (scene::BankDecl& bank : script->slider_banks()) ast.banks.push_back(std::move(bank));
  script->run_slider_commands(ast, diagnostics);
  ast.expressions.set_script(std::move(script));
}

}  // namespace nome::slide
