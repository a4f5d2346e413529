// memset for the STM32F405 images, in place of newlib-nano's: 164 B of flash, unrolled for
// speed. The flight image calls it to zero a few sums: the release window's block when one
// starts (48 B, once a block_us), a check's seed, a flight's result and its parts at
// start-up. A byte loop (18 B) made room for other code first: 146 B of flash less, 17 more
// instructions per sample (2,577 -> 2,594). This one stores whole words where it can (bytes
// up to a 4-byte boundary, words of the byte, the last bytes): 52 B, and for the image's
// 32 B of flash more (32,044 -> 32,076 B) 16 instructions per sample less (2,595 -> 2,579).
// Measured too (function, image, instructions per sample): the words counted in n, not to
// the end, 60 B, 32,084 B, 2,578; unrolled by two, 70 B, 32,092 B, 2,578; one loop storing a
// word where aligned with 4 bytes left, else a byte, 42 B, 32,068 B, 2,582. Compiled as
// small_memcpy.cpp is: -Os, and not turned back into a call to memset (../CMakeLists.txt).
#include <cstddef>
#include <cstdint>
#include <cstring>

extern "C" void* memset(void* dst, int value, std::size_t n) {
  using Word = std::uint32_t __attribute__((may_alias));  // whatever dst holds
  auto* to = static_cast<unsigned char*>(dst);
  auto* const end = to + n;
  const auto byte = static_cast<unsigned char>(value);
  while (to != end && (reinterpret_cast<std::uintptr_t>(to) & 3u) != 0) *to++ = byte;
  const Word word = byte * 0x01010101u;
  for (; end - to >= 4; to += 4) *reinterpret_cast<Word*>(to) = word;
  while (to != end) *to++ = byte;
  return dst;
}
