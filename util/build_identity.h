// The identity of what this build of skinsim computes: "sha256:" and 16 hex digits, a hash
// of the compiler and of every source file that decides a stored figure or image (generated
// by cmake/build_identity.cmake). Results and caches that a later run may reuse carry it: a
// sweep resumed by another build recomputes rather than mixing two builds' numbers.
#pragma once

#include <string_view>

namespace skinsim {

std::string_view build_identity();

}  // namespace skinsim
