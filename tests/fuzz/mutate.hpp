// SPDX-License-Identifier: Apache-2.0
// Random mutations of a file's bytes for the fuzz driver: bit flips, byte
// changes, truncation, insertions, erasures, header field edits (with the PNG
// IHDR CRC fixed up so the decoder believes them), duplications and splices.
// Everything is drawn from the given generator: same seed, same mutations.
#pragma once

#include "bad_images.hpp"

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace sgm::test {

class Mutator {
 public:
  explicit Mutator(std::mt19937_64& rng) : rng_(rng) {}

  // 1 .. 4 mutations of bytes; other is the material for splices.
  std::string mutate(std::string bytes, const std::string& other) {
    const int count = 1 + int(below(4));
    for (int i = 0; i < count; ++i) bytes = mutateOnce(std::move(bytes), other);
    return bytes;
  }

 private:
  uint64_t below(uint64_t n) { return n ? rng_() % n : 0; }
  // A position biased towards the header (the first 64 bytes) half of the time.
  size_t position(size_t size) { return below(2) ? below(std::min<size_t>(size, 64)) : below(size); }

  uint32_t interestingValue() {
    static const uint32_t values[] = {0,      1,      2,      7,       8,          9,           15,
                                      16,     17,     255,    256,     16383,      16384,       16385,
                                      0x7fff, 0x8000, 0xffff, 0x10000, 0x7fffffff, 0x80000000u, 0xffffffffu};
    return values[below(sizeof values / sizeof values[0])];
  }

  std::string mutateOnce(std::string b, const std::string& other) {
    if (b.empty()) return std::string(1, char(below(256)));
    const size_t n = b.size();
    switch (below(9)) {
      case 0: {  // flip a bit
        const size_t at = position(n);
        b[at] = char(b[at] ^ (1 << below(8)));
        return b;
      }
      case 1: {  // set a byte
        static const uint8_t special[] = {0x00, 0xff, 0x7f, 0x80, 0x01};
        b[position(n)] = char(below(2) ? special[below(5)] : below(256));
        return b;
      }
      case 2:  // truncate
        return b.substr(0, below(2) ? below(std::min<size_t>(n, 64)) : below(n));
      case 3: {  // insert random bytes
        std::string junk(1 + below(16), '\0');
        for (char& c : junk) c = char(below(256));
        return b.insert(position(n), junk);
      }
      case 4: {  // erase a range
        const size_t at = position(n);
        return b.erase(at, 1 + below(std::min<size_t>(n - at, 32)));
      }
      case 5: {  // header field: 1, 2 or 4 bytes, big or little endian
        const int width = 1 << below(3);
        if (n < size_t(width)) return b;
        const size_t at = below(std::min<size_t>(n - width + 1, 64));
        const uint32_t v = interestingValue();
        const bool big = below(2);
        for (int i = 0; i < width; ++i) b[at + i] = char(v >> (8 * (big ? width - 1 - i : i)));
        return b;
      }
      case 6:  // PNG IHDR field (width, height, depth, colour type, interlace) with the CRC fixed up
        if (n > 33 && b.compare(1, 3, "PNG") == 0) {
          static const int fields[][2] = {{16, 4}, {20, 4}, {24, 1}, {25, 1}, {28, 1}};
          const auto& f = fields[below(5)];
          const uint32_t v = below(2) ? interestingValue() : uint32_t(below(32));
          putBigEndian(b, size_t(f[0]), f[1] == 4 ? v : (v & 0xff), f[1]);
          putBigEndian(b, 29, crc32(reinterpret_cast<const uint8_t*>(b.data()) + 12, 17), 4);
        }
        return b;
      case 7: {  // duplicate a chunk elsewhere
        const size_t at = below(n), len = 1 + below(std::min<size_t>(n - at, 256));
        return b.insert(below(n), b.substr(at, len));
      }
      default: {  // splice: this file's beginning, the other's end
        if (other.empty()) return b;
        return b.substr(0, below(n)) + other.substr(below(other.size()));
      }
    }
  }

  std::mt19937_64& rng_;
};

}  // namespace sgm::test
