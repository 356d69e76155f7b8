#include "nome/io/print_double.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace nome {
namespace {

__extension__ typedef unsigned __int128 u128;  // GCC and Clang; -Wpedantic knows no __int128

constexpr std::uint64_t power_of_ten(int k) {
  std::uint64_t p = 1;
  for (int i = 0; i < k; ++i) p *= 10;
  return p;
}
constexpr std::uint64_t least_17_digits = power_of_ten(16), past_17_digits = power_of_ten(17);

// 10^-20 .. 10^17, as near as doubles get.
constexpr double powers_of_ten[] = {1e-20, 1e-19, 1e-18, 1e-17, 1e-16, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11,
                                    1e-10, 1e-9,  1e-8,  1e-7,  1e-6,  1e-5,  1e-4,  1e-3,  1e-2,  1e-1,
                                    1e0,   1e1,   1e2,   1e3,   1e4,   1e5,   1e6,   1e7,   1e8,   1e9,
                                    1e10,  1e11,  1e12,  1e13,  1e14,  1e15,  1e16,  1e17};

// x = m 2^-s (m < 2^53) rounded to an integer after scaling by 10^k, half to even, exactly: m 10^k fits
// in 117 bits.
std::uint64_t scaled_rounded(std::uint64_t m, int s, int k) {
  const u128 n = u128(m) * power_of_ten(k);
  if (s == 0) return std::uint64_t(n);
  const std::uint64_t q = std::uint64_t(n >> s);
  const u128 rest = n & ((u128(1) << s) - 1), half = u128(1) << (s - 1);
  return q + ((rest > half || (rest == half && (q & 1))) ? 1 : 0);
}

// The 17 significant digits of positive finite x, digits = round(x 10^(16 - exponent)) in
// [10^16, 10^17); false where that needs more than 128 bits (x >= 2^53, x below about 10^-19) and for
// subnormals.
bool seventeen_digits(double x, std::uint64_t& digits, int& exponent) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, 8);
  const int biased = int(bits >> 52) & 0x7ff;
  if (biased == 0) return false;
  const std::uint64_t m = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
  const int s = 1075 - biased;  // x = m 2^-s, x in [2^(52-s), 2^(53-s))
  if (s < 0 || s > 127) return false;
  exponent = ((52 - s) * 78913) >> 18;  // floor((52 - s) log10 2): floor(log10 x), or one less
  // Mostly right after one comparison (the loop below settles it exactly): a second product saved.
  if (exponent >= -20 && exponent < 17 && x >= powers_of_ten[exponent + 21]) ++exponent;
  for (;;) {
    const int k = 16 - exponent;
    if (k < 0 || k > 19) return false;
    digits = scaled_rounded(m, s, k);
    if (digits < least_17_digits)
      --exponent;
    else if (digits >= past_17_digits)
      ++exponent;
    else
      return true;
  }
}

// Two digits at a time.
constexpr char digit_pairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The 17 digits of `digits` (in [10^16, 10^17)) into d[0..16].
void spell_digits(std::uint64_t digits, char* d) {
  std::uint32_t high = std::uint32_t(digits / 100000000), low = std::uint32_t(digits % 100000000);
  for (int i = 15; i >= 9; i -= 2, low /= 100) std::memcpy(d + i, digit_pairs + 2 * (low % 100), 2);
  for (int i = 7; i >= 1; i -= 2, high /= 100) std::memcpy(d + i, digit_pairs + 2 * (high % 100), 2);
  d[0] = char('0' + high);
}

// printf's %g with 17 digits: scientific when the exponent is below -4 or above 16, and no trailing
// zeros either way.
char* print_digits(char* at, std::uint64_t digits, int exponent) {
  char d[17];
  spell_digits(digits, d);
  int n = 17;
  while (n > 1 && d[n - 1] == '0') --n;
  if (exponent < -4 || exponent >= 17) {
    *at++ = d[0];
    if (n > 1) {
      *at++ = '.';
      std::memcpy(at, d + 1, size_t(n - 1));
      at += n - 1;
    }
    *at++ = 'e';
    *at++ = exponent < 0 ? '-' : '+';
    const int e = exponent < 0 ? -exponent : exponent;
    if (e >= 100) *at++ = char('0' + e / 100);
    *at++ = char('0' + e / 10 % 10);
    *at++ = char('0' + e % 10);
    return at;
  }
  if (exponent < 0) {
    *at++ = '0';
    *at++ = '.';
    for (int i = 0; i < -exponent - 1; ++i) *at++ = '0';
    std::memcpy(at, d, size_t(n));
    return at + n;
  }
  const int whole = exponent + 1;
  std::memcpy(at, d, size_t(whole));
  at += whole;
  if (n > whole) {
    *at++ = '.';
    std::memcpy(at, d + whole, size_t(n - whole));
    at += n - whole;
  }
  return at;
}

}  // namespace

char* print_double_g17(char* at, double value) {
  std::uint64_t digits = 0;
  int exponent = 0;
  if (value != 0.0 && std::isfinite(value) && seventeen_digits(std::fabs(value), digits, exponent)) {
    if (value < 0) *at++ = '-';
    return print_digits(at, digits, exponent);
  }
  return std::to_chars(at, at + 32, value, std::chars_format::general, 17).ptr;
}

}  // namespace nome
