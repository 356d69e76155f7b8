// `mobiusstrip NAME (radius twists cuts segs) endmobiusstrip`.
#include <array>
#include <cmath>
#include <numbers>

#include "nome/scene/generators/mobius_strip.hpp"
#include "scene/generators/generator_support.hpp"

namespace nome::scene {

Piece mobius_strip(const MobiusStripParams& p) {
  require(p.segs >= 3 && p.cuts >= 1 && p.twists >= 0,
          "mobius_strip: needs segs >= 3, cuts >= 1, twists >= 0");
  Piece piece;
  const int across = p.cuts + 1;
  const double half_width = p.radius / 4;
  for (int i = 0; i < p.segs; ++i) {
    const double around = 2 * std::numbers::pi * i / p.segs;
    const double turn = std::numbers::pi * p.twists * i / p.segs;
    const Vec3 radial{std::cos(around), std::sin(around), 0};
    const Vec3 across_dir = std::cos(turn) * radial + std::sin(turn) * Vec3(0, 0, 1);
    for (int j = 0; j < across; ++j) {
      const double t = -half_width + 2 * half_width * j / p.cuts;
      piece.add_vertex(p.radius * radial + t * across_dir, "v" + std::to_string(i) + "_" + std::to_string(j));
    }
  }
  // After a full turn the cross-section has turned by twists*180 degrees: odd twists reverse it.
  const bool is_reversed = p.twists % 2 == 1;
  auto vertex = [&](int i, int j) {
    if (i == p.segs) {
      i = 0;
      if (is_reversed) j = p.cuts - j;
    }
    return Index(i * across + j);
  };
  for (int i = 0; i < p.segs; ++i)
    for (int j = 0; j < p.cuts; ++j) {
      const std::array<Index, 4> quad{vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)};
      piece.add_face(quad, "f" + std::to_string(i) + "_" + std::to_string(j));
    }
  return piece;
}

namespace {

// The 2016 meaning needs a cut (its cuts count the quads across); JIPCAD's files write 0 cuts for the
// uncut band. A JIPCAD file reads every strip in JIPCAD's meaning; elsewhere 0 cuts does too.
Piece evaluate_mobius_strip(DefinitionContext& c, Index decl) {
  const std::vector<Value>& a = generator_arguments(c, decl);
  const MobiusStripParams p{c.positive(a[0], "radius"), c.whole(a[1], 0, "twists"), c.whole(a[2], 0, "cuts"),
                            c.whole(a[3], 3, "segs")};
  expect_generator_faces(c, decl, double(p.cuts + 1) * p.segs);
  const bool is_jipcad = c.ast().dialect.dialect == Dialect::jipcad;
  return is_jipcad || p.cuts == 0 ? cut_mobius_strip(p) : mobius_strip(p);
}

}  // namespace

StatementKind mobius_strip_statement() {
  return with_generator_syntax({.keyword = "mobiusstrip",
                                .end_keyword = "endmobiusstrip",
                                .signature = "(radius twists cuts segs)",
                                .argument_count = 4,
                                .evaluate = evaluate_mobius_strip,
                                .example = "(1 1 2 12)"});
}

}  // namespace nome::scene
