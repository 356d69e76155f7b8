#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "scene/scene_support.hpp"

using nome::test::scene_errors;

namespace {

struct Case {
  const char* text;
  const char* first_error;  // the complete first diagnostic, `t.nome:line:col: message`
};

}  // namespace

TEST_CASE("malformed scenes: each error says where and what was expected", "[scene]") {
  const Case cases[] = {
      // syntax
      {"funnel fun (4 1 0 1) endmesh\n", "t.nome:1:22: expected 'endfunnel', found 'endmesh'"},
      {"point p (1 2 3 endpoint\n", "t.nome:1:16: expected a number or '{expr ...}', found 'endpoint'"},
      {"point p (1 2) endpoint\n", "t.nome:1:9: point takes 3 numbers, found 2"},
      {"point p (1 2 3 4) endpoint\n", "t.nome:1:9: point takes 3 numbers, found 4"},
      {"funnel fun (4 1 0) endfunnel\n",
       "t.nome:1:12: funnel 'fun' takes 4 arguments (n ro ratio h), found 3"},
      {"tunnel t (4 1 0 1 2) endtunnel\n",
       "t.nome:1:10: tunnel 't' takes 4 arguments (n ro ratio h [ratio_low h_low]), found 5"},
      {"circle c (4) endcircle\n", "t.nome:1:10: circle 'c' takes 2 arguments (n r), found 1"},
      {"mobiusstrip m (1 1 1) endmobiusstrip\n",
       "t.nome:1:15: mobiusstrip 'm' takes 4 arguments (radius twists cuts segs), found 3"},
      {"bank b\n  set n 8 3 10 1\n",
       "t.nome:1:1: 'bank' is never closed: expected 'endbank', found end of file at 3:1"},
      {"group g\n  instance a fun endinstance\nfunnel f (4 1 0 1) endfunnel\n",
       "t.nome:1:1: 'group' is never closed: expected 'endgroup', found 'funnel' at 3:1"},
      {"mesh m\n  face f (a b c) endface\n",
       "t.nome:1:1: 'mesh' is never closed: expected 'endmesh', found end of file at 3:1"},
      {"frobnicate x\n",
       "t.nome:1:1: expected a statement (bank, surface, point, polyline, face, object, funnel, tunnel, "
       "circle, mobiusstrip, sphere, ellipsoid, cylinder, cone, disk, torus, torusknot, helix, spiral, "
       "hyperboloid, dupin, gencartesiansurf, genparametricsurf, genimplicitsurf, mesh, group, instance, "
       "delete, consolidate, sharp, sharpedges, include, subdivision, offset, boundary, printsetup, camera, "
       "light, "
       "window, "
       "viewport, "
       "frontcolor, backcolor, backgroundcolor, backface, controlpoint, beziercurve, bspline, sweep, "
       "sweepmorph, morphvisualizer, ribbon), found 'frobnicate'"},
      {"bank b set n 8 3 10 endbank\n", "t.nome:1:21: expected a number, found 'endbank'"},
      {"(* never closed\n", "t.nome:1:1: unclosed comment: '(*' without '*)'"},
      {"point p (1e 2 3) endpoint\n", "t.nome:1:10: malformed number '1e'"},
      {"point p ({expr 1 +} 0 0) endpoint\n",
       "t.nome:1:19: expected a number, '$parameter', a function or '(', found '}'"},
      {"point p ({expr (1 + 2} 0 0) endpoint\n", "t.nome:1:22: expected ')', found '}'"},
      {"point p ({expr foo(1)} 0 0) endpoint\n", "t.nome:1:16: unknown function 'foo'"},
      {"point p ({expr sinn(1)} 0 0) endpoint\n", "t.nome:1:16: unknown function 'sinn' (did you mean sin?)"},
      {"point p ({expr atan2(1)} 0 0) endpoint\n",
       "t.nome:1:16: function 'atan2' takes 2 arguments, found 1"},
      {"point p ({expr x + 1} 0 0) endpoint\n",
       "t.nome:1:16: unknown name 'x' in an expression (parameters are written $bank_name)"},
      {"point p ({expr $} 0 0) endpoint\n", "t.nome:1:16: expected a parameter name after '$'"},
      {"face f (a b) endface\n", "t.nome:1:8: face 'f' needs at least 3 vertices, found 2"},
      {"polyline l (a) endpolyline\n", "t.nome:1:12: polyline 'l' needs at least 2 vertices, found 1"},
      {"instance i fun rotate (0 0 1) endinstance\n", "t.nome:1:31: expected '(', found 'endinstance'"},
      {"instance i fun mirror (0 0 1) endinstance\n", "t.nome:1:23: mirror takes 4 numbers, found 3"},
      // A word between a generator's name and its arguments that opens no function.
      {"torus t radius (1 0.3 0 360 12 8) endtorus\n", "t.nome:1:9: expected '(', found 'radius'"},
      // sliders
      // stage blocks (an initial value outside the slider's range is a warning: see scene_dialect_test)
      {"subdivision s instance i f endinstance endsubdivision\n",
       "t.nome:1:15: expected 'sd_level' and its value, found 'instance'"},
      {"bank b set n 5 10 3 1 endbank\n", "t.nome:1:16: slider 'b_n': min 10 is above max 3"},
      {"bank b set n 5 3 10 0 endbank\n", "t.nome:1:21: slider 'b_n': step must be positive, found 0"},
      {"bank b set n 5 3 10 1 set n 6 3 10 1 endbank\n", "t.nome:1:27: duplicate parameter 'b_n'"},
      // names
      {"funnel a (4 1 0 1) endfunnel\nfunnel a (5 1 0 1) endfunnel\n",
       "t.nome:2:8: duplicate name 'a' (first defined at 1:8)"},
      {"funnel fun (4 1 0 1) endfunnel\ninstance i fn endinstance\n",
       "t.nome:2:12: unknown name 'fn' to instantiate (did you mean fun?)"},
      {"funnel fun ({expr $p_n} 1 0 1) endfunnel\n", "t.nome:1:19: unknown parameter '$p_n'"},
      {"bank p set n 4 3 10 1 endbank funnel fun ({expr $p_m} 1 0 1) endfunnel\n",
       "t.nome:1:49: unknown parameter '$p_m' (did you mean p_n?)"},
      {"group g instance x g endinstance endgroup\ninstance r g endinstance\n",
       "t.nome:1:20: group 'g' contains itself"},
      {"point p (0 0 0) endpoint\ninstance i p endinstance\n",
       "t.nome:2:12: 'p' is a point: instantiate a mesh, face, object, polyline, generator or group"},
      {"funnel fun (4 1 0 1) endfunnel\ninstance i fun surface Red endinstance\n",
       "t.nome:2:24: unknown surface 'Red'"},
      // evaluation
      {"funnel fun (2 1 0 1) endfunnel\ninstance i fun endinstance\n",
       "t.nome:1:13: n must be a whole number in [3, 100000], found 2"},
      {"funnel fun (4.5 1 0 1) endfunnel\ninstance i fun endinstance\n",
       "t.nome:1:13: n must be a whole number in [3, 100000], found 4.5"},
      {"funnel fun (4 -1 0 1) endfunnel\ninstance i fun endinstance\n",
       "t.nome:1:15: ro must be positive, found -1"},
      {"funnel fun (4 1 -1 1) endfunnel\ninstance i fun endinstance\n",
       "t.nome:1:17: ratio must be above -1, found -1"},
      {"funnel fun (4 {expr 1 / 0} 0 1) endfunnel\ninstance i fun endinstance\n",
       "t.nome:1:23: division by zero in '/'"},
      {"funnel fun (4 {expr sqrt(-1)} 0 1) endfunnel\ninstance i fun endinstance\n",
       "t.nome:1:21: sqrt(-1) is not a finite number"},
      {"funnel fun (4 1 0 {expr 10 ^ 400}) endfunnel\ninstance i fun endinstance\n",
       "t.nome:1:28: the result of '^' is not finite"},
      {"funnel fun (4 1 0 1) endfunnel\ninstance i fun rotate (0 0 0) (90) endinstance\n",
       "t.nome:2:16: rotate needs a non-zero axis"},
      {"funnel fun (4 1 0 1) endfunnel\ninstance i fun mirror (0 0 0 1) endinstance\n",
       "t.nome:2:16: mirror needs a non-zero plane normal (a b c)"},
      {"mesh m face f (a b c) endface endmesh\ninstance i m endinstance\n",
       "t.nome:1:16: unknown vertex 'a'"},
      {"point a (0 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint\n"
       "face f (a b c) endface object o (f g) endobject\ninstance i o endinstance\n",
       "t.nome:2:36: unknown face 'g' (did you mean f?)"},
      {"funnel fun (4 1 0 1) endfunnel\ninstance i fun endinstance\ndelete face i_f9 endface enddelete\n",
       "t.nome:3:13: unknown face 'i_f9' (did you mean i_f0, i_f1, i_f2?)"},
      {"consolidate consolidateface vertex a endvertex vertex b endvertex endconsolidateface "
       "endconsolidate\n",
       "t.nome:1:13: a consolidated face needs at least 3 vertices, found 2"},
  };
  size_t checked = 0;
  for (const Case& c : cases) {
    if (!c.first_error) continue;
    INFO(c.text);
    const auto errors = scene_errors(c.text);
    REQUIRE_FALSE(errors.empty());
    CHECK(errors.front() == c.first_error);
    ++checked;
  }
  CHECK(checked >= 30);
}

TEST_CASE("after an error the parser resynchronises and reports the next ones", "[scene]") {
  const auto errors = scene_errors(
      "bank b\n"
      "  set n 8 3 10\n"
      "  set r 1 0 2 0.1\n"
      "  set q 9 0 2 0.1\n"
      "endbank\n"
      "funnel f (8 1 0) endfunnel\n"
      "group g\n"
      "  instance a f spin (1) endinstance\n"
      "  instance b f translate (0 0 1 endinstance\n"
      "  instance c f endinstance\n"
      "endgroup\n"
      "point p (1 2 3) endface\n");
  REQUIRE(errors.size() == 5);  // b_q's value outside its range is a warning
  CHECK(errors[0] == "t.nome:3:3: expected a number, found 'set'");
  CHECK(errors[1] == "t.nome:6:10: funnel 'f' takes 4 arguments (n ro ratio h), found 3");
  CHECK(errors[2] ==
        "t.nome:8:16: expected a transform (translate, rotate, scale, mirror), 'surface', "
        "'backface' or 'endinstance', found 'spin'");
  CHECK(errors[3] == "t.nome:9:33: expected a number or '{expr ...}', found 'endinstance'");
  CHECK(errors[4] == "t.nome:12:17: expected 'endpoint', found 'endface'");
}

// After an error inside a face the parser skips to that face's own `endface`, so a face written after it
// on the same line is still read.
TEST_CASE("an error in one face of a mesh leaves the faces after it to be read", "[scene]") {
  const auto errors = scene_errors(
      "mesh m\n"
      "  point a (0 0 0) endpoint point b (1 0 0) endpoint point c (0 1 0) endpoint\n"
      "  face f (a b c 1.5) endface face g (a b) endface\n"
      "endmesh\n");
  REQUIRE(errors.size() == 2);
  CHECK(errors[0] == "t.nome:3:17: expected a vertex name or ')', found number 1.5");
  CHECK(errors[1] == "t.nome:3:37: face 'g' needs at least 3 vertices, found 2");
}

TEST_CASE("a closing word misspelt by a letter or two is read as meant, with a warning", "[scene]") {
  const nome::scene::Scene s =
      nome::scene::Scene::from_text("funnel fun (4 1 0 1) endfunnel\ninstance i fun enintance\n", "t.nome");
  REQUIRE(s.warnings().size() == 1);
  CHECK(s.warnings()[0].to_string() ==
        "t.nome:2:16: warning: expected 'endinstance', found 'enintance': read as 'endinstance'");
  CHECK(s.instances().size() == 1);
}

TEST_CASE("an empty or comment-only scene file is an empty scene, not an error", "[scene]") {
  for (const char* text : {"", "# nothing yet\n", "\n \t\n\n"}) {
    const nome::scene::Scene s = nome::scene::Scene::from_text(text, "t.nome");
    CHECK(s.instances().empty());
    CHECK(s.parameters().empty());
    CHECK(s.combined_soup().num_faces() == 0);
  }
}

TEST_CASE("a file of garbage lists its first 20 errors, not one per byte", "[scene]") {
  const auto errors = scene_errors(std::string(1000, '\x01'));
  REQUIRE(errors.size() == 21);
  CHECK(errors[19] == "t.nome:1:20: unexpected character code 1");
  CHECK(errors[20] == "t.nome:1:21: more errors follow from here; fix those above first");
}

TEST_CASE("a repeated instance name is drawn under a name of its own, with a warning", "[scene]") {
  const nome::scene::Scene s = nome::scene::Scene::from_text(
      "funnel fun (4 1 0 1) endfunnel\ninstance i fun endinstance\ninstance i fun translate (0 0 1) "
      "endinstance\ninstance i_2 fun endinstance\n",
      "t.nome");
  REQUIRE(s.instances().size() == 3);
  CHECK(s.instances()[1].name == "i_3");
  REQUIRE(s.warnings().size() == 1);
  CHECK(s.warnings()[0].to_string() ==
        "t.nome:3:10: warning: instance name 'i' repeated (first at 2:10): this one is named 'i_3'");
}

// Each repeat takes the first `name_k` (k = 2, 3, ...) that no statement of its list is written with and no
// earlier repeat took; the warning names the place of the name's first statement.
TEST_CASE("a name repeated four times among instances gives four names of their own, none taken twice",
          "[scene]") {
  const nome::scene::Scene s = nome::scene::Scene::from_text(
      "funnel fun (4 1 0 1) endfunnel\n"
      "instance i fun endinstance\n"
      "instance i fun translate (0 0 1) endinstance\n"
      "instance i_2 fun translate (0 0 2) endinstance\n"
      "instance i fun translate (0 0 3) endinstance\n"
      "instance i_4 fun translate (0 0 4) endinstance\n"
      "instance i fun translate (0 0 5) endinstance\n"
      "instance i_2 fun translate (0 0 6) endinstance\n"
      "group g\n"
      "  instance p fun endinstance\n"
      "  instance p fun translate (1 0 0) endinstance\n"
      "  instance p fun translate (2 0 0) endinstance\n"
      "endgroup\n"
      "instance gi g translate (9 0 0) endinstance\n",
      "t.nome");
  std::vector<std::string> names;
  for (const auto& instance : s.instances()) names.push_back(instance.name);
  CHECK(names == std::vector<std::string>{"i", "i_3", "i_2", "i_5", "i_4", "i_6", "i_2_2", "gi"});
  const std::vector<std::string> expected_warnings = {
      "t.nome:3:10: warning: instance name 'i' repeated (first at 2:10): this one is named 'i_3'",
      "t.nome:5:10: warning: instance name 'i' repeated (first at 2:10): this one is named 'i_5'",
      "t.nome:7:10: warning: instance name 'i' repeated (first at 2:10): this one is named 'i_6'",
      "t.nome:8:10: warning: instance name 'i_2' repeated (first at 4:10): this one is named 'i_2_2'",
      "t.nome:11:12: warning: instance name 'p' repeated (first at 10:12): this one is named 'p_2'",
      "t.nome:12:12: warning: instance name 'p' repeated (first at 10:12): this one is named 'p_3'"};
  std::vector<std::string> warnings;
  for (const auto& w : s.warnings()) warnings.push_back(w.to_string());
  std::sort(warnings.begin(), warnings.end(), [](const std::string& a, const std::string& b) {
    const auto line = [](const std::string& w) { return std::stoi(w.substr(w.find(':') + 1)); };
    return line(a) < line(b);
  });
  CHECK(warnings == expected_warnings);
  // Every vertex is drawn under a name of its own, each instance's under its new name, where it was placed.
  const nome::PolygonSoup soup = s.combined_soup();
  const std::vector<std::string>& vertex_names = soup.vertex_names;
  CHECK(std::set<std::string>(vertex_names.begin(), vertex_names.end()).size() == vertex_names.size());
  const nome::Index per_funnel = s.instances()[0].geometry.soup.num_vertices();
  REQUIRE(soup.num_vertices() == 10 * per_funnel);
  const double heights[] = {0, 1, 2, 3, 4, 5, 6};
  for (nome::Index k = 0; k < 7; ++k) {
    const std::string& first = vertex_names[k * per_funnel];
    CHECK(first.substr(0, names[k].size() + 1) == names[k] + "_");
    CHECK(soup.positions[k * per_funnel].z ==
          soup.positions[0].z + heights[k]);  // the statement's own translate, so its own instance
  }
  for (const char* path : {"gi_p_", "gi_p_2_", "gi_p_3_"})
    CHECK(std::count_if(vertex_names.begin(), vertex_names.end(), [&](const std::string& n) {
            return n.rfind(path, 0) == 0 && n.find('_', std::string(path).size()) == std::string::npos;
          }) == per_funnel);
}
