#include "analysis/grid_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpmcut {

namespace {

constexpr double kSafetyFactor = 1.25;  // Roache's factor for three or more grids
constexpr double kMaxOrder = 20.0;      // a search bound far above any order a grid method shows
constexpr double kPlausibleOrderMin = 0.5, kPlausibleOrderMax = 3.0;  // about the orders of MPM (1 to 2)

}  // namespace

GridConvergenceEstimate three_grid_convergence(double h1, double phi1, double h2, double phi2, double h3, double phi3) {
  for (double x : {h1, phi1, h2, phi2, h3, phi3})
    if (!std::isfinite(x)) throw std::invalid_argument("grid convergence: a cell size or result is not finite");
  if (!(h1 > 0.0 && h1 < h2 && h2 < h3))
    throw std::invalid_argument("grid convergence: cell sizes must satisfy 0 < h1 < h2 < h3");
  GridConvergenceEstimate e;
  const double e21 = phi2 - phi1, e32 = phi3 - phi2;  // Celik et al.: epsilon_21 and epsilon_32
  e.approximate_relative_error = phi1 != 0.0 ? std::abs(e21 / phi1) : std::abs(e21);
  if (e21 == 0.0 && e32 == 0.0) {
    e.behaviour = "converged";
    e.gci_fine = 0.0;
    e.extrapolated = phi1;
    e.extrapolated_relative_error = 0.0;
    return e;
  }
  const double scale = std::max({std::abs(phi1), std::abs(phi2), std::abs(phi3)});
  if (e21 * e32 < 0.0 || e21 == 0.0 || e32 == 0.0) {
    // Oscillatory (or stalled on one pair): Richardson's error model does not hold; the spread is the band.
    e.behaviour = "oscillatory";
    const double range = std::max({phi1, phi2, phi3}) - std::min({phi1, phi2, phi3});
    e.gci_fine = 0.5 * range / (phi1 != 0.0 ? std::abs(phi1) : scale);
    return e;
  }
  const double r21 = h2 / h1, r32 = h3 / h2;
  // p solves p ln r21 = ln|e32 / e21| + ln((r21^p - 1) / (r32^p - 1)) (monotonic, s = 1). The right side
  // minus the left falls with p: bisection on (0, kMaxOrder]; no root there means the changes do not
  // shrink fast enough for any positive order: diverging.
  const double ratio = std::log(std::abs(e32 / e21));
  const auto residual = [&](double p) {
    return ratio + std::log((std::pow(r21, p) - 1.0) / (std::pow(r32, p) - 1.0)) - p * std::log(r21);
  };
  double lo = 1e-6, hi = kMaxOrder;
  if (!(residual(lo) > 0.0 && residual(hi) < 0.0)) {
    e.behaviour = "not shrinking";
    return e;
  }
  for (int k = 0; k < 200 && hi - lo > 1e-12; ++k) {
    const double mid = 0.5 * (lo + hi);
    (residual(mid) > 0.0 ? lo : hi) = mid;
  }
  const double p = 0.5 * (lo + hi);
  const double rp = std::pow(r21, p);
  e.behaviour = "monotonic";
  e.observed_order = p;
  e.extrapolated = (rp * phi1 - phi2) / (rp - 1.0);
  if (*e.extrapolated != 0.0) e.extrapolated_relative_error = std::abs((*e.extrapolated - phi1) / *e.extrapolated);
  e.gci_fine = kSafetyFactor * e.approximate_relative_error / (rp - 1.0);
  e.order_plausible = p >= kPlausibleOrderMin && p <= kPlausibleOrderMax;
  return e;
}

}  // namespace mpmcut
