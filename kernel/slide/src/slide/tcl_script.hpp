#pragma once

#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "nome/scene/ast.hpp"
#include "nome/scene/expression_script.hpp"
#include "slide/safe_interpreter.hpp"
#include "slide/scene_tcl.hpp"
#include "slide/tk_stand_in.hpp"

namespace nome::slide {

// A .slf scene's Tcl: the interpreter its `tclinit` blocks ran in, which then computes its braced values.
// A slider is a Tcl variable bound to one of the scene's parameters: before a value is computed the
// variables whose parameters moved are set (an integer where the slider's step is whole, as Tk's scale
// gives it, so that Tcl's integer division stays SLIDE's), and read traces on them tell which
// parameters the value read.
class TclScript final : public scene::ExpressionScript {
 public:
  TclScript(const scene::SceneAst& ast, std::filesystem::path folder, const TclReading& reading);
  ~TclScript() override;

  // Runs the AST's blocks in file order; each error is reported and the next block runs. Their `slide`
  // commands edit the AST.
  void run_blocks(scene::SceneAst& ast, scene::Diagnostics& diagnostics);
  // The scales the blocks made, as the scene's banks of sliders (one per toplevel window), in order.
  std::vector<scene::BankDecl> slider_banks();
  // Runs every scale's command once with its value, its `slide` commands editing the AST: Tk ran it on the
  // first move only, leaving what it computes unset (a missing variable) until then.
  void run_slider_commands(scene::SceneAst& ast, scene::Diagnostics& diagnostics);

  void bind(const std::function<std::optional<scene::ParameterId>(const std::string&)>& find) override;
  double evaluate(Index expression, std::span<const double> parameters,
                  scene::ParameterReads* reads) override;
  std::string text(Index expression) const override { return values_[expression].text; }

 private:
  struct Binding {
    std::string variable;
    std::string parameter_name;  // the scene's full name
    bool is_whole = false;       // written as an integer
    scene::ParameterId parameter;
    double written = std::numeric_limits<double>::quiet_NaN();
    TclScript* script = nullptr;
    std::string command;  // the scale's -command: run with the value whenever the slider moves
    scene::SourceLocation at;
  };
  struct CompiledValue {
    std::string text;
    scene::SourceLocation at;
    Tcl_Obj* script = nullptr;  // compiled on first use
  };
  static char* on_read(void* data, Tcl_Interp*, const char*, const char*, int);
  void add_commands();
  std::string source(const std::string& name);
  // A file in the scene's folder (canonical), or a command error saying why not.
  std::filesystem::path scene_file(const std::string& name) const;
  // SLIDE's parselib: `CreateSTLObject NAME FILE` makes the object oNAME of the file's faces (its vertices
  // the points NAME_vK, its faces NAME_fK) and the group NAME of it, and returns the object's name.
  std::string mesh_file_object(const std::string& name, const std::string& file);
  std::string package(std::span<Tcl_Obj* const> args);
  void load_library();
  void write_moved_sliders(std::span<const double> parameters, scene::SourceLocation at);
  // Tk calls a scale's command with its new value; so does Nome when the slider moves.
  bool run_slider_command(const Binding& b, TclFailure& failure);

  std::filesystem::path folder_;
  PolygonFileReader read_polygons_;
  SafeInterpreter interpreter_;
  TkStandIn tk_{interpreter_};
  std::vector<CompiledValue> values_;
  std::vector<std::unique_ptr<Binding>> bindings_;
  scene::ParameterReads* reads_ = nullptr;
  bool has_library_ = false;
  scene::SceneAst* building_ = nullptr;  // while the blocks run
  scene::SourceLocation running_block_;
};

}  // namespace nome::slide
