#pragma once
/// \file
/// Scalar functions of position and time written in a deck, e.g. "1e-3*(2*x + y + z)/2"
/// (muParser syntax: + - * / ^, sin, cos, exp, sqrt, abs, min, max, pi via _pi).

#include <functional>
#include <memory>
#include <string>

namespace railfe {

/// A parsed expression in the variables x, y, z (m) and t (s).
class Expression {
 public:
  /// Parses \p text; throws InputError naming \p deck and \p path if it is not a valid expression
  /// in x, y, z, t.
  Expression(const std::string& text, const std::string& deck, const std::string& path);
  ~Expression();
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;

  /// The value at (x, y, z) and time t. Not thread-safe.
  double operator()(double x, double y, double z, double t = 0) const;
  /// The text it was parsed from.
  const std::string& text() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// A function of one variable written in a deck with x, e.g. of the position s along a track:
/// \p text parsed as an Expression (InputError naming \p deck and \p path), or an empty
/// function for ''.
std::function<double(double)> function_of_x(const std::string& text, const std::string& deck,
                                            const std::string& path);

}  // namespace railfe
