#include <catch2/catch.hpp>

#include "nome/scene/save_nome.hpp"
#include "scene/scene_support.hpp"

using namespace nome;
using namespace nome::scene;

namespace {
const std::string print_setup_band =
    "mobiusstrip band (1 1 2 24) endmobiusstrip\n"
    "instance strip band endinstance\n";
}

TEST_CASE("printsetup keeps a fit and a rest face and saves them back", "[scene]") {
  const Scene s =
      Scene::from_text(print_setup_band + "printsetup fitsize 80 reston 12 endprintsetup\n", "t.nome");
  REQUIRE(s.print_setup());
  CHECK(s.print_setup()->fit == FitTarget::largest);
  CHECK(s.print_setup()->fit_size == 80.0);
  CHECK(s.print_setup()->rest == RestOn::face);
  CHECK(s.print_setup()->rest_face == 12);
  const Scene back = Scene::from_text(to_nome_text(s), "saved.nome");
  CHECK(back.print_setup() == s.print_setup());

  Scene edited = s;
  edited.set_print_setup(
      PrintPlacementOptions{.fit = FitTarget::height, .fit_size = 60, .rest = RestOn::flattest});
  CHECK_THAT(to_nome_text(edited), Catch::Contains("printsetup fitheight 60 reston flattest endprintsetup"));
  CHECK_FALSE(Scene::from_text(print_setup_band, "t.nome").print_setup());
}

TEST_CASE("printsetup errors say where and what was expected", "[scene]") {
  CHECK(test::scene_errors("printsetup fitheight -3 endprintsetup\n") ==
        std::vector<std::string>{"t.nome:1:22: expected a positive size in mm, found '-'"});
  CHECK(test::scene_errors("printsetup reston 1.5 endprintsetup\n") ==
        std::vector<std::string>{"t.nome:1:19: expected flattest or a face number, found number 1.5"});
  CHECK(test::scene_errors("printsetup tall endprintsetup\n") ==
        std::vector<std::string>{
            "t.nome:1:12: expected fitheight, fitsize, reston or endprintsetup, found 'tall'"});
}
