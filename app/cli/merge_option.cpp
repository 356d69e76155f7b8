#include "cli/merge_option.hpp"

#include <iostream>

#include "nome/ops/merge.hpp"

namespace nome::cli {

std::vector<OptionSpec> merge_options() {
  return {{"--merge", "", "", "glue boundary edges of all parts whose end points coincide (report 3.3)"},
          {"--tolerance", "", "T", "merge distance (default 1e-3 of the bounding box diagonal)"}};
}

Mesh apply_merge_option(Mesh mesh, const Arguments& args) {
  if (!args.has("--merge")) {
    if (args.has("--tolerance")) throw UsageError("--tolerance applies with --merge only");
    return mesh;
  }
  MergeOptions options;
  options.tolerance = args.double_value("--tolerance", 0.0);
  if (args.has("--tolerance") && !(options.tolerance > 0))
    throw UsageError("--tolerance expects a positive distance, found '" + *args.value("--tolerance") + "'");
  MergeResult merged = merge_boundaries(mesh, options);
  constexpr size_t max_listed = 10;
  for (size_t k = 0; k < merged.skipped.size() && k < max_listed; ++k)
    std::cerr << "nome: warning: merge: " << merged.skipped[k].message << "\n";
  if (merged.skipped.size() > max_listed)
    std::cerr << "nome: warning: merge: " << merged.skipped.size() - max_listed << " more merges skipped\n";
  return std::move(merged.mesh);
}

}  // namespace nome::cli
