#pragma once
// How far a result is from its grid-converged value: Richardson extrapolation from three grids with the
// observed order of convergence and the fine-grid convergence index (GCI), as in the procedure of
// Celik et al. (2008) for possibly unequal refinement ratios, after Roache's GCI ([Celik2008],
// [Roache1998] in docs/references.md).
// A cut's mean force at three cell sizes gives the observed order p, the extrapolated (h -> 0) force, and
// the GCI: an error band around the finest result with a safety factor of 1.25.
#include <optional>
#include <string>

namespace mpmcut {

// The three-grid estimate. Grids: h1 < h2 < h3 (finest first), results phi1, phi2, phi3.
struct GridConvergenceEstimate {
  // "monotonic": the changes phi3 -> phi2 -> phi1 have one sign and shrink, p > 0 (extrapolation applies);
  // "oscillatory": they change sign (no order or extrapolation; the band is half the range of the three);
  // "not shrinking": they have one sign but do not shrink (no order, no band);
  // "converged": phi1 = phi2 = phi3.
  std::string behaviour;
  std::optional<double> observed_order;               // p
  std::optional<double> extrapolated;                 // phi_ext21, the h -> 0 estimate
  double approximate_relative_error = 0.0;            // e_a21 = |phi1 - phi2| / |phi1|
  std::optional<double> extrapolated_relative_error;  // e_ext21 = |phi_ext21 - phi1| / |phi_ext21|
  // GCI_fine21 = 1.25 e_a21 / (r21^p - 1), a fraction of phi1 (monotonic); oscillatory: half the range of
  // the three results over |phi1|.
  std::optional<double> gci_fine;
  // The observed order lies in [0.5, 3]: the grids are plausibly in the asymptotic range, where the
  // extrapolation and the GCI mean what they say. Outside it (a far-from-asymptotic p makes the
  // extrapolation run away) they are indicative only.
  bool order_plausible = false;
};

// Throws std::invalid_argument unless 0 < h1 < h2 < h3 and every value is finite.
GridConvergenceEstimate three_grid_convergence(double h1, double phi1, double h2, double phi2, double h3, double phi3);

}  // namespace mpmcut
