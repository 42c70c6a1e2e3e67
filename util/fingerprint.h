// Content fingerprints: a stored result records the fingerprint of the inputs it was made
// from (a device profile's bytes), so a later run can tell whether they changed.
#pragma once

#include <xxhash.h>

#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <memory>
#include <new>
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

// "xxh3-64:<16 hex digits>" of `parts` read as one stream (XXH3's streaming digest equals its
// one-shot digest of the concatenation): what a sweep records of its images' bytes and the
// reference store of its pixels, to tell a damaged or swapped copy from the one written. XXH3
// rather than FNV-1a: it digests megabytes of pixels at memory speed.
inline std::string xxh3_fingerprint(std::initializer_list<std::string_view> parts) {
  const std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(),
                                                                       XXH3_freeState);
  if (!state || XXH3_64bits_reset(state.get()) == XXH_ERROR) throw std::bad_alloc();
  for (const std::string_view part : parts) {
    XXH3_64bits_update(state.get(), part.data(), part.size());
  }
  char text[16 + 1];
  std::snprintf(text, sizeof text, "%016llx",
                static_cast<unsigned long long>(XXH3_64bits_digest(state.get())));
  return std::string("xxh3-64:") + text;
}

}  // namespace skinsim
