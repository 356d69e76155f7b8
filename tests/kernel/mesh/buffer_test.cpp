#include <catch2/catch.hpp>

#include "nome/mesh/buffer.hpp"

using nome::Buffer;

TEST_CASE("freed big buffers are kept for the next buffer of their size, while a program asks for it",
          "[kernel]") {
  constexpr std::size_t big = (std::size_t(3) << 20) / sizeof(int);  // 3 MB: a 4 MB block
  nome::keep_freed_buffers(std::size_t(8) << 20);
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
