#pragma once
// A consistent nodal average of the volumetric strain rate, against volumetric locking (docs/solver.md,
// "Volumetric averaging"; [solver] volumetric_average = "nodal").
//
// Why: J2 plastic flow is isochoric, and a particle's own velocity gradient cannot keep tr L = 0 along a band that
// runs at an angle to the grid without also straining across it: the band locks, widens to two or three cells and
// dissipates several times G_f (docs/theory_materials.md §10). Averaging the volumetric rate over the nodes around a
// particle frees it: the B-bar idea
// [Hughes1980], in MPM as in [CoombsEtAl2018].
//
// Rate: d_n = sum_q S_qn m_q tr L_q / M_n with M_n = sum_q S_qn m_q, then per particle dbar_p = sum_n S_pn d_n and
// L_p <- L_p + (dbar_p - tr L_p) I / 2 (the in-plane trace becomes dbar_p; the deviatoric part is untouched).
// Force: the in-plane mean stress s_p = (sigma_xx + sigma_yy)/2 of the internal force is replaced by
// sbar_p = (m_p / V_p) sum_n S_pn pi_n / M_n, pi_n = sum_q S_qn V_q s_q: the transpose of the same projection, so
// that the nodal forces do the work sum_p V_p s_p dbar_p that the constitutive update books (without it the energy
// balance opens by tens of per cent). A uniform rate or mean stress is reproduced exactly (partition of unity).
// Weights are the true masses, so mass scaling does not change the average. Both scatters run in the P2G strips.
#include <span>
#include <vector>

#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/shape_functions.hpp"
#include "core/strip_colouring.hpp"

namespace mpmcut {

class NodalVolumetricAverage {
 public:
  // Before P2G (the colouring bucketed for this step's positions): the nodal mean stress pi_n / M_n and the node
  // masses M_n that the rate average of the same step reuses (positions do not change in between).
  void project_mean_stress(const Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                           const StripColouring& colouring, bool parallel);
  // pi_n / M_n per node, Pa m^3/kg: P2G's mean stress of particle p is (m_p / V_p) sum_n S_pn of this.
  std::span<const double> node_mean_stress() const { return node_mean_stress_; }

  // After the velocity gradients of this step: replaces each particle's volumetric rate by the nodal average.
  void average_volumetric_rates(Particles& particles, const Grid& grid, std::span<const ShapeFunction> body_shapes,
                                const StripColouring& colouring, bool parallel);

 private:
  std::vector<double> node_mass_;         // M_n = sum S m, true mass, kg/m
  std::vector<double> node_mean_stress_;  // pi_n / M_n, Pa m^3/kg
  std::vector<double> node_rate_;         // sum S m tr L / M_n, 1/s
};

}  // namespace mpmcut
