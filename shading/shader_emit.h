#pragma once

// The third instantiation of the shading language (beside Exec and Count): Emit.
// An EVec<N> carries the GLSL expression that computes it; every non-constant
// operation appends a statement `vecN tK = EXPR;` to the thread-local GlslEmitter,
// so the exported source reads one statement per line with named temporaries.
// Operations whose operands are all constants fold to a literal exactly as Count
// folds them (so the emitted code has the ops the op profile counts).
//
// The shader's inputs, outputs and texture reads are spelled by sim/shader_emit_io.h; the
// program wrappers (sim/program.h) assemble whole shaders from a body and its interface.

#include <cmath>
#include <glm/glm.hpp>
#include <set>
#include <string>
#include <vector>

namespace skinsim::sim::sl {

// The GLSL ES version a body is emitted for: 1.00 (OpenGL ES 2.0, the iPad 4's API, with
// the extensions its GPU has) or 3.00 (OpenGL ES 3.0, where those are core).
enum class GlslDialect : std::uint8_t { kEs100, kEs300 };

// Collects the statements of one shader body. Nests like OpRecorder: the
// innermost live emitter receives statements.
class GlslEmitter {
 public:
  explicit GlslEmitter(GlslDialect dialect = GlslDialect::kEs100)
      : previous_(current_), dialect_(dialect) {
    current_ = this;
  }
  ~GlslEmitter() { current_ = previous_; }
  GlslEmitter(const GlslEmitter&) = delete;
  GlslEmitter& operator=(const GlslEmitter&) = delete;

  // Appends `TYPE tK = EXPR;` and returns the temporary's name. Without a
  // live emitter the expression is returned unnamed (nothing to append to).
  static std::string bind(const std::string& type, const std::string& expr);
  // Appends a raw statement (e.g. `gl_FragColor = t3;`).
  static void statement(const std::string& text);

  // The dialect of the live emitter (ES 1.00 without one).
  static GlslDialect dialect() { return current_ ? current_->dialect_ : GlslDialect::kEs100; }
  // Notes an ES 1.00 extension the body uses (none is needed in ES 3.00).
  static void require_extension(const char* name) {
    if (current_ && current_->dialect_ == GlslDialect::kEs100) current_->extensions_.insert(name);
  }

  // The body, one statement a line, each indented by `indent` spaces.
  std::string body(int indent = 2) const;
  const std::set<std::string>& extensions() const { return extensions_; }

 private:
  static inline thread_local GlslEmitter* current_ = nullptr;
  GlslEmitter* previous_;
  GlslDialect dialect_;
  std::vector<std::string> lines_;
  std::set<std::string> extensions_;
  int next_temp_ = 0;
};

// GLSL spelling of a float literal that reads back to the same float
// (always with a decimal point or exponent, as GLSL ES 1.00 requires).
std::string glsl_float(float f);

template <int N>
struct EVec;

namespace emit_detail {
// A constructor argument's value and GLSL spelling.
inline float raw(float f) {
  return f;
}
template <int M>
glm::vec<M, float> raw(const glm::vec<M, float>& v) {
  return v;
}
template <int M>
auto raw(const EVec<M>& e) {
  if constexpr (M == 1) {
    return e.v.x;
  } else {
    return e.v;
  }
}
inline bool is_constant(float) {
  return true;
}
template <int M>
bool is_constant(const glm::vec<M, float>&) {
  return true;
}
template <int M>
bool is_constant(const EVec<M>& e) {
  return e.constant;
}
inline std::string spelling(float f);
template <int M>
std::string spelling(const glm::vec<M, float>& v);
template <int M>
std::string spelling(const EVec<M>& e) {
  return e.expr;
}
}  // namespace emit_detail

template <int N>
struct EVec {
  using value_type = glm::vec<N, float>;
  value_type v{0.0f};    // the folded value while constant
  bool constant = true;  // expr is a literal of v
  std::string expr;      // a temporary's name, an input's name, or a literal

  EVec() : expr(literal(v)) {}
  EVec(const value_type& value) : v(value), expr(literal(value)) {}  // NOLINT: constants convert
  EVec(float s) requires(N == 1) : v(s), expr(literal(v)) {}         // NOLINT
  explicit EVec(float s) requires(N > 1) : v(s), expr(literal(v)) {}
  // A scalar splat, vecN(s): free, as in Count.
  template <int M>
  requires(M == 1 && N > 1) explicit EVec(const EVec<M>& s)
      : v(s.v.x),
        constant(s.constant),
        expr(constant ? literal(v) : type_name() + ("(" + s.expr + ")")) {}
  // Construction from parts, vec4(p, 1.0): a constructor, not an operation.
  template <typename... Parts>
  requires(sizeof...(Parts) >= 2) EVec(const Parts&... parts)  // NOLINT: as GLSL's
      : v(emit_detail::raw(parts)...), constant((emit_detail::is_constant(parts) && ...)) {
    if (constant) {
      expr = literal(v);
    } else {
      expr = type_name();
      const char* separator = "(";
      ((expr += separator, expr += emit_detail::spelling(parts), separator = ", "), ...);
      expr += ")";
    }
  }

  // A value read from outside the shader body (attribute, varying, sampler result).
  static EVec named(const std::string& name) {
    EVec e;
    e.constant = false;
    e.expr = name;
    return e;
  }
  static const char* type_name() {
    if constexpr (N == 1) {
      return "float";
    } else if constexpr (N == 2) {
      return "vec2";
    } else if constexpr (N == 3) {
      return "vec3";
    } else {
      return "vec4";
    }
  }
  static std::string literal(const value_type& value) {
    if constexpr (N == 1) {
      return glsl_float(value.x);
    } else {
      bool splat = true;
      for (int i = 1; i < N; ++i) splat = splat && value[i] == value[0];
      std::string s = std::string(type_name()) + "(" + glsl_float(value[0]);
      for (int i = 1; i < N && !splat; ++i) s += ", " + glsl_float(value[i]);
      return s + ")";
    }
  }
  // A computed value: emitted as a named temporary.
  static EVec computed(const std::string& expression) {
    return named(GlslEmitter::bind(type_name(), expression));
  }
};
using EFloat = EVec<1>;

namespace emit_detail {
inline std::string spelling(float f) {
  return glsl_float(f);
}
template <int M>
std::string spelling(const glm::vec<M, float>& v) {
  return EVec<M>::literal(v);
}
constexpr int result_lanes(int n, int m) {
  return n > m ? n : m;
}
template <int R, int N>
glm::vec<R, float> widen(const glm::vec<N, float>& v) {
  if constexpr (N == R) {
    return v;
  } else {
    return glm::vec<R, float>(v.x);
  }
}
}  // namespace emit_detail

#define SKINSIM_SL_EMIT_BINOP(op)                                                             \
  template <int N, int M>                                                                     \
  inline EVec<emit_detail::result_lanes(N, M)> operator op(                                   \
      const EVec<N>& a, const EVec<M>& b) requires(N == M || N == 1 || M == 1) {              \
    constexpr int R = emit_detail::result_lanes(N, M);                                        \
    if (a.constant && b.constant)                                                             \
      return EVec<R>(emit_detail::widen<R>(a.v) op emit_detail::widen<R>(b.v));               \
    return EVec<R>::computed(a.expr + " " #op " " + b.expr);                                  \
  }                                                                                           \
  template <int N>                                                                            \
  inline EVec<N> operator op(const EVec<N>& a, float b) {                                     \
    return a op EFloat(b);                                                                    \
  }                                                                                           \
  template <int N>                                                                            \
  inline EVec<N> operator op(float a, const EVec<N>& b) {                                     \
    return EFloat(a) op b;                                                                    \
  }                                                                                           \
  template <int N>                                                                            \
  inline EVec<N> operator op(const EVec<N>& a, const glm::vec<N, float>& b) requires(N > 1) { \
    return a op EVec<N>(b);                                                                   \
  }                                                                                           \
  template <int N>                                                                            \
  inline EVec<N> operator op(const glm::vec<N, float>& a, const EVec<N>& b) requires(N > 1) { \
    return EVec<N>(a) op b;                                                                   \
  }

SKINSIM_SL_EMIT_BINOP(+)
SKINSIM_SL_EMIT_BINOP(-)
SKINSIM_SL_EMIT_BINOP(*)
SKINSIM_SL_EMIT_BINOP(/)
#undef SKINSIM_SL_EMIT_BINOP

template <int N>
inline EVec<N> operator-(const EVec<N>& a) {
  if (a.constant) return EVec<N>(-a.v);
  // A source modifier, as Count treats it. Operands are names, swizzles or
  // literals, so a prefix needs no parentheses; a double minus would read as "--".
  if (a.expr.starts_with('-')) return EVec<N>::named(a.expr.substr(1));
  return EVec<N>::named("-" + a.expr);
}

template <int N>
inline EFloat dot(const EVec<N>& a, const EVec<N>& b) {
  if (a.constant && b.constant) return EFloat(glm::dot(a.v, b.v));
  return EFloat::computed("dot(" + a.expr + ", " + b.expr + ")");
}
template <int N>
inline EFloat dot(const EVec<N>& a, const glm::vec<N, float>& b) {
  return dot(a, EVec<N>(b));
}
template <int N>
inline EFloat dot(const glm::vec<N, float>& a, const EVec<N>& b) {
  return dot(EVec<N>(a), b);
}

// Component selection is a swizzle of the operand, not an operation.
template <int N>
inline EFloat component(const EVec<N>& a, int i) {
  if (a.constant) return EFloat(a.v[i]);
  static constexpr const char* kLanes[] = {"x", "y", "z", "w"};
  if constexpr (N == 1) {
    return a;
  } else {
    return EFloat::named(a.expr + "." + kLanes[i]);
  }
}
#define SKINSIM_SL_EMIT_LANE(name, lane) \
  template <int N>                       \
  inline EFloat name(const EVec<N>& a) { \
    return component(a, lane);           \
  }
SKINSIM_SL_EMIT_LANE(x, 0)
SKINSIM_SL_EMIT_LANE(y, 1)
SKINSIM_SL_EMIT_LANE(z, 2)
SKINSIM_SL_EMIT_LANE(w, 3)
#undef SKINSIM_SL_EMIT_LANE

template <int N>
inline EVec<2> xy(const EVec<N>& a) requires(N > 2) {
  if (a.constant) return EVec<2>(glm::vec2(a.v.x, a.v.y));
  return EVec<2>::named(a.expr + ".xy");
}
inline EVec<3> xyz(const EVec<4>& a) {
  if (a.constant) return EVec<3>(glm::vec3(a.v));
  return EVec<3>::named(a.expr + ".xyz");
}
// A source modifier, free as in Count.
template <int N>
inline EVec<N> abs(const EVec<N>& a) {
  if (a.constant) return EVec<N>(glm::abs(a.v));
  return EVec<N>::named("abs(" + a.expr + ")");
}
// Screen-space derivatives (fwidth's parts): one op each, from the 2x2 quad.
template <int N>
inline EVec<N> dFdx(const EVec<N>& a) {
  GlslEmitter::require_extension("GL_OES_standard_derivatives");
  return EVec<N>::computed("dFdx(" + a.expr + ")");
}
template <int N>
inline EVec<N> dFdy(const EVec<N>& a) {
  GlslEmitter::require_extension("GL_OES_standard_derivatives");
  return EVec<N>::computed("dFdy(" + a.expr + ")");
}

#define SKINSIM_SL_EMIT_UNARY(name, glsl_call, fold)                 \
  template <int N>                                                   \
  inline EVec<N> name(const EVec<N>& a) {                            \
    if (a.constant) {                                                \
      glm::vec<N, float> r;                                          \
      for (int i = 0; i < N; ++i) {                                  \
        const float v = a.v[i];                                      \
        r[i] = (fold);                                               \
      }                                                              \
      return EVec<N>(r);                                             \
    }                                                                \
    return EVec<N>::computed(std::string(glsl_call) + a.expr + ")"); \
  }

SKINSIM_SL_EMIT_UNARY(exp2, "exp2(", std::exp2(v))
SKINSIM_SL_EMIT_UNARY(log2, "log2(", std::log2(v))
SKINSIM_SL_EMIT_UNARY(sqrt, "sqrt(", std::sqrt(v))
SKINSIM_SL_EMIT_UNARY(rsqrt, "inversesqrt(", 1.0f / std::sqrt(v))
SKINSIM_SL_EMIT_UNARY(sin, "sin(", std::sin(v))
SKINSIM_SL_EMIT_UNARY(cos, "cos(", std::cos(v))
SKINSIM_SL_EMIT_UNARY(floor, "floor(", std::floor(v))
SKINSIM_SL_EMIT_UNARY(fract, "fract(", v - std::floor(v))
#undef SKINSIM_SL_EMIT_UNARY

template <int N>
inline EVec<N> rcp(const EVec<N>& a) {
  if (a.constant) return EVec<N>(1.0f / a.v);
  return EVec<N>::computed("1.0 / " + a.expr);
}
template <int N>
inline EVec<N> saturate(const EVec<N>& a) {
  if (a.constant) return EVec<N>(glm::clamp(a.v, 0.0f, 1.0f));
  return EVec<N>::computed("clamp(" + a.expr + ", 0.0, 1.0)");
}

#define SKINSIM_SL_EMIT_BINARY(name, fold)                                                   \
  template <int N, int M>                                                                    \
  inline EVec<emit_detail::result_lanes(N, M)> name(                                         \
      const EVec<N>& a, const EVec<M>& b) requires(N == M || N == 1 || M == 1) {             \
    constexpr int R = emit_detail::result_lanes(N, M);                                       \
    if (a.constant && b.constant)                                                            \
      return EVec<R>(fold(emit_detail::widen<R>(a.v), emit_detail::widen<R>(b.v)));          \
    /* GLSL has min(vecN, float) but not min(float, vecN): splat a scalar first operand */   \
    const std::string first =                                                                \
        (N == 1 && R > 1) ? std::string(EVec<R>::type_name()) + "(" + a.expr + ")" : a.expr; \
    return EVec<R>::computed(#name "(" + first + ", " + b.expr + ")");                       \
  }                                                                                          \
  template <int N>                                                                           \
  inline EVec<N> name(const EVec<N>& a, float b) {                                           \
    return name(a, EFloat(b));                                                               \
  }                                                                                          \
  template <int N>                                                                           \
  inline EVec<N> name(float a, const EVec<N>& b) requires(N == 1) {                          \
    return name(EFloat(a), b);                                                               \
  }                                                                                          \
  template <int N>                                                                           \
  inline EVec<N> name(const EVec<N>& a, const glm::vec<N, float>& b) requires(N > 1) {       \
    return name(a, EVec<N>(b));                                                              \
  }

SKINSIM_SL_EMIT_BINARY(min, glm::min)
SKINSIM_SL_EMIT_BINARY(max, glm::max)
SKINSIM_SL_EMIT_BINARY(step, glm::step)
#undef SKINSIM_SL_EMIT_BINARY

inline EVec<3> cross(const EVec<3>& a, const EVec<3>& b) {
  if (a.constant && b.constant) return EVec<3>(glm::cross(a.v, b.v));
  return EVec<3>::computed("cross(" + a.expr + ", " + b.expr + ")");
}

// Folds only when every operand is constant, as Count does (it charges one op otherwise).
template <int N>
inline EVec<N> select(const EFloat& c, const EVec<N>& a, const EVec<N>& b) {
  if (c.constant && a.constant && b.constant) return EVec<N>(c.v.x > 0.0f ? a.v : b.v);
  return EVec<N>::computed(c.expr + " > 0.0 ? " + a.expr + " : " + b.expr);
}

// GLSL spelling of a uniform matrix, inlined column by column (both glm and GLSL
// constructors are column-major).
template <int C>
std::string glsl_matrix(const glm::mat<C, C, float>& m) {
  std::string s = "mat" + std::to_string(C) + "(";
  for (int column = 0; column < C; ++column) {
    for (int row = 0; row < C; ++row) {
      if (column + row > 0) s += ", ";
      s += glsl_float(m[column][row]);
    }
  }
  return s + ")";
}
template <int C>
inline EVec<C> operator*(const glm::mat<C, C, float>& m,
                         const EVec<C>& v) requires(C == 3 || C == 4) {
  if (v.constant) return EVec<C>(m * v.v);
  return EVec<C>::computed(glsl_matrix(m) + " * " + v.expr);
}

}  // namespace skinsim::sim::sl
