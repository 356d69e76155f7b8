#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "nome/buffer.hpp"

using nome::Buffer;

namespace {

constexpr std::size_t megabyte = std::size_t(1) << 20;

// The first value of each 4 KB page of `b`'s first `n` elements (each page's memory as it came, before
// anything wrote it: Buffer::resize leaves it unwritten).
std::vector<int> page_values(const Buffer<int>& b, std::size_t n) {
  std::vector<int> values;
  for (std::size_t i = 0; i < n; i += 4096 / sizeof(int)) values.push_back(b.data()[i]);
  return values;
}

}  // namespace

TEST_CASE("freed big buffers are kept for the next buffer of their size, while a program asks for it",
          "[kernel]") {
  constexpr std::size_t big = 3 * megabyte / sizeof(int);  // 3 MB: a 4 MB block
  nome::keep_freed_buffers(8 * megabyte);
  const int* first = nullptr;
  {
    Buffer<int> a(big, 7);
    first = a.data();
  }
  {
    Buffer<int> again(big + 1000, 1);  // rounds to the same 4 MB block
    CHECK(again.data() == first);
    CHECK(again.back() == 1);
  }
  nome::keep_freed_buffers(0);  // gives the kept blocks back
  Buffer<int> small(16, 3);
  CHECK(small[15] == 3);
}

TEST_CASE("a buffer larger than any kept block is made of the kept blocks' memory, the rest fresh",
          "[kernel]") {
  nome::keep_freed_buffers(64 * megabyte);
  // Three 6 MB blocks kept, with a live block mapped after each, so that they seldom touch and join.
  std::vector<Buffer<int>> between;
  {
    std::vector<Buffer<int>> kept;
    for (int value : {7, 8, 9}) {
      kept.emplace_back(6 * megabyte / sizeof(int), value);
      between.emplace_back(2 * megabyte / sizeof(int), 0);
    }
  }
  const std::size_t n = 20 * megabyte / sizeof(int);
  Buffer<int> gathered;
  gathered.resize(n);
  const std::vector<int> values = page_values(gathered, n);
  // 18 MB of the old blocks' pages, moved with what they held; the last 2 MB fresh (zero).
  const auto old = std::count_if(values.begin(), values.end(), [](int v) { return v >= 7 && v <= 9; });
  CHECK(std::size_t(old) * 4096 == 18 * megabyte);
  CHECK(std::all_of(values.end() - 512, values.end(), [](int v) { return v == 0; }));
  std::fill(gathered.begin(), gathered.end(), 5);
  CHECK(std::count(gathered.begin(), gathered.end(), 5) == std::ptrdiff_t(n));
  CHECK(std::all_of(between.begin(), between.end(), [](const Buffer<int>& b) {
    return std::count(b.begin(), b.end(), 0) == std::ptrdiff_t(b.size());
  }));
  nome::keep_freed_buffers(0);
}

TEST_CASE("kept blocks cut, joined and moved never give two live buffers the same memory", "[kernel]") {
  nome::keep_freed_buffers(48 * megabyte);
  std::mt19937 random(18);
  std::vector<Buffer<std::uint32_t>> live;
  std::vector<std::uint32_t> tags;
  auto holds_its_tag = [&](std::size_t i) {
    return std::all_of(live[i].begin(), live[i].end(), [&](std::uint32_t v) { return v == tags[i]; });
  };
  for (std::uint32_t step = 1; step <= 300; ++step) {
    if (live.size() < 8 && (live.empty() || random() % 3 != 0)) {
      const std::size_t bytes = (2 + random() % 12) * megabyte + random() % megabyte;
      live.emplace_back(bytes / sizeof(std::uint32_t), step);
      tags.push_back(step);
    } else {
      const std::size_t i = random() % live.size();
      REQUIRE(holds_its_tag(i));
      live.erase(live.begin() + std::ptrdiff_t(i));
      tags.erase(tags.begin() + std::ptrdiff_t(i));
    }
  }
  for (std::size_t i = 0; i < live.size(); ++i) CHECK(holds_its_tag(i));
  live.clear();
  nome::keep_freed_buffers(0);
}

// Two kept blocks that touch become one range, whichever is freed first: a buffer the size of both then
// takes that range where it lies instead of moving pages into a new mapping.
TEST_CASE("two freed blocks that touch are joined into one kept range whichever is freed first", "[kernel]") {
  constexpr std::size_t n = 4 * megabyte / sizeof(int);  // a 4 MB block each
  for (const bool is_lower_freed_first : {true, false}) {
    INFO("lower block freed first: " << is_lower_freed_first);
    nome::keep_freed_buffers(0);
    nome::keep_freed_buffers(64 * megabyte);
    // An 8 MB block kept, then cut into two 4 MB blocks that touch.
    const int* whole = nullptr;
    {
      Buffer<int> eight(2 * n, 0);
      whole = eight.data();
    }
    {
      std::vector<Buffer<int>> pair;
      pair.emplace_back(n, 1);
      pair.emplace_back(n, 2);
      REQUIRE(std::min(pair[0].data(), pair[1].data()) == whole);
      REQUIRE(std::max(pair[0].data(), pair[1].data()) == whole + n);
      if ((pair[0].data() == whole) != is_lower_freed_first) std::swap(pair[0], pair[1]);
      pair.erase(pair.begin());
    }
    Buffer<int> both;
    both.resize(2 * n);
    CHECK(both.data() == whole);
  }
  nome::keep_freed_buffers(0);
}
