#include <catch2/catch.hpp>

#include <fstream>

#include "app/cli_support.hpp"

TEST_CASE("nome info of a face that repeats a vertex says where the face is written", "[app]") {
  const std::string dir = nome::test::scratch_dir("repeated_vertex");
  const std::string file = dir + "/repeat.nome";
  std::ofstream(file) << "point a (0 0 0) endpoint\npoint b (1 0 0) endpoint\npoint c (0 1 0) endpoint\n"
                         "mesh m\n"
                         "  face f (a b c b) endface\n"
                         "endmesh\ninstance j m endinstance\n";
  const auto r = nome::test::run_nome_in_process({"info", file});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith("nome: " + file +
                                      ":5:8: not a 2-manifold: face j_f repeats "
                                      "vertex j_b"));
}
