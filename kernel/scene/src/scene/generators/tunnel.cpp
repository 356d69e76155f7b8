// `tunnel NAME (n ro ratio h [ratio_low h_low]) endtunnel`: two funnels sharing the base circle; the
// successor's dialect: (radius ratio height segs).
#include "nome/scene/generators/tunnel.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {

Piece tunnel(const TunnelParams& p) {
  require(p.n >= 3, "tunnel: n must be at least 3");
  Piece piece;
  const Index base = ring(piece, p.n, p.ro, 0, "bc");
  const Index high = ring(piece, p.n, p.ro * (1 + p.ratio), p.h, "hc");
  const Index low = ring(piece, p.n, p.ro * (1 + p.ratio_low), -p.h_low, "lc");
  band(piece, p.n, base, high, "hf");
  band(piece, p.n, low, base, "lf");
  return piece;
}

namespace {

// Without the last two arguments the tunnel is symmetric.
// The successor's dialect writes (radius ratio height segs) and has no lower-half arguments.
Piece evaluate_tunnel(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  if (c.ast().dialect.dialect == Dialect::jipcad) {
    if (a.size() != 4)
      c.error(a[0].location, "tunnel takes (radius ratio height segs) in the successor's dialect, found " +
                                 std::to_string(a.size()) + " numbers");
    const double ratio = c.ratio(a[1]), h = c.number(a[2]);
    return tunnel({c.whole(a[3], 3, "segs"), c.positive(a[0], "radius"), ratio, h, ratio, h});
  }
  TunnelParams t{c.whole(a[0], 3, "n"), c.positive(a[1], "ro"), c.ratio(a[2]), c.number(a[3]), 0, 0};
  t.ratio_low = a.size() == 6 ? c.ratio(a[4]) : t.ratio;
  t.h_low = a.size() == 6 ? c.number(a[5]) : t.h;
  return tunnel(t);
}

}  // namespace

StatementKind tunnel_statement() {
  // The report's klein_bottle.nome closes its tunnels with endfunnel.
  return with_generator_syntax({.keyword = "tunnel",
                                .end_keyword = "endtunnel",
                                .alternative_end_keyword = "endfunnel",
                                .signature = "(n ro ratio h [ratio_low h_low])",
                                .argument_count = 4,
                                .alternative_argument_count = 6,
                                .evaluate = evaluate_tunnel,
                                .example = "(5 1 0.5 2 0.25 1)"});
}

}  // namespace nome::scene
