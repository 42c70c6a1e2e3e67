// Content fingerprints: a stored result records the fingerprint of the inputs it was made
// from (a device profile's bytes), so a later run can tell whether they changed.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace skinsim {

// FNV-1a, 64-bit (Fowler, Noll, Vo; offset basis and prime from the reference,
// http://www.isthe.com/chongo/tech/comp/fnv/), as 16 hex digits. Not cryptographic: it tells
// edits apart, it does not resist forgery.
inline std::string fnv1a64_hex(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  char text[16 + 1];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

// "fnv1a64:<16 hex digits>", the algorithm named, as stored results record it.
inline std::string content_fingerprint(std::string_view bytes) {
  return "fnv1a64:" + fnv1a64_hex(bytes);
}

}  // namespace skinsim
