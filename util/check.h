// Internal invariants, apart from user errors (pbrt-v4's util/check.h is the model). A failed
// SKINSIM_CHECK is a bug in skinsim, never bad input: it prints the condition, the operands
// and where it failed, then aborts. Bad input throws a UserError with a message instead.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

namespace skinsim::detail {

[[noreturn]] inline void check_failed(const char* file, int line, const char* condition,
                                      const std::string& operands) {
  std::fprintf(stderr, "skinsim: internal error (a bug in skinsim): %s:%d: CHECK(%s) failed%s%s\n",
               file, line, condition, operands.empty() ? "" : ": ", operands.c_str());
  std::fflush(stderr);
  std::abort();
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
