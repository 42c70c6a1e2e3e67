// Internal invariants, apart from user errors (pbrt-v4's util/check.h is the model). A failed
// SKINSIM_CHECK is a bug in skinsim, never bad input: it prints the condition, the operands
// and where it failed, then aborts. Bad input throws a UserError with a message instead.
//
// SKINSIM_DCHECK and SKINSIM_DCHECK_INDEX are the emulator's contracts: checks on its hot
// paths (binding indices, varying slots, texels, tile memory) that cost too much to keep in
// Release. They compile to nothing unless SKINSIM_DEBUG_CHECKS is defined (the CMake option
// of that name, on in the sanitizer build); a failed one reports a bug in skinsim and exits
// with status 3, as every internal error does. It exits from where it fails rather than
// throwing, because hot paths run inside TBB tasks and noexcept code.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>

namespace skinsim::detail {

[[noreturn]] inline void check_failed(const char* file, int line, const char* condition,
                                      const std::string& operands) {
  std::fprintf(stderr, "skinsim: internal error (a bug in skinsim): %s:%d: CHECK(%s) failed%s%s\n",
               file, line, condition, operands.empty() ? "" : ": ", operands.c_str());
  std::fflush(stderr);
  std::abort();
}

[[noreturn]] inline void contract_failed(const char* file, int line, const char* condition,
                                         const std::string& operands) {
  std::fprintf(stderr,
               "skinsim: internal error (a bug in skinsim): %s:%d: contract (%s) failed%s%s\n",
               file, line, condition, operands.empty() ? "" : ": ", operands.c_str());
  std::fflush(stderr);
  std::_Exit(3);
}

template <typename A, typename B>
std::string check_operands(const char* a_text, const A& a, const char* b_text, const B& b) {
  std::ostringstream out;
  out << a_text << " = " << a << ", " << b_text << " = " << b;
  return out.str();
}

}  // namespace skinsim::detail

#define SKINSIM_CHECK(condition)                                                           \
  do {                                                                                     \
    if (!(condition)) ::skinsim::detail::check_failed(__FILE__, __LINE__, #condition, ""); \
  } while (false)

#define SKINSIM_CHECK_OP(a, op, b)                                                      \
  do {                                                                                  \
    const auto& skinsim_check_a = (a);                                                  \
    const auto& skinsim_check_b = (b);                                                  \
    if (!(skinsim_check_a op skinsim_check_b)) {                                        \
      ::skinsim::detail::check_failed(                                                  \
          __FILE__, __LINE__, #a " " #op " " #b,                                        \
          ::skinsim::detail::check_operands(#a, skinsim_check_a, #b, skinsim_check_b)); \
    }                                                                                   \
  } while (false)

#define SKINSIM_CHECK_EQ(a, b) SKINSIM_CHECK_OP(a, ==, b)
#define SKINSIM_CHECK_NE(a, b) SKINSIM_CHECK_OP(a, !=, b)
#define SKINSIM_CHECK_LT(a, b) SKINSIM_CHECK_OP(a, <, b)
#define SKINSIM_CHECK_LE(a, b) SKINSIM_CHECK_OP(a, <=, b)
#define SKINSIM_CHECK_GT(a, b) SKINSIM_CHECK_OP(a, >, b)
#define SKINSIM_CHECK_GE(a, b) SKINSIM_CHECK_OP(a, >=, b)

#ifdef SKINSIM_DEBUG_CHECKS
#define SKINSIM_DCHECK(condition)                                                             \
  do {                                                                                        \
    if (!(condition)) ::skinsim::detail::contract_failed(__FILE__, __LINE__, #condition, ""); \
  } while (false)
// 0 <= index < size, for any integer types (a negative index fails, whatever size's sign).
#define SKINSIM_DCHECK_INDEX(index, size)                                                        \
  do {                                                                                           \
    const auto skinsim_dcheck_i = (index);                                                       \
    const auto skinsim_dcheck_n = (size);                                                        \
    if (!(std::cmp_greater_equal(skinsim_dcheck_i, 0) &&                                         \
          std::cmp_less(skinsim_dcheck_i, skinsim_dcheck_n))) {                                  \
      ::skinsim::detail::contract_failed(                                                        \
          __FILE__, __LINE__, "0 <= " #index " < " #size,                                        \
          ::skinsim::detail::check_operands(#index, skinsim_dcheck_i, #size, skinsim_dcheck_n)); \
    }                                                                                            \
  } while (false)
#else
// Not evaluated, but still compiled (sizeof), so a contract cannot rot unseen in Release.
#define SKINSIM_DCHECK(condition) static_cast<void>(sizeof(static_cast<bool>(condition)))
#define SKINSIM_DCHECK_INDEX(index, size) static_cast<void>(sizeof(index) + sizeof(size))
#endif
