#include "framework/deck/expression.hpp"

#include <muParser.h>

#include <cmath>

#include "framework/base/error.hpp"

namespace railfe {

// muParser keeps the addresses of the variables, so they live on the heap beside it.
struct Expression::State {
  double x = 0, y = 0, z = 0, t = 0;
  mu::Parser parser;
  std::string text;
};

Expression::Expression(const std::string& text, const std::string& deck, const std::string& path)
    : state_(std::make_unique<State>()) {
  state_->text = text;
  try {
    state_->parser.DefineVar("x", &state_->x);
    state_->parser.DefineVar("y", &state_->y);
    state_->parser.DefineVar("z", &state_->z);
    state_->parser.DefineVar("t", &state_->t);
    state_->parser.SetExpr(text);
    state_->parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    throw_input_error(deck, path, "invalid expression '" + text + "': " + error.GetMsg(),
                      "a muParser expression in x, y, z (m) and t (s)");
  }
}

Expression::~Expression() = default;
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;

double Expression::operator()(double x, double y, double z, double t) const {
  state_->x = x;
  state_->y = y;
  state_->z = z;
  state_->t = t;
  return state_->parser.Eval();
}

const std::string& Expression::text() const {
  return state_->text;
}

std::function<double(double)> function_of_x(const std::string& text, const std::string& deck,
                                            const std::string& path) {
  if (text.empty())
    return {};
  auto expression = std::make_shared<Expression>(text, deck, path);
  return [expression](double x) { return (*expression)(x, 0, 0, 0); };
}

}  // namespace railfe
