#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "nome/number_text.hpp"

namespace {

std::string shortest(double value) {
  char text[64];
  return std::string(text, nome::shortest_to_chars(text, text + sizeof text, value).ptr);
}

std::string shortest(float value) {
  char text[64];
  return std::string(text, nome::shortest_to_chars(text, text + sizeof text, value).ptr);
}

std::string general(double value, int precision) {
  char text[64];
  return std::string(text, nome::general_to_chars(text, text + sizeof text, value, precision).ptr);
}

struct Read {
  double value = 42.0;
  std::ptrdiff_t length = 0;
  std::errc error = std::errc();
};

Read read(const std::string& text) {
  Read r;
  const auto [ptr, error] = nome::number_from_chars(text.data(), text.data() + text.size(), r.value);
  r.length = ptr - text.data();
  r.error = error;
  return r;
}

}  // namespace

TEST_CASE("Numbers are written in the fewest characters that read back, fixed on a tie", "[kernel]") {
  CHECK(shortest(1e20) == "1e+20");
  CHECK(shortest(1.5e-7) == "1.5e-07");
  CHECK(shortest(0.1) == "0.1");
  CHECK(shortest(10000.0) == "10000");
  CHECK(shortest(100000.0) == "1e+05");
  CHECK(shortest(0.001) == "0.001");
  CHECK(shortest(-1234.5) == "-1234.5");
  CHECK(shortest(-0.0) == "-0");
  CHECK(shortest(1e300) == "1e+300");
  CHECK(shortest(0.1f) == "0.1");
  CHECK(shortest(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(general(0.1, 17) == "0.10000000000000001");
  CHECK(general(1e20, 17) == "1e+20");
}

TEST_CASE("A buffer too short for a number is reported, not overrun", "[kernel]") {
  char text[4];
  const auto [ptr, error] = nome::shortest_to_chars(text, text + sizeof text, 0.125);
  CHECK(error == std::errc::value_too_large);
  CHECK(ptr == text + sizeof text);
}

TEST_CASE("Numbers are read up to the first character not part of them", "[kernel]") {
  CHECK(read("1.5e3x").value == 1500.0);
  CHECK(read("1.5e3x").length == 5);
  CHECK(read("2e+").length == 1);
  CHECK(read(".5").value == 0.5);
  CHECK(read("0x10").length == 1);
  CHECK(read("-inf").value == -std::numeric_limits<double>::infinity());
  CHECK(std::isnan(read("nan(7)").value));
  CHECK(read("nan(7)").length == 6);
  CHECK(read("+1").error == std::errc::invalid_argument);
  CHECK(read(" 1").error == std::errc::invalid_argument);
  CHECK(read("-").error == std::errc::invalid_argument);
  CHECK(read("1e400").error == std::errc::result_out_of_range);
  CHECK(read("1e400").value == 42.0);
  CHECK(read("1e-400").error == std::errc::result_out_of_range);
  CHECK(read("5e-324").value == std::numeric_limits<double>::denorm_min());
}

// The fallback, what builds without floating-point <charconv> use, against the standard library.
#if defined(__cpp_lib_to_chars)

namespace {

// Random bit patterns (subnormals, inf and nan among them), whole numbers, powers of two and ten and their
// neighbours, steps of 0.1, both zeros.
std::vector<double> sample_doubles() {
  std::mt19937_64 rng{42};
  std::vector<double> values = {0.0,
                                -0.0,
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN(),
                                -std::numeric_limits<double>::quiet_NaN()};
  for (int k = 0; k < 40000; ++k) values.push_back(std::bit_cast<double>(rng()));
  for (int k = 0; k < 5000; ++k) values.push_back(std::bit_cast<double>(rng() & 0x800fffffffffffffu));
  for (int k = 0; k < 5000; ++k) values.push_back(double(std::int64_t(rng()) >> (k % 64)));
  for (int k = -5000; k <= 5000; ++k) values.push_back(k);
  for (int k = -10000; k <= 10000; ++k) values.push_back(k * 0.1);
  for (int e = -1074; e < 1024; ++e)
    for (double p : {std::ldexp(1.0, e), -std::ldexp(3.0, e - 1)})
      for (double v : {p, std::nextafter(p, 0.0), std::nextafter(p, 2 * p)}) values.push_back(v);
  for (int e = -324; e <= 308; ++e)
    for (double v : {std::pow(10.0, e), 1.5 * std::pow(10.0, e)}) values.push_back(v);
  return values;
}

std::vector<float> sample_floats(const std::vector<double>& doubles) {
  std::mt19937 rng{42};
  std::vector<float> values;
  for (int k = 0; k < 20000; ++k) values.push_back(std::bit_cast<float>(std::uint32_t(rng())));
  for (std::size_t k = 0; k < doubles.size(); k += 4) values.push_back(float(doubles[k]));
  return values;
}

template <class T>
std::string fallback_shortest(T value) {
  char text[64];
  return std::string(text, nome::fallback::shortest_to_chars(text, text + sizeof text, value).ptr);
}

template <class T>
std::string std_shortest(T value) {
  char text[64];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

// Same bits, or both nan with the same sign.
bool same_double(double a, double b) {
  if (std::isnan(a) || std::isnan(b))
    return std::isnan(a) && std::isnan(b) && std::signbit(a) == std::signbit(b);
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Where both stop, what both report, and what both read, which only out of range leaves as it was.
void check_same_reading(const std::string& text) {
  double by_fallback = 42.0, by_std = 42.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto fallback = nome::fallback::number_from_chars(first, last, by_fallback);
  const auto standard = std::from_chars(first, last, by_std);
  INFO(text);
  CHECK(fallback.ptr == standard.ptr);
  CHECK(fallback.ec == standard.ec);
  CHECK(same_double(by_fallback, by_std));
}

}  // namespace

TEST_CASE("The fallback writes every number as the standard library does", "[kernel]") {
  const std::vector<double> doubles = sample_doubles();
  for (double value : doubles) {
    INFO(std_shortest(value));
    CHECK(fallback_shortest(value) == std_shortest(value));
    char standard[64], fallback[64];
    const auto s = std::to_chars(standard, standard + sizeof standard, value, std::chars_format::general, 17);
    const auto f = nome::fallback::general_to_chars(fallback, fallback + sizeof fallback, value, 17);
    CHECK(std::string(fallback, f.ptr) == std::string(standard, s.ptr));
  }
  for (float value : sample_floats(doubles)) {
    INFO(std_shortest(value));
    CHECK(fallback_shortest(value) == std_shortest(value));
  }
}

TEST_CASE("The fallback reads every number as the standard library does", "[kernel]") {
  for (double value : sample_doubles()) {
    check_same_reading(std_shortest(value));
    char text[64];
    check_same_reading(std::string(
        text, std::to_chars(text, text + sizeof text, value, std::chars_format::scientific, 25).ptr));
  }
  for (const char* text : {"",
                           "-",
                           ".",
                           "-.",
                           ".5",
                           "5.",
                           "1e",
                           "1e+",
                           "1e5x",
                           "1E-5",
                           "+1",
                           " 1",
                           "0x1p3",
                           "inf",
                           "-Infinity",
                           "infinit",
                           "INFINITYx",
                           "nan",
                           "NaN(abc_1)",
                           "nan(",
                           "nan(1",
                           "nan(a-b)",
                           "-nan",
                           "1e400",
                           "-1e400",
                           "1e-400",
                           "2e-324",
                           "3e-324",
                           "1e-310",
                           "0e999",
                           "0.000e-999",
                           "00012.5000e2",
                           "1..2",
                           "e5",
                           "-e5",
                           "1.7976931348623159e308",
                           "123456789012345678901234567890123456789012345678901234567890e-40",
                           "abc"})
    check_same_reading(text);
}

#endif
