// Memory points of frictional contact.
#include "hpcontact/model/memory_points.hpp"

#include <algorithm>
#include <cmath>

namespace hpcontact::model {

namespace {

/// Whether, in a step, the point at coordinate s stuck: its nearest point of the pair stuck.
bool stuck_at(const std::vector<double>& stuck, const std::vector<double>& slipped, double s) {
  auto nearest = [s](const std::vector<double>& v) {
    double d = INFINITY;
    for (double t : v) d = std::min(d, std::abs(t - s));
    return d;
  };
  return !stuck.empty() && nearest(stuck) <= nearest(slipped);
}

/// The largest distance between two of the last state's zone ends of the pair.
double zone_extent(const ContactResult& c) {
  double extent = 0;
  for (int i : c.outer_ends)
    for (int j : c.outer_ends) extent = std::max(extent, (c.gamma_star[i] - c.gamma_star[j]).norm());
  return extent;
}

}  // namespace

MemoryPoints memory_points(const NonlinearSolution& sol, size_t k) {
  MemoryPoints m;
  const auto& history = sol.stick_slip_history;
  if (k >= sol.contact.size() || k >= sol.pairs.size() || history.size() < 2) return m;
  const ContactPair& pair = sol.pairs[k];
  const ContactResult& c = sol.contact[k];
  const double apart = 1e-3 * zone_extent(c);
  auto stuck_since = [&](size_t step, const Vec2& X) {
    const double s = pair.coordinate(X);
    for (size_t later = step + 1; later < history.size(); ++later)
      if (k >= history[later].stuck.size() || !stuck_at(history[later].stuck[k], history[later].slipped[k], s))
        return false;
    return true;
  };
  auto add = [&](std::vector<Vec2>& points, const std::vector<Vec2>& last, const Vec2& X) {
    auto near = [&](const Vec2& Y) { return (Y - X).norm() <= apart; };
    if (std::any_of(last.begin(), last.end(), near) || std::any_of(points.begin(), points.end(), near)) return;
    points.push_back(X);
  };
  for (size_t step = 0; step + 1 < history.size(); ++step) {
    if (k >= history[step].own.size()) continue;
    for (const Vec2& X : history[step].own[k].X)
      if (stuck_since(step, X)) add(m.own, c.stick_slip.X, X);
    for (const Vec2& X : history[step].other[k].X)
      if (stuck_since(step, X)) add(m.other, c.other_stick_slip.X, X);
  }
  return m;
}

}  // namespace hpcontact::model
