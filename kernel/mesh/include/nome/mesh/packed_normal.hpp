#pragma once

#include <cstdint>

#include <emmintrin.h>

#include <glm/vec3.hpp>

namespace nome {

// A unit normal in 32 bits, three signed normalized 10-bit fields x | y << 10 | z << 20 (and 0 in the top
// two): the layout of glm::packSnorm3x10_1x2 and of GPU vertex data "2_10_10_10_REV, normalized". A display
// normal needs no more (a step of 1/511, about 0.1 degrees) and takes a third of a float vector's bytes,
// which is what a slider's tick at a million faces spends its time moving. Zero packs to zero.
using PackedNormal = std::uint32_t;

// Each component clamped to [-1, 1] and rounded to the nearest step, ties to even. glm's pack rounds ties
// away from zero, with a call per component and bit-field stores: three times the time of these SSE2
// instructions (part of x86-64 itself), on a million normals at each slider tick.
inline PackedNormal pack_normal(const glm::vec3& n) {
  const __m128 clamped =
      _mm_min_ps(_mm_max_ps(_mm_setr_ps(n.x, n.y, n.z, 0.0f), _mm_set1_ps(-1.0f)), _mm_set1_ps(1.0f));
  const __m128i fields =
      _mm_and_si128(_mm_cvtps_epi32(_mm_mul_ps(clamped, _mm_set1_ps(511.0f))), _mm_set1_epi32(0x3ff));
  return std::uint32_t(_mm_cvtsi128_si32(fields)) |
         std::uint32_t(_mm_cvtsi128_si32(_mm_srli_si128(fields, 4))) << 10 |
         std::uint32_t(_mm_cvtsi128_si32(_mm_srli_si128(fields, 8))) << 20;
}

inline glm::vec3 unpack_normal(PackedNormal p) {
  // Each field shifted to the top, then back with its sign.
  const auto component = [p](int shift) {
    return float(std::int32_t(p << (22 - shift)) >> 22) * (1.0f / 511.0f);
  };
  return {component(0), component(10), component(20)};
}

// pack_normal(-n) from pack_normal(n): each field's two's complement, in one word (the low nine bits of
// each field incremented, the carry out of them folded into the field's top bit without passing on).
inline PackedNormal negated(PackedNormal p) {
  constexpr std::uint32_t low = 0x1ffu | 0x1ffu << 10 | 0x1ffu << 20;
  constexpr std::uint32_t top = 0x200u | 0x200u << 10 | 0x200u << 20;
  constexpr std::uint32_t ones = 1u | 1u << 10 | 1u << 20;
  const std::uint32_t complement = ~p;
  return (((complement & low) + ones) ^ (complement & top)) & (low | top);
}

}  // namespace nome
