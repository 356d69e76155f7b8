#include "slide/slide_command.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include <tcl.h>

namespace nome::slide {
namespace {

std::vector<Tcl_Obj*> list_elements(Tcl_Obj* list) {
  Tcl_Obj** items = nullptr;
  int count = 0;
  if (Tcl_ListObjGetElements(nullptr, list, &count, &items) != TCL_OK)
    throw TclCommandError{"expected a Tcl list, found \"" + tcl_string(list) + "\""};
  return {items, items + count};
}

std::vector<scene::Name> names(Tcl_Obj* list, scene::SourceLocation at) {
  std::vector<scene::Name> out;
  for (Tcl_Obj* item : list_elements(list)) out.push_back({tcl_string(item), at});
  return out;
}

// `-option value` pairs after the positional arguments.
std::string option(std::span<Tcl_Obj* const> args, std::size_t from, const std::string& name) {
  for (std::size_t i = from; i + 1 < args.size(); i += 2)
    if (tcl_string(args[i]) == name) return tcl_string(args[i + 1]);
  return {};
}

// Holds a Tcl value for as long as it is read.
struct HeldObject {
  explicit HeldObject(Tcl_Obj* o) : obj(o) { Tcl_IncrRefCount(obj); }
  ~HeldObject() { Tcl_DecrRefCount(obj); }
  HeldObject(const HeldObject&) = delete;
  HeldObject& operator=(const HeldObject&) = delete;
  Tcl_Obj* obj;
};

template <class Decl>
void erase_named(std::vector<Decl>& decls, const std::string& name) {
  std::erase_if(decls, [&](const Decl& d) { return d.name.text == name; });
}

}  // namespace

SlideCommand::SlideCommand(scene::SceneAst& ast, scene::SourceLocation at,
                           std::function<scene::ExprId(std::string, scene::SourceLocation)> add_value)
    : ast_(ast), at_(at), add_value_(std::move(add_value)) {}

std::string SlideCommand::run(std::span<Tcl_Obj* const> args) {
  if (args.size() < 4)
    throw TclCommandError{
        "wrong # args: should be \"slide create TYPE NAME ...\" or \"slide delete TYPE NAME\""};
  const std::string verb = tcl_string(args[1]), type = tcl_string(args[2]);
  if (verb == "create") return create(type, args);
  if (verb == "delete") return remove(type, tcl_string(args[3]));
  throw TclCommandError{"'slide " + verb + "' is not supported yet (Nome has slide create and slide delete)"};
}

// A number, or `expr ...` as a list: a value Tcl computes whenever its sliders move.
scene::Value SlideCommand::coordinate(Tcl_Obj* element) {
  const std::vector<Tcl_Obj*> words = list_elements(element);
  if (!words.empty() && tcl_string(words[0]) == "expr") return {0, add_value_(tcl_string(element), at_), at_};
  double number = 0;
  if (Tcl_GetDoubleFromObj(nullptr, element, &number) != TCL_OK)
    throw TclCommandError{"expected a number or a list starting with expr, found \"" + tcl_string(element) +
                          "\""};
  return {number, no_index, at_};
}

// `{translate (x y z)} {rotate (ax ay az) angle} {scale (x y z)}`: a word that is no number (`$t`) is a
// value Tcl computes.
std::vector<scene::TransformDecl> SlideCommand::transforms(const std::string& xforms) {
  std::vector<scene::TransformDecl> out;
  const HeldObject list(Tcl_NewStringObj(xforms.data(), int(xforms.size())));
  for (Tcl_Obj* item : list_elements(list.obj)) {
    std::string text = tcl_string(item);
    std::replace(text.begin(), text.end(), '(', ' ');
    std::replace(text.begin(), text.end(), ')', ' ');
    std::istringstream in(text);
    std::string kind, word;
    in >> kind;
    scene::TransformDecl t;
    t.location = at_;
    int count = 3;
    if (kind == "translate")
      t.kind = scene::TransformKind::translate;
    else if (kind == "scale")
      t.kind = scene::TransformKind::scale;
    else if (kind == "rotate")
      t.kind = scene::TransformKind::rotate, count = 4;
    else
      throw TclCommandError{"expected translate, rotate or scale in -xforms, found \"" + kind + "\""};
    int k = 0;
    for (; k < count && in >> word; ++k) {
      char* end = nullptr;
      const double number = std::strtod(word.c_str(), &end);
      t.args[k] = *end == '\0' ? scene::Value{number, no_index, at_}
                               : scene::Value{0, add_value_("expr {" + word + "}", at_), at_};
    }
    if (k != count) throw TclCommandError{kind + " in -xforms takes " + std::to_string(count) + " numbers"};
    out.push_back(t);
  }
  return out;
}

std::string SlideCommand::create(const std::string& type, std::span<Tcl_Obj* const> args) {
  const std::string id = tcl_string(args[3]);
  const auto need = [&](std::size_t count, const char* usage) {
    if (args.size() < count)
      throw TclCommandError{std::string("wrong # args: should be \"slide create ") + usage + "\""};
  };
  if (type == "point") {
    need(5, "point NAME {x y z}");
    const std::vector<Tcl_Obj*> xyz = list_elements(args[4]);
    if (xyz.size() != 3)
      throw TclCommandError{"a point takes 3 coordinates, found " + std::to_string(xyz.size())};
    scene::PointDecl p{name(id), {}};
    for (int k = 0; k < 3; ++k) p.xyz[k] = coordinate(xyz[size_t(k)]);
    ast_.points.push_back(std::move(p));
  } else if (type == "face") {
    need(5, "face NAME {p1 p2 p3 ...} ?-surface S?");
    ast_.faces.push_back({name(id), names(args[4], at_), std::nullopt});
  } else if (type == "object") {
    need(5, "object NAME {f1 f2 ...}");
    ast_.objects.push_back({name(id), names(args[4], at_)});
  } else if (type == "group") {
    ast_.groups.push_back({name(id), {}});
  } else if (type == "instance") {
    need(6, "instance ID GROUP NODE ?-xforms {{translate (x y z)} ...}?");
    const std::string group = tcl_string(args[4]);
    const auto g = std::find_if(ast_.groups.begin(), ast_.groups.end(),
                                [&](const scene::GroupDecl& d) { return d.name.text == group; });
    if (g == ast_.groups.end())
      throw TclCommandError{"slide create instance: no group named \"" + group + "\""};
    scene::InstanceDecl instance{name(id), name(tcl_string(args[5])), {}, std::nullopt, at_};
    instance.transforms = transforms(option(args, 6, "-xforms"));
    g->instances.push_back(std::move(instance));
  } else {
    throw TclCommandError{"'slide create " + type +
                          "' is not supported yet (Nome creates point, face, object, "
                          "group and instance)"};
  }
  return id;
}

std::string SlideCommand::remove(const std::string& type, const std::string& id) {
  if (type == "point") {
    erase_named(ast_.points, id);
  } else if (type == "face") {
    erase_named(ast_.faces, id);
  } else if (type == "object" || type == "group") {
    type == "object" ? erase_named(ast_.objects, id) : erase_named(ast_.groups, id);
    for (scene::GroupDecl& g : ast_.groups)
      std::erase_if(g.instances, [&](const scene::InstanceDecl& i) { return i.target.text == id; });
  } else {
    throw TclCommandError{"'slide delete " + type +
                          "' is not supported yet (Nome deletes point, face, object and "
                          "group)"};
  }
  return {};
}

}  // namespace nome::slide
