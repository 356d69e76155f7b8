#include <catch2/catch.hpp>

#include "nome/error.hpp"
#include "viewer/commands/script.hpp"

using nome::viewer::parse_script;
using Kind = nome::viewer::ScriptCommand::Kind;

TEST_CASE("a script is parsed one command a line, comments and blank lines skipped", "[app]") {
  const auto commands = parse_script(
      "# funnel cube\n"
      "set fp_n 6\n"
      "\n"
      "mode border-partial\n"
      "click 640.5 400   # the rim\n"
      "key Ctrl+Z\n"
      "action add-polygon\n"
      "view 30 -25\n"
      "screenshot out.png\n"
      "quit\n",
      "s.txt");
  REQUIRE(commands.size() == 8);
  CHECK(commands[0].kind == Kind::set);
  CHECK(commands[0].words[0] == "fp_n");
  CHECK(commands[0].numbers[0] == 6.0);
  CHECK(commands[1].words[0] == "border-partial");
  CHECK(commands[2].numbers == std::vector<double>{640.5, 400.0});
  CHECK(commands[2].line == 5);
  CHECK(commands[3].words[0] == "Ctrl+Z");
  CHECK(commands[5].numbers == std::vector<double>{30.0, -25.0});
  CHECK(commands[7].kind == Kind::quit);
}

TEST_CASE("double-click, drop and prompt take the window's pixel, the dropped file and the answer", "[app]") {
  const auto commands = parse_script("double-click 12 34.5\ndrop other.nome\nprompt discard\n", "s.txt");
  REQUIRE(commands.size() == 3);
  CHECK(commands[2].kind == Kind::prompt);
  CHECK_THROWS_WITH(parse_script("prompt maybe\n", "s.txt"),
                    Catch::Contains("s.txt:1:8: expected save, discard or cancel, found 'maybe'"));
  CHECK(commands[0].kind == Kind::double_click);
  CHECK(commands[0].numbers == std::vector<double>{12.0, 34.5});
  CHECK(commands[1].kind == Kind::drop);
  CHECK(commands[1].words[0] == "other.nome");
}

TEST_CASE("every bad line of a script is reported with its line and column", "[app]") {
  try {
    parse_script("click 10\nmode edges\nfrobnicate\nset a b\naction fly\n", "s.txt");
    FAIL("the script should have been refused");
  } catch (const nome::InvalidInputError& e) {
    const std::string message = e.what();
    CHECK_THAT(message, Catch::Contains("s.txt:1:9: expected 'click X Y"));
    CHECK_THAT(
        message,
        Catch::Contains(
            "s.txt:2:6: expected vertex, face, border, border-partial, edge or instance, found 'edges'"));
    CHECK_THAT(message, Catch::Contains("s.txt:3:1: expected a command"));
    CHECK_THAT(message, Catch::Contains("s.txt:4:7: expected a number"));
    CHECK_THAT(message, Catch::Contains("s.txt:5:8: expected an action (") &&
                            Catch::Contains("undo, redo, add-polygon, accept, delete, sharp"));
  }
}

TEST_CASE("layout takes no argument, scroll a panel and pixels", "[app]") {
  const auto commands = parse_script("layout\nscroll parameters -40.5\n", "s.txt");
  REQUIRE(commands.size() == 2);
  CHECK(commands[0].kind == Kind::layout);
  CHECK(commands[1].kind == Kind::scroll);
  CHECK(commands[1].words[0] == "parameters");
  CHECK(commands[1].numbers[0] == -40.5);
  CHECK_THROWS_WITH(parse_script("scroll sidebar 10\n", "s.txt"),
                    Catch::Contains("s.txt:1:8: expected controls, parameters or log, found 'sidebar'"));
  CHECK_THROWS_WITH(parse_script("layout now\n", "s.txt"), Catch::Contains("s.txt:1:8: expected 'layout'"));
}

// One line of every command, as its usage says, with the words and numbers it must give; one argument
// fewer is refused with the usage.
TEST_CASE("every script command reads its words and numbers, and refuses one argument fewer", "[app]") {
  struct Case {
    const char* line;
    Kind kind;
    std::vector<std::string> words;
    std::vector<double> numbers;
  };
  const std::vector<Case> cases{
      {"set b_n 6", Kind::set, {"b_n"}, {6}},
      {"mode edge", Kind::mode, {"edge"}, {}},
      {"color 1 0.5 0", Kind::color, {}, {1, 0.5, 0}},
      {"display-color background 0 0 0.25", Kind::display_color, {"background"}, {0, 0, 0.25}},
      {"click 10 20", Kind::click, {}, {10, 20}},
      {"double-click 10 20", Kind::double_click, {}, {10, 20}},
      {"key Ctrl+Z", Kind::key, {"Ctrl+Z"}, {}},
      {"action zip", Kind::action, {"zip"}, {}},
      {"subdiv 2", Kind::subdiv, {}, {2}},
      {"offset 0.05", Kind::offset, {}, {0.05}},
      {"setting creases chaikin", Kind::setting, {"creases", "chaikin"}, {}},
      {"view 30 -25", Kind::view, {}, {30, -25}},
      {"screenshot out.png", Kind::screenshot, {"out.png"}, {}},
      {"save out.nome", Kind::save, {"out.nome"}, {}},
      {"export out.stl", Kind::export_file, {"out.stl"}, {}},
      {"recover discard", Kind::recover, {"discard"}, {}},
      {"drop other.nome", Kind::drop, {"other.nome"}, {}},
      {"prompt cancel", Kind::prompt, {"cancel"}, {}},
      {"scroll log 120", Kind::scroll, {"log"}, {120}},
      {"text-set new.nome", Kind::text_set, {"new.nome"}, {}},
      {"log-click 2", Kind::log_click, {}, {2}},
      {"tool measure", Kind::tool, {"measure"}, {}},
  };
  for (const Case& c : cases) {
    INFO(c.line);
    const auto commands = parse_script(std::string(c.line) + "\n", "s.txt");
    REQUIRE(commands.size() == 1);
    CHECK(commands[0].kind == c.kind);
    CHECK(commands[0].words == c.words);
    CHECK(commands[0].numbers == c.numbers);
    const std::string line(c.line);
    const std::string shorter = line.substr(0, line.rfind(' '));
    CHECK_THROWS_AS(parse_script(shorter + "\n", "s.txt"), nome::Error);
  }
}

TEST_CASE("a colour takes components in 0..1 and display-color a colour of the Look panel", "[app]") {
  for (const char* name :
       {"default", "back-faces", "selected", "background", "rim-lines", "temporary", "consolidated"}) {
    INFO(name);
    CHECK(parse_script(std::string("display-color ") + name + " 0.2 0.4 0.6\n", "s.txt").size() == 1);
  }
  CHECK_THROWS_WITH(
      parse_script("display-color sky 0 0 1\n", "s.txt"),
      Catch::Contains("s.txt:1:15: expected default, back-faces, selected, background, rim-lines, "
                      "temporary or consolidated, found 'sky'"));
  CHECK_THROWS_WITH(parse_script("display-color background 0 1.5 0\n", "s.txt"),
                    Catch::Contains("s.txt:1:28: expected a colour component in 0..1, found '1.5'"));
  CHECK_THROWS_WITH(parse_script("color 0 0 -1\n", "s.txt"),
                    Catch::Contains("s.txt:1:11: expected a colour component in 0..1, found '-1'"));
}

TEST_CASE("an unknown command is answered with every command there is", "[app]") {
  try {
    parse_script("subdivide 2\n", "s.txt");
    FAIL("the script should have been refused");
  } catch (const nome::InvalidInputError& e) {
    const std::string message = e.what();
    CHECK_THAT(message,
               Catch::StartsWith("s.txt:1:1: expected a command (set, mode, color, display-color, "));
    for (const char* word : {"tool", "quit", "log-click", "text-set", "state", "scroll", "layout"}) {
      INFO(word);
      CHECK_THAT(message, Catch::Contains(std::string(", ") + word));
    }
    CHECK_THAT(message, Catch::EndsWith("found 'subdivide'"));
  }
}
