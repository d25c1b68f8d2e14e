// User formulas from the input (muparser), e.g. "0.001*x" for a prescribed displacement.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace hpcontact::model {

/// A scalar formula in named variables, checked when constructed. Safe to evaluate from several
/// threads (a parametric curve inside the parallel assembly): evaluations of one formula take
/// turns, since its parser holds the variables and its evaluation stack.
class Expression {
public:
  /// Parses `text` with the variables `names` (e.g. {"x", "y"}); InputError naming `where` if the
  /// formula does not parse or uses an unknown variable.
  Expression(const std::string& text, const std::vector<std::string>& names, const std::string& where);
  ~Expression();
  Expression(const Expression&);
  Expression& operator=(const Expression&) = delete;

  double operator()(double a, double b = 0.0) const;
  const std::string& text() const { return text_; }
  /// True if the text is a plain number.
  bool is_constant() const { return constant_; }

private:
  struct Impl;
  std::string text_, where_;
  std::vector<std::string> names_;
  bool constant_ = false;
  double value_ = 0;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hpcontact::model
