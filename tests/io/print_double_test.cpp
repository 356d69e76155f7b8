#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "nome/io/print_double.hpp"

using namespace nome;

namespace {

std::string fast_g17(double x) {
  char buf[40];
  return {buf, print_double_g17(buf, x)};
}

std::string printf_g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace

TEST_CASE("print_double_g17 writes what printf's %.17g writes", "[io]") {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-2.0, 2.0);
  auto same = [](double x) {
    CAPTURE(x);
    CHECK(fast_g17(x) == printf_g17(x));
  };
  for (int i = 0; i < 20000; ++i) {
    // Any bit pattern (subnormals, infinities, NaNs, the far exponents), coordinates at many scales,
    // short decimals and floats widened to doubles.
    std::uint64_t bits = random();
    double any = 0;
    std::memcpy(&any, &bits, 8);
    if (!std::isnan(any)) same(any);
    const double x = unit(random);
    same(x);
    same(std::ldexp(x, int(random() % 140) - 70));
    same(std::nearbyint(x * 1e6) / 1e6);
    same(double(float(x)));
  }
  // Around the powers of ten, where the exponent and the switch to scientific notation change.
  for (int p = -25; p <= 25; ++p) {
    const double x = std::pow(10.0, p);
    for (double y : {x, std::nextafter(x, 0.0), std::nextafter(x, 2 * x), -x}) same(y);
  }
  for (double x : {0.0, -0.0, 0.5, 1.3, 0.1, 9007199254740991.0, 9007199254740992.0, 99999999999999999.0,
                   9.9999999999999995e-5, 1e16, 1e17, 5e-324})
    same(x);
}
