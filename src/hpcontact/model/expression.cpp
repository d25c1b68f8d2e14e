// muparser behind a small value type.
#include "hpcontact/model/expression.hpp"

#include <cmath>
#include <cstdlib>
#include <mutex>

#include <muParser.h>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::model {

namespace {
/// The formula as messages quote it: whole if short, else its start and its length.
std::string shown(const std::string& text) {
  constexpr std::size_t kShown = 80;
  if (text.size() <= kShown) return "'" + text + "'";
  return "'" + text.substr(0, kShown) + "...' (" + std::to_string(text.size()) + " characters)";
}

/// muparser's message, which may quote the formula again, cut to a line.
std::string shown_message(const std::string& message) {
  constexpr std::size_t kShown = 200;
  return message.size() <= kShown ? message : message.substr(0, kShown) + "...";
}
}  // namespace

struct Expression::Impl {
  mu::Parser parser;
  double vars[2] = {0, 0};
  std::mutex turn;  ///< one evaluation at a time: vars and the parser's stack are shared
};

Expression::Expression(const std::string& text, const std::vector<std::string>& names,
                       const std::string& where)
    : text_(text), where_(where), names_(names) {
  char* end = nullptr;
  value_ = std::strtod(text.c_str(), &end);
  if (end != text.c_str() && *end == '\0' && std::isfinite(value_)) {
    constant_ = true;
    return;
  }
  impl_ = std::make_unique<Impl>();
  try {
    for (size_t i = 0; i < names_.size() && i < 2; ++i)
      impl_->parser.DefineVar(names_[i], &impl_->vars[i]);
    impl_->parser.DefineConst("pi", 3.14159265358979323846);
    impl_->parser.SetExpr(text_);
    impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(where_ + ": cannot evaluate " + shown(text_) + ": " + shown_message(e.GetMsg()));
  }
}

Expression::~Expression() = default;

Expression::Expression(const Expression& other)
    : Expression(other.text_, other.names_, other.where_) {}

double Expression::operator()(double a, double b) const {
  if (constant_) return value_;
  double v;
  try {
    const std::lock_guard<std::mutex> lock(impl_->turn);
    impl_->vars[0] = a;
    impl_->vars[1] = b;
    v = impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(where_ + ": cannot evaluate " + shown(text_) + ": " + shown_message(e.GetMsg()));
  }
  HPC_REQUIRE(std::isfinite(v), InputError, where_, ": ", shown(text_), " is not finite at (", a,
              ", ", b, ")");
  HPC_REQUIRE(std::abs(v) <= kMaxMagnitude, InputError, where_, ": ", shown(text_), " is ", v, " at (",
              a, ", ", b, "), beyond the magnitude ", kMaxMagnitude,
              " of input values (products of them must stay within double precision)");
  return v;
}

}  // namespace hpcontact::model
