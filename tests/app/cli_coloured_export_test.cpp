#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "app/cli_support.hpp"
#include "support/skip.hpp"

using nome::test::run_nome_in_process;

namespace {

// The Khronos validator, installed by `make gltf-validator` under build/tools.
const std::string gltf_validator_dir = std::string(NOME_SOURCE_DIR) + "/build/tools/node_modules";

// The validator's report of a file: its issues' counts as JSON, or "" when it could not run.
std::string validate_gltf(const std::string& dir, const std::string& file) {
  const std::string script = dir + "/validate.js";
  std::ofstream(script)
      << "const v = require('gltf-validator');\n"
         "const bytes = new Uint8Array(require('fs').readFileSync(process.argv[2]));\n"
         "v.validateBytes(bytes).then(r => {\n"
         "  const i = r.issues;\n"
         "  console.log(JSON.stringify({errors: i.numErrors, warnings: i.numWarnings,\n"
         "    messages: i.messages.filter(m => m.severity <= 1).map(m => m.code + ' ' + m.message)}));\n"
         "}, e => console.log('failed: ' + e));\n";
  const std::string command = "NODE_PATH=" + gltf_validator_dir + " node " + script + " " + file + " 2>&1";
  std::string out;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    ::pclose(pipe);
  }
  return out;
}

}  // namespace

TEST_CASE("nome export -o .glb passes the Khronos validator and nome info reads it back", "[app]") {
  const std::string dir = nome::test::private_scratch_dir("coloured_export");
  const std::string scene = nome::test::assets + "funnel_cube.nome";
  REQUIRE(run_nome_in_process("export " + scene + " --subdiv 1 -o " + dir + "/fc.glb").status == 0);
  REQUIRE(run_nome_in_process("export " + scene + " --subdiv 1 -o " + dir + "/fc.ply").status == 0);
  const auto glb = run_nome_in_process("info " + dir + "/fc.glb --json");
  const auto ply = run_nome_in_process("info " + dir + "/fc.ply --json");
  const auto original = run_nome_in_process("info " + scene + " --subdiv 1 --json");
  REQUIRE(glb.status == 0);
  REQUIRE(ply.status == 0);
  // The same surface: the vertices, the Euler characteristic and the borders (glTF holds triangles).
  const auto field = [](const std::string& json, const std::string& key) {
    const std::size_t at = json.find("\"" + key + "\": ");
    return at == std::string::npos ? std::string() : json.substr(at, json.find(',', at) - at);
  };
  for (const char* key : {"vertices", "chi", "borders", "orientable"}) {
    INFO(key);
    CHECK(field(glb.out, key) == field(original.out, key));
    CHECK(field(ply.out, key) == field(original.out, key));
  }
  CHECK(field(ply.out, "faces") == field(original.out, "faces"));

  if (!std::filesystem::exists(gltf_validator_dir + "/gltf-validator") ||
      std::system("node --version >/dev/null 2>&1") != 0) {
    NOME_SKIP("the Khronos glTF validation needs node and `make gltf-validator` (npm)");
  }
  const std::string report = validate_gltf(dir, dir + "/fc.glb");
  INFO(report);
  CHECK_THAT(report, Catch::Contains("\"errors\":0,\"warnings\":0"));
}
