// `funnel NAME (n ro ratio h) endfunnel` (report 6.3); the successor's dialect: (radius ratio height segs).
#include "nome/scene/generators/funnel.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {

Piece funnel(const FunnelParams& p) {
  require(p.n >= 3, "funnel: n must be at least 3");
  Piece piece;
  const Index base = ring(piece, p.n, p.ro, 0, p.base_names);
  const Index high = ring(piece, p.n, p.ro * (1 + p.ratio), p.h, p.high_names);
  band(piece, p.n, base, high, "f");
  return piece;
}

namespace {

// The 2016 report writes (n ro ratio h), the successor (radius ratio height segs): the same funnel.
Piece evaluate_funnel(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  if (c.ast().dialect.dialect == Dialect::jipcad)
    return funnel(
        {c.whole(a[3], 3, "segs"), c.positive(a[0], "radius"), c.ratio(a[1]), c.number(a[2]), "v1_", "v2_"});
  return funnel({c.whole(a[0], 3, "n"), c.positive(a[1], "ro"), c.ratio(a[2]), c.number(a[3])});
}

}  // namespace

StatementKind funnel_statement() {
  return with_generator_syntax({.keyword = "funnel",
                                .end_keyword = "endfunnel",
                                .signature = "(n ro ratio h)",
                                .argument_count = 4,
                                .evaluate = evaluate_funnel,
                                .example = "(4 1 0.5 1)"});
}

}  // namespace nome::scene
