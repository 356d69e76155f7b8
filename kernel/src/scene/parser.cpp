#include "nome/scene/parser.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "nome/scene/lexer.hpp"

namespace nome::scene {
namespace {

constexpr std::array top_level_keywords = {"bank",   "surface", "point",    "polyline", "face",
                                           "object", "funnel",  "tunnel",   "circle",   "mobiusstrip",
                                           "mesh",   "group",   "instance", "delete",   "consolidate"};

bool is_top_level_keyword(const Token& t) {
  return t.kind == TokenKind::word &&
         std::find(top_level_keywords.begin(), top_level_keywords.end(), t.text) != top_level_keywords.end();
}

std::string location_text(SourceLocation at) {
  return std::to_string(at.line) + ":" + std::to_string(at.column);
}

// Thrown after a syntax error has been reported: unwinds to the statement loop that resynchronises.
struct SyntaxError {};

// Expressions are parsed and evaluated recursively: deeper ones (a million parentheses, a sum of
// 200,000 terms) would overflow the stack, so they are refused. No real scene comes close.
constexpr int max_expression_depth = 256;

// Counts one level of recursion for as long as it lives.
struct DepthGuard {
  explicit DepthGuard(int& depth) : depth_(++depth) {}
  ~DepthGuard() { --depth_; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;
  int& depth_;
};

// Where the parser is: which tokens start a statement here and which word closes the enclosing block.
struct Context {
  std::vector<const char*> starters;
  const char* end_word;
};

class Parser {
 public:
  Parser(std::string_view text, Diagnostics& diagnostics, bool slf = false)
      : diagnostics_(diagnostics), tokens_(tokenize(text, diagnostics)), slf_(slf) {}

  SceneAst parse_scene() {
    ast_.file = diagnostics_.file();
    const Context top{{top_level_keywords.begin(), top_level_keywords.end()}, nullptr};
    while (peek().kind != TokenKind::end) {
      const size_t start = pos_;
      try {
        top_level_statement();
      } catch (const SyntaxError&) {
        resynchronise(top, start);
      }
    }
    if (slf_) choose_slf_roots();
    return std::move(ast_);
  }

  AnomAst parse_anom() {
    AnomAst anom;
    const Context top{{"savedparameter", "savedworkingmesh"}, nullptr};
    while (peek().kind != TokenKind::end) {
      const size_t start = pos_;
      try {
        const Token opener = take();
        if (opener.is_word("savedparameter")) {
          statement_end_ = "endsavedparameter";
          while (!block_closed(opener, "endsavedparameter", top)) {
            Name name = take_name("a parameter name");
            const Value v = literal_value();
            anom.saved_parameters.emplace_back(std::move(name), v.literal);
          }
        } else if (opener.is_word("savedworkingmesh")) {
          statement_end_ = "endsavedworkingmesh";
          take_name("the working mesh's name");
          const Context faces{{"face"}, "endsavedworkingmesh"};
          while (!block_closed(opener, "endsavedworkingmesh", faces)) {
            const Token face = peek();
            expect_word("face");
            NamedFace f{vertex_blocks("endface", face), face.location};
            if (f.vertices.size() < 3)
              diagnostics_.error(face.location,
                                 "a face of the working mesh needs at least 3 vertices, found " +
                                     std::to_string(f.vertices.size()));
            anom.working_mesh.push_back(std::move(f));
          }
        } else {
          fail(opener, "'savedparameter' or 'savedworkingmesh'");
        }
      } catch (const SyntaxError&) {
        resynchronise(top, start);
      }
    }
    return anom;
  }

 private:
  // --- tokens
  const Token& peek(size_t ahead = 0) const { return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)]; }
  Token take() {
    const Token& t = peek();
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
  }
  [[noreturn]] void fail(const Token& found, const std::string& expected) {
    diagnostics_.error(found.location, "expected " + expected + ", found " + found.describe());
    throw SyntaxError{};
  }
  void expect_word(const char* word) {
    if (!peek().is_word(word) && !near_miss(word)) fail(peek(), std::string("'") + word + "'");
    take();
  }
  // A closing word misspelt by a letter or two (hild.nom's `enintance`) is read as meant, with a warning.
  bool near_miss(const char* end_word) {
    const Token& t = peek();
    if (t.kind != TokenKind::word || std::string_view(end_word).substr(0, 3) != "end" ||
        is_top_level_keyword(t) || edit_distance(t.text, end_word) > 2)
      return false;
    diagnostics_.warning(t.location, "expected '" + std::string(end_word) + "', found '" + t.text +
                                         "': read as '" + end_word + "'");
    return true;
  }
  void expect_symbol(const char* symbol) {
    if (!peek().is_symbol(symbol)) fail(peek(), std::string("'") + symbol + "'");
    take();
  }
  Name take_name(const char* what) {
    if (peek().kind != TokenKind::word) fail(peek(), what);
    const Token t = take();
    return {normalize_name(t.text), t.location};
  }

  // Skips to the end of the failed statement or the next statement the context knows. Always moves on.
  void resynchronise(const Context& context, size_t statement_start) {
    if (pos_ == statement_start) take();
    while (peek().kind != TokenKind::end) {
      const Token& t = peek();
      if (statement_end_ && t.is_word(statement_end_)) {
        take();
        break;
      }
      // Statements usually start a line: a keyword in mid-line (`surface` in an instance) is no restart.
      const bool starts_line = pos_ == 0 || tokens_[pos_ - 1].location.line != t.location.line;
      if (t.kind == TokenKind::word &&
          ((context.end_word && t.text == context.end_word) ||
           (starts_line &&
            (is_top_level_keyword(t) || std::any_of(context.starters.begin(), context.starters.end(),
                                                    [&](const char* s) { return t.text == s; })))))
        break;
      take();
    }
    statement_end_ = nullptr;
  }

  // True (and consumes it) at the block's end word. At the end of the input, or at a statement that cannot
  // stand inside this block, reports the unclosed block at its opener and stops the block.
  bool block_closed(const Token& opener, const char* end_word, const Context& inner) {
    const Token& t = peek();
    if (t.is_word(end_word)) {
      take();
      return true;
    }
    const bool foreign = is_top_level_keyword(t) && std::none_of(inner.starters.begin(), inner.starters.end(),
                                                                 [&](const char* s) { return t.text == s; });
    if (t.kind == TokenKind::end || foreign) {
      diagnostics_.error(opener.location, "'" + opener.text + "' is never closed: expected '" + end_word +
                                              "', found " + t.describe() + " at " +
                                              location_text(t.location));
      return true;
    }
    return false;
  }

  // --- values and expressions
  Value literal_value() {
    const Token start = peek();
    double sign = 1;
    if (peek().is_symbol("-") || peek().is_symbol("+")) sign = take().text == "-" ? -1 : 1;
    if (peek().kind != TokenKind::number) fail(peek(), "a number");
    return {sign * take().number, no_index, start.location};
  }

  Value value() {
    const Token start = peek();
    if (start.is_symbol("{")) {
      take();
      if (peek().is_word("expr")) take();
      const ExprId e = expression();
      expect_symbol("}");
      return {0, e, start.location};
    }
    if (start.kind == TokenKind::parameter) return {0, primary(), start.location};
    if (start.kind == TokenKind::number || start.is_symbol("-") || start.is_symbol("+"))
      return literal_value();
    fail(start, "a number or '{expr ...}'");
  }

  // `( v v v )` with exactly `count` values.
  void value_tuple(Value* out, int count, const char* what) {
    const Token open = peek();
    expect_symbol("(");
    int n = 0;
    while (!peek().is_symbol(")") && peek().kind != TokenKind::end) {
      Value v = value();
      if (n < count) out[n] = v;
      ++n;
    }
    if (n != count) {
      diagnostics_.error(open.location, std::string(what) + " takes " + std::to_string(count) + " number" +
                                            (count == 1 ? "" : "s") + ", found " + std::to_string(n));
    }
    expect_symbol(")");
  }

  ExprId node(ExprOp op, SourceLocation at, ExprId a = no_index, ExprId b = no_index) {
    int depth = 1;
    for (ExprId child : {a, b})
      if (child != no_index) depth = std::max(depth, expression_depth_[child] + 1);
    if (depth > max_expression_depth) expression_too_deep(at);
    ExprNode n;
    n.op = op;
    n.location = at;
    n.args[0] = a;
    n.args[1] = b;
    const ExprId id = ast_.expressions.add(std::move(n));
    expression_depth_.resize(size_t(id) + 1, 0);
    expression_depth_[id] = depth;
    return id;
  }

  [[noreturn]] void expression_too_deep(SourceLocation at) {
    diagnostics_.error(
        at, "expression nested more than " + std::to_string(max_expression_depth) + " levels deep");
    throw SyntaxError{};
  }

  ExprId expression() {
    const ExprId left = additive();
    static constexpr std::pair<const char*, ExprOp> comparisons[] = {
        {"<", ExprOp::less},           {"<=", ExprOp::less_equal}, {">", ExprOp::greater},
        {">=", ExprOp::greater_equal}, {"==", ExprOp::equal},      {"!=", ExprOp::not_equal}};
    for (auto [text, op] : comparisons)
      if (peek().is_symbol(text)) {
        const Token t = take();
        return node(op, t.location, left, additive());
      }
    return left;
  }
  ExprId additive() {
    ExprId left = term();
    while (peek().is_symbol("+") || peek().is_symbol("-")) {
      const Token t = take();
      left = node(t.text == "+" ? ExprOp::add : ExprOp::subtract, t.location, left, term());
    }
    return left;
  }
  ExprId term() {
    ExprId left = unary();
    while (peek().is_symbol("*") || peek().is_symbol("/") || peek().is_symbol("%")) {
      const Token t = take();
      const ExprOp op = t.text == "*" ? ExprOp::multiply : t.text == "/" ? ExprOp::divide : ExprOp::modulo;
      left = node(op, t.location, left, unary());
    }
    return left;
  }
  ExprId unary() {
    // Every recursion of the expression grammar passes here.
    const DepthGuard guard(parse_depth_);
    if (parse_depth_ > max_expression_depth) expression_too_deep(peek().location);
    if (peek().is_symbol("-")) {
      const Token t = take();
      return node(ExprOp::negate, t.location, unary());
    }
    if (peek().is_symbol("+")) {
      take();
      return unary();
    }
    const ExprId base = primary();
    if (peek().is_symbol("^")) {
      const Token t = take();
      return node(ExprOp::power, t.location, base, unary());
    }
    return base;
  }
  ExprId primary() {
    const Token t = peek();
    if (t.kind == TokenKind::number) {
      take();
      const ExprId id = node(ExprOp::number, t.location);
      ast_.expressions.node(id).number = t.number;
      return id;
    }
    if (t.kind == TokenKind::parameter) {
      take();
      const ExprId id = node(ExprOp::parameter, t.location);
      ast_.expressions.node(id).parameter_name = normalize_name(t.text);
      return id;
    }
    if (t.is_symbol("(")) {
      take();
      const ExprId inner = expression();
      expect_symbol(")");
      return inner;
    }
    if (t.is_word("pi")) {
      take();
      return node(ExprOp::pi, t.location);
    }
    if (t.kind == TokenKind::word && peek(1).is_symbol("(")) {
      Function f{};
      int arity = 0;
      if (!find_function(t.text, f, arity)) {
        diagnostics_.error(t.location, "unknown function '" + t.text + "'" +
                                           did_you_mean(t.text, {"sin", "cos", "tan", "asin", "acos", "atan",
                                                                 "atan2", "sqrt", "abs", "pow", "exp", "log",
                                                                 "floor", "ceil", "min", "max"}));
        throw SyntaxError{};
      }
      take();
      take();
      ExprId args[2] = {no_index, no_index};
      int n = 0;
      if (!peek().is_symbol(")")) {
        do {
          const ExprId a = expression();
          if (n < 2) args[n] = a;
          ++n;
        } while (peek().is_symbol(",") && (take(), true));
      }
      expect_symbol(")");
      if (n != arity) {
        diagnostics_.error(t.location, "function '" + t.text + "' takes " + std::to_string(arity) +
                                           " argument" + (arity == 1 ? "" : "s") + ", found " +
                                           std::to_string(n));
        throw SyntaxError{};
      }
      const ExprId id = node(ExprOp::call, t.location, args[0], args[1]);
      ast_.expressions.node(id).function = f;
      return id;
    }
    if (t.kind == TokenKind::word) {
      diagnostics_.error(
          t.location, "unknown name '" + t.text + "' in an expression (parameters are written $bank_name)");
      throw SyntaxError{};
    }
    fail(t, "a number, '$parameter', a function or '('");
  }

  // --- statements
  std::vector<Name> name_list(const char* what) {
    expect_symbol("(");
    std::vector<Name> names;
    while (!peek().is_symbol(")")) names.push_back(take_name(what));
    take();
    return names;
  }

  std::optional<Name> optional_surface() {
    if (!peek().is_word("surface")) return std::nullopt;
    take();
    return take_name("a surface name");
  }

  FaceDecl face_statement() {
    statement_end_ = "endface";
    expect_word("face");
    FaceDecl f;
    f.name = take_name("a face name");
    const Token open = peek();
    f.vertices = name_list("a vertex name or ')'");
    if (f.vertices.size() < 3)
      diagnostics_.error(open.location, "face '" + f.name.text + "' needs at least 3 vertices, found " +
                                            std::to_string(f.vertices.size()));
    const Token surface = peek();
    f.surface = optional_surface();
    if (slf_) ignore_surface(surface, f.surface);
    expect_word("endface");
    return f;
  }

  InstanceDecl instance_statement() {
    statement_end_ = "endinstance";
    InstanceDecl inst;
    inst.location = peek().location;
    expect_word("instance");
    if (slf_) {
      // SLIDE: `instance TARGET [id NAME] ...`; the instance is named by its id, else by its target.
      inst.target = take_name("the name of what to instantiate");
      inst.name = inst.target;
    } else {
      inst.name = take_name("an instance name");
      inst.target = take_name("the name of what to instantiate");
    }
    while (!peek().is_word("endinstance") && !near_miss("endinstance")) {
      const Token t = peek();
      TransformDecl tr;
      tr.location = t.location;
      if (t.is_word("translate") || t.is_word("scale")) {
        take();
        tr.kind = t.text == "translate" ? TransformKind::translate : TransformKind::scale;
        value_tuple(tr.args, 3, t.text.c_str());
      } else if (t.is_word("rotate")) {
        take();
        tr.kind = TransformKind::rotate;
        value_tuple(tr.args, 3, "rotate's axis");
        value_tuple(tr.args + 3, 1, "rotate's angle");
      } else if (t.is_word("mirror")) {
        take();
        tr.kind = TransformKind::mirror;
        value_tuple(tr.args, 4, "mirror");
      } else if (t.is_word("surface")) {
        inst.surface = optional_surface();
        if (slf_) ignore_surface(t, inst.surface);
        continue;
      } else if (slf_ && t.is_word("id")) {
        take();
        inst.name = take_name("an instance id");
        continue;
      } else if (slf_ && t.kind == TokenKind::word) {
        diagnostics_.error(t.location, "not supported yet: " + t.text);
        throw SyntaxError{};
      } else {
        fail(t, "a transform (translate, rotate, scale, mirror), 'surface' or 'endinstance'");
      }
      inst.transforms.push_back(tr);
    }
    take();
    return inst;
  }

  void generator_statement(GeneratorKind kind, const char* end_word, const char* alternative_end,
                           const char* signature, size_t count, size_t alternative_count = 0) {
    statement_end_ = end_word;
    const Token keyword = take();
    GeneratorDecl g;
    g.kind = kind;
    g.name = take_name("a name");
    const Token open = peek();
    expect_symbol("(");
    while (!peek().is_symbol(")") && peek().kind != TokenKind::end) g.args.push_back(value());
    expect_symbol(")");
    if (g.args.size() != count && g.args.size() != alternative_count)
      diagnostics_.error(open.location, keyword.text + " '" + g.name.text + "' takes " +
                                            std::to_string(count) + " arguments " + signature + ", found " +
                                            std::to_string(g.args.size()));
    if (alternative_end && peek().is_word(alternative_end))
      take();
    else
      expect_word(end_word);
    ast_.generators.push_back(std::move(g));
  }

  std::vector<Name> vertex_blocks(const char* end_word, const Token& opener) {
    std::vector<Name> names;
    const Context inner{{"vertex"}, end_word};
    while (!block_closed(opener, end_word, inner)) {
      expect_word("vertex");
      names.push_back(take_name("a vertex name"));
      expect_word("endvertex");
    }
    return names;
  }

  void top_level_statement() {
    const Token t = peek();
    statement_end_ = nullptr;
    if (slf_ && !(t.is_word("surface") || t.is_word("point") || t.is_word("face") || t.is_word("object") ||
                  t.is_word("group") || t.is_word("instance"))) {
      if (t.kind != TokenKind::word) fail(t, "a statement (point, face, object, group, instance, surface)");
      diagnostics_.error(t.location, "not supported yet: " + t.text);
      skip_unsupported(t.text);
      return;
    }
    if (t.is_word("bank")) {
      bank();
    } else if (t.is_word("surface")) {
      statement_end_ = "endsurface";
      take();
      SurfaceDecl s;
      s.name = take_name("a surface name");
      expect_word("color");
      value_tuple(s.rgb, 3, "color");
      expect_word("endsurface");
      if (slf_)
        diagnostics_.warning(t.location,
                             "surface '" + s.name.text + "' ignored: colours of .slf files are not read");
      else
        ast_.surfaces.push_back(std::move(s));
    } else if (t.is_word("point")) {
      statement_end_ = "endpoint";
      take();
      PointDecl p;
      p.name = take_name("a point name");
      value_tuple(p.xyz, 3, "point");
      expect_word("endpoint");
      ast_.points.push_back(std::move(p));
    } else if (t.is_word("polyline")) {
      statement_end_ = "endpolyline";
      take();
      PolylineDecl p;
      p.name = take_name("a polyline name");
      const Token open = peek();
      p.vertices = name_list("a vertex name or ')'");
      if (p.vertices.size() < 2)
        diagnostics_.error(open.location, "polyline '" + p.name.text + "' needs at least 2 vertices, found " +
                                              std::to_string(p.vertices.size()));
      if (peek().is_word("isloop")) {
        take();
        p.is_loop = true;
      }
      expect_word("endpolyline");
      ast_.polylines.push_back(std::move(p));
    } else if (t.is_word("face")) {
      ast_.faces.push_back(face_statement());
    } else if (t.is_word("object")) {
      statement_end_ = "endobject";
      take();
      ObjectDecl o;
      o.name = take_name("an object name");
      o.faces = name_list("a face name or ')'");
      expect_word("endobject");
      ast_.objects.push_back(std::move(o));
    } else if (t.is_word("funnel")) {
      generator_statement(GeneratorKind::funnel, "endfunnel", nullptr, "(n ro ratio h)", 4);
    } else if (t.is_word("tunnel")) {
      // The report's klein_bottle.nome closes its tunnels with endfunnel.
      generator_statement(GeneratorKind::tunnel, "endtunnel", "endfunnel", "(n ro ratio h [ratio_low h_low])",
                          4, 6);
    } else if (t.is_word("circle")) {
      generator_statement(GeneratorKind::circle, "endcircle", nullptr, "(n r)", 2);
    } else if (t.is_word("mobiusstrip")) {
      generator_statement(GeneratorKind::mobius_strip, "endmobiusstrip", nullptr, "(radius twists cuts segs)",
                          4);
    } else if (t.is_word("mesh")) {
      mesh();
    } else if (t.is_word("group")) {
      group();
    } else if (t.is_word("instance")) {
      ast_.instances.push_back(instance_statement());
    } else if (t.is_word("delete")) {
      const Token opener = take();
      const Context inner{{"face"}, "enddelete"};
      while (!block_closed(opener, "enddelete", inner)) {
        statement_end_ = "endface";
        expect_word("face");
        ast_.deleted_faces.push_back(take_name("a face name"));
        expect_word("endface");
      }
    } else if (t.is_word("consolidate")) {
      const Token opener = take();
      const Context inner{{"consolidateface"}, "endconsolidate"};
      while (!block_closed(opener, "endconsolidate", inner)) {
        const Token face = peek();
        expect_word("consolidateface");
        NamedFace f{vertex_blocks("endconsolidateface", face), face.location};
        if (f.vertices.size() < 3)
          diagnostics_.error(face.location, "a consolidated face needs at least 3 vertices, found " +
                                                std::to_string(f.vertices.size()));
        ast_.consolidated_faces.push_back(std::move(f));
      }
    } else {
      fail(t,
           "a statement (bank, surface, point, polyline, face, object, funnel, tunnel, circle, "
           "mobiusstrip, mesh, group, instance, delete, consolidate)");
    }
  }

  // .slf: colours are not read; say so once per use.
  void ignore_surface(const Token& at, std::optional<Name>& surface) {
    if (!surface) return;
    diagnostics_.warning(at.location,
                         "surface '" + surface->text + "' ignored: colours of .slf files are not read");
    surface.reset();
  }

  // .slf: skips an unsupported statement: to its `endWORD`, or over a `{ ... }` block (tclinit).
  void skip_unsupported(const std::string& word) {
    take();
    if (peek().is_symbol("{")) {
      int depth = 0;
      do {
        if (peek().is_symbol("{")) ++depth;
        if (peek().is_symbol("}")) --depth;
        take();
      } while (depth > 0 && peek().kind != TokenKind::end);
      return;
    }
    for (size_t i = pos_; i < tokens_.size(); ++i)
      if (tokens_[i].is_word("end" + word)) {
        pos_ = i + 1;
        return;
      }
  }

  // .slf files name no root: without top-level instances, every group no instance uses is one (else every
  // object, else every face), as SLIDE's render statement would draw it.
  void choose_slf_roots() {
    if (!ast_.instances.empty()) return;
    std::vector<std::string> used;
    for (const GroupDecl& g : ast_.groups)
      for (const InstanceDecl& i : g.instances) used.push_back(i.target.text);
    auto add_roots = [&](const auto& decls) {
      for (const auto& d : decls)
        if (std::find(used.begin(), used.end(), d.name.text) == used.end())
          ast_.instances.push_back({d.name, d.name, {}, std::nullopt, d.name.location});
      return !ast_.instances.empty();
    };
    if (add_roots(ast_.groups) || add_roots(ast_.objects)) return;
    add_roots(ast_.faces);
  }

  void bank() {
    const Token opener = take();
    BankDecl b;
    b.name = take_name("a bank name");
    const Context inner{{"set"}, "endbank"};
    while (!block_closed(opener, "endbank", inner)) {
      const size_t start = pos_;
      try {
        statement_end_ = nullptr;
        expect_word("set");
        SliderDecl s;
        s.name = take_name("a parameter name");
        s.value = literal_value();
        s.min = literal_value();
        s.max = literal_value();
        s.step = literal_value();
        check_slider(b.name.text, s);
        b.sliders.push_back(std::move(s));
      } catch (const SyntaxError&) {
        resynchronise(inner, start);
      }
    }
    ast_.banks.push_back(std::move(b));
  }

  void check_slider(const std::string& bank, const SliderDecl& s) {
    const std::string full = bank + "_" + s.name.text;
    if (s.min.literal > s.max.literal)
      diagnostics_.error(s.min.location, "slider '" + full + "': min " + format_number(s.min.literal) +
                                             " is above max " + format_number(s.max.literal));
    else if (s.value.literal < s.min.literal || s.value.literal > s.max.literal)
      diagnostics_.error(s.value.location, "value " + format_number(s.value.literal) + " of '" + full +
                                               "' is outside its slider range [" +
                                               format_number(s.min.literal) + ", " +
                                               format_number(s.max.literal) + "]");
    if (!(s.step.literal > 0))
      diagnostics_.error(s.step.location, "slider '" + full + "': step must be positive, found " +
                                              format_number(s.step.literal));
  }

  void mesh() {
    const Token opener = take();
    MeshDecl m;
    m.name = take_name("a mesh name");
    const Context inner{{"face", "sharp"}, "endmesh"};
    while (!block_closed(opener, "endmesh", inner)) {
      const size_t start = pos_;
      try {
        if (peek().is_word("face")) {
          m.faces.push_back(face_statement());
        } else if (peek().is_word("sharp")) {
          statement_end_ = "endsharp";
          SharpDecl s;
          s.location = take().location;
          s.vertices = name_list("a vertex name or ')'");
          if (s.vertices.size() < 2)
            diagnostics_.error(s.location,
                               "sharp needs at least 2 vertices, found " + std::to_string(s.vertices.size()));
          expect_word("endsharp");
          m.sharps.push_back(std::move(s));
        } else {
          fail(peek(), "'face', 'sharp' or 'endmesh'");
        }
      } catch (const SyntaxError&) {
        resynchronise(inner, start);
      }
    }
    ast_.meshes.push_back(std::move(m));
  }

  void group() {
    const Token opener = take();
    GroupDecl g;
    g.name = take_name("a group name");
    const Context inner{{"instance"}, "endgroup"};
    while (!block_closed(opener, "endgroup", inner)) {
      const size_t start = pos_;
      try {
        if (!peek().is_word("instance")) fail(peek(), "'instance' or 'endgroup'");
        g.instances.push_back(instance_statement());
      } catch (const SyntaxError&) {
        resynchronise(inner, start);
      }
    }
    ast_.groups.push_back(std::move(g));
  }

  Diagnostics& diagnostics_;
  std::vector<Token> tokens_;
  size_t pos_ = 0;
  bool slf_ = false;                     // the SLIDE subset of .slf files
  const char* statement_end_ = nullptr;  // the word that closes the statement being parsed
  SceneAst ast_;
  std::vector<int> expression_depth_;  // height of each expression node's subtree
  int parse_depth_ = 0;                // expression grammar levels being parsed
};

}  // namespace

std::string normalize_name(std::string name) {
  std::replace(name.begin(), name.end(), '.', '_');
  return name;
}

SceneAst parse_nome(std::string_view text, Diagnostics& diagnostics) {
  return Parser(text, diagnostics).parse_scene();
}

SceneAst parse_slf(std::string_view text, Diagnostics& diagnostics) {
  return Parser(text, diagnostics, true).parse_scene();
}

AnomAst parse_anom(std::string_view text, Diagnostics& diagnostics) {
  return Parser(text, diagnostics).parse_anom();
}

}  // namespace nome::scene
