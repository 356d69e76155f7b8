#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "nome/number_text.hpp"

namespace nome::fallback {
namespace {

// A positive decimal digits[0].digits[1..count) * 10^exponent, without trailing zeros.
struct Decimal {
  char digits[24];
  int count = 0;
  int exponent = 0;
};

// printf rounds exactly (to nearest, ties to even), which is the rounding the standard asks for.
Decimal nearest_decimal(double value, int count) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*e", count - 1, value);
  Decimal d;
  const char* at = text;
  for (; *at != 'e'; ++at)
    if (*at != '.') d.digits[d.count++] = *at;
  d.exponent = std::atoi(at + 1);
  return d;
}

// The next decimal of as many digits up from `d`.
Decimal next_decimal_up(Decimal d) {
  int k = d.count - 1;
  while (k >= 0 && d.digits[k] == '9') d.digits[k--] = '0';
  if (k >= 0) {
    ++d.digits[k];
  } else {
    d.digits[0] = '1';
    ++d.exponent;
  }
  return d;
}

void drop_trailing_zeros(Decimal& d) {
  while (d.count > 1 && d.digits[d.count - 1] == '0') --d.count;
}

double read_as(const char* text, double) {
  return std::strtod(text, nullptr);
}

float read_as(const char* text, float) {
  return std::strtof(text, nullptr);
}

template <class T>
bool reads_back(const Decimal& d, T value) {
  char text[48];
  std::snprintf(text, sizeof text, "%c.%.*se%d", d.digits[0], d.count - 1, d.digits + 1, d.exponent);
  return read_as(text, value) == value;
}

// The fewest digits that read back to `value` (positive and finite), the nearest such when several do.
// The nearest decimal of a length can miss where its neighbour above reads back: at a power of two the
// values that read back reach twice as far up as down.
template <class T>
Decimal shortest_decimal(T value, int most_digits) {
  for (int count = 1; count < most_digits; ++count) {
    Decimal d = nearest_decimal(double(value), count);
    if (reads_back(d, value)) {
      drop_trailing_zeros(d);
      return d;
    }
    d = next_decimal_up(d);
    if (reads_back(d, value)) {
      drop_trailing_zeros(d);
      return d;
    }
  }
  Decimal d = nearest_decimal(double(value), most_digits);
  drop_trailing_zeros(d);
  return d;
}

std::to_chars_result put_text(char* first, char* last, const char* text, std::size_t size) {
  if (std::size_t(last - first) < size) return {last, std::errc::value_too_large};
  std::memcpy(first, text, size);
  return {first + size, std::errc()};
}

// inf and nan as the standard library writes them; null for a finite value.
const char* non_finite_text(double value) {
  if (std::isfinite(value)) return nullptr;
  if (std::isnan(value)) return std::signbit(value) ? "-nan" : "nan";
  return value < 0 ? "-inf" : "inf";
}

// Fixed or scientific, whichever is shorter, fixed on a tie. A whole number in fixed is written with all
// its digits exact, as the standard library does, where the shortest digits would end in zeros.
std::to_chars_result put_decimal(char* first, char* last, double value, const Decimal& d) {
  const int n = d.count, e = d.exponent;
  const int fixed_size = e >= 0 ? std::max(n, e + 1) + (n > e + 1 ? 1 : 0) : n + 1 - e;
  const int scientific_size = n + (n > 1 ? 1 : 0) + 2 + (std::abs(e) >= 100 ? 3 : 2);
  char text[48];
  int size = 0;
  if (fixed_size <= scientific_size && e >= n - 1) {
    size = std::snprintf(text, sizeof text, "%.0f", value);
  } else if (fixed_size <= scientific_size) {
    if (value < 0) text[size++] = '-';
    if (e < 0) {
      text[size++] = '0';
      text[size++] = '.';
      for (int k = 0; k < -e - 1; ++k) text[size++] = '0';
      for (int k = 0; k < n; ++k) text[size++] = d.digits[k];
    } else {
      for (int k = 0; k < n; ++k) {
        if (k == e + 1) text[size++] = '.';
        text[size++] = d.digits[k];
      }
    }
  } else {
    size = std::snprintf(text, sizeof text, "%s%c%s%.*se%c%02d", value < 0 ? "-" : "", d.digits[0],
                         n > 1 ? "." : "", n - 1, d.digits + 1, e < 0 ? '-' : '+', std::abs(e));
  }
  return put_text(first, last, text, std::size_t(size));
}

template <class T>
std::to_chars_result shortest_text(char* first, char* last, T value, int most_digits) {
  if (const char* text = non_finite_text(double(value)))
    return put_text(first, last, text, std::strlen(text));
  if (value == 0) return put_text(first, last, std::signbit(value) ? "-0" : "0", std::signbit(value) ? 2 : 1);
  return put_decimal(first, last, double(value), shortest_decimal(std::abs(value), most_digits));
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

bool is_letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// Whether [at, last) starts with `word` (lower case), whatever the case of its letters.
bool starts_with_word(const char* at, const char* last, const char* word) {
  for (; *word; ++word, ++at)
    if (at == last || (*at | 0x20) != *word) return false;
  return true;
}

}  // namespace

std::to_chars_result shortest_to_chars(char* first, char* last, double value) {
  return shortest_text(first, last, value, 17);
}

std::to_chars_result shortest_to_chars(char* first, char* last, float value) {
  return shortest_text(first, last, value, 9);
}

std::to_chars_result general_to_chars(char* first, char* last, double value, int precision) {
  if (const char* text = non_finite_text(value)) return put_text(first, last, text, std::strlen(text));
  char text[64];
  const int size = std::snprintf(text, sizeof text, "%.*g", precision, value);
  if (std::size_t(size) < sizeof text) return put_text(first, last, text, std::size_t(size));
  std::string longer(std::size_t(size) + 1, '\0');
  std::snprintf(longer.data(), longer.size(), "%.*g", precision, value);
  return put_text(first, last, longer.data(), std::size_t(size));
}

std::from_chars_result number_from_chars(const char* first, const char* last, double& value) {
  const bool is_negative = first != last && *first == '-';
  const char* at = first + (is_negative ? 1 : 0);
  if (starts_with_word(at, last, "inf")) {
    at += starts_with_word(at, last, "infinity") ? 8 : 3;
    value = is_negative ? -HUGE_VAL : HUGE_VAL;
    return {at, std::errc()};
  }
  if (starts_with_word(at, last, "nan")) {
    at += 3;
    // "nan(letters, digits and _)" as one; an unclosed bracket leaves just "nan".
    const char* close = at;
    if (close != last && *close == '(') {
      ++close;
      while (close != last && (is_digit(*close) || is_letter(*close) || *close == '_')) ++close;
      if (close != last && *close == ')') at = close + 1;
    }
    value = std::copysign(NAN, is_negative ? -1.0 : 1.0);
    return {at, std::errc()};
  }
  // Scanned here rather than by strtod, which would also take spaces, '+' and hexadecimal.
  const char* number = at;
  bool has_digits = false, has_nonzero_digit = false;
  for (; at != last && is_digit(*at); ++at) has_digits = true, has_nonzero_digit |= *at != '0';
  if (at != last && *at == '.')
    for (++at; at != last && is_digit(*at); ++at) has_digits = true, has_nonzero_digit |= *at != '0';
  if (!has_digits) return {first, std::errc::invalid_argument};
  if (at != last && (*at == 'e' || *at == 'E')) {
    const char* exponent = at + 1;
    if (exponent != last && (*exponent == '+' || *exponent == '-')) ++exponent;
    if (exponent != last && is_digit(*exponent)) {
      at = exponent;
      while (at != last && is_digit(*at)) ++at;
    }
  }
  const std::string text(number, at);
  const double read = std::strtod(text.c_str(), nullptr);
  if (std::isinf(read) || (read == 0 && has_nonzero_digit)) return {at, std::errc::result_out_of_range};
  value = is_negative ? -read : read;
  return {at, std::errc()};
}

}  // namespace nome::fallback
