// Does a shear band form the same way whatever its orientation to the grid? (issue 11, item 2; docs/
// theory_materials.md §10, "Where a band forms").
//
// Set-up: the sandwich of test_hillerborg_band_orientation.cpp without damage: a layer six cells thick (20 um
// cells) of Ti-6Al-4V with the TANH softening of Sima & Oezel 2010, adiabatic (no conduction), between two heavy,
// stiff elastic blocks that overhang its ends and are held to their velocities every step (the lower at rest, the
// upper sliding at v0 = gamma_dot H along the layer, gamma_dot = 1e5 1/s); the layer starts with the matching linear
// velocity profile. A seed strip one particle row thick just below its middle is 2 % weaker (A x 0.98). The
// homogeneous adiabatic response of the same material (material-point driver, simple shear) peaks at 781 MPa at
// gamma 0.50. Measured over the middle 40 % of the layer's length: the band's width (the plastic strain across
// the layer integrated over its peak, bins of half a cell) and, in the core (the middle half of the thickness), the
// mean shear stress s.sigma.n and the mean shear s.F.n. The core's shear, not the nominal one (slip / H), is what
// the homogeneous response is compared at: turned against the grid, the grid nodes the layer shares with the blocks,
// a staircase of them along each side, hold about a third of its thickness still, and the core shears 1.5 times
// faster than nominal (on the particle lattice turned with the sandwich as well: it is the nodes, not the particles).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "../support/scene_builders.hpp"
#include "../support/ti64_parameters.hpp"
#include "physics/johnson_cook.hpp"
#include "physics/material_point_driver.hpp"
#include "solver/simulation.hpp"

using namespace mpmcut;
using namespace mpmcut::testing;

namespace {

constexpr double kCell = 20e-6, kShearRate = 1e5, kSeedWeakening = 0.98;
constexpr double kLength = 50 * kCell, kThickness = 6 * kCell;

MaterialParameters layer_material(const char* name, double strength_factor) {
  MaterialParameters m = ti64_sima_ozel_2010();
  m.name = name;
  m.jc_A *= strength_factor;
  return m;
}

struct Sample {
  double gamma = 0.0;         // nominal shear (slip / H), -
  double core_gamma = 0.0;    // mean shear s.F.n of the window's core, -
  double shear_stress = 0.0;  // mean s.sigma.n of the window's core, Pa
  double band_width = 0.0;    // plastic strain across the layer over its peak, m
  double band_centre = 0.0;   // where that peak is, from the anchor across the layer (the seed row at H/2 - h/4), m
};

// The homogeneous adiabatic shear stress at the nominal shear gamma (material-point driver, simple shear).
std::vector<Sample> homogeneous_response(double gamma_end) {
  const MaterialParameters m = layer_material("layer", 1.0);
  const JohnsonCookMaterial jc(m);
  MaterialPointDriver driver(jc, 298.0, kCell);
  Mat2 L;
  L << 0.0, kShearRate, 0.0, 0.0;
  const int n = 20000;
  std::vector<Sample> out;
  for (const MaterialPointRecord& r : driver.run(L, gamma_end / kShearRate / n, n))
    out.push_back({r.time * kShearRate, r.time * kShearRate, r.stress.xy, 0.0, 0.0});
  return out;
}

// The curve's shear stress at the shear gamma (linear between samples; its `gamma` is the abscissa).
double interpolate(const std::vector<Sample>& curve, double gamma) {
  for (std::size_t k = 1; k < curve.size(); ++k)
    if (curve[k].gamma >= gamma) {
      const double w = (gamma - curve[k - 1].gamma) / (curve[k].gamma - curve[k - 1].gamma);
      return (1 - w) * curve[k - 1].shear_stress + w * curve[k].shear_stress;
    }
  return curve.back().shear_stress;
}

// The sandwich turned by theta_deg against the grid, sheared until the nominal shear reaches gamma_end or the core's
// reaches core_gamma_end; a sample every 0.02 of nominal shear.
std::vector<Sample> sheared_layer(double theta_deg, VolumetricAverage average, double gamma_end,
                                  double core_gamma_end = 1e9, bool turned_lattice = false) {
  const double theta = theta_deg * std::numbers::pi / 180.0, h = kCell, L = kLength, H = kThickness;
  const double v0 = kShearRate * H, d = h / 2;
  const Vec2 s(std::cos(theta), std::sin(theta)), n(-std::sin(theta), std::cos(theta));
  // The blocks overhang the layer's ends by E, more than the slip, so that the layer's ends stay between them.
  const double E = 15 * h, span = L + 2 * E;
  const Vec2 o = Vec2(3 * h + (H + 4 * h) * std::sin(theta), 3 * h) + E * s;
  Scene scene;
  scene.grid = {h, Vec2(0, 0), Vec2(span * std::cos(theta) + H + 20 * h, span * std::sin(theta) + H + 20 * h)};
  scene.solver.cfl = 0.4;
  scene.solver.volumetric_average = average;
  scene.materials.push_back(layer_material("layer", 1.0));
  scene.materials.push_back(layer_material("seed", kSeedWeakening));
  scene.materials.push_back(elastic_material("heavy", 113.8e9 * 1e4, 0.342, 4430.0 * 1e4));
  const double mid = 0.5 * H;
  scene.bodies.push_back(inclined_strip("anchor", "heavy", -2 * h, 0.0, span, theta, o - E * s, Vec2::Zero()));
  // The seed's sides lie between particle rows (a whole number of spacings from o): it holds the row just below the
  // middle (sides on a row would leave the row to whichever strip round-off gives it: along the grid, none).
  scene.bodies.push_back(inclined_strip("lower layer", "layer", 0.0, mid - d, L, theta, o, Vec2::Zero()));
  scene.bodies.push_back(inclined_strip("seed", "seed", mid - d, mid, L, theta, o, Vec2::Zero()));
  scene.bodies.push_back(inclined_strip("upper layer", "layer", mid, H, L, theta, o, Vec2::Zero()));
  scene.bodies.push_back(inclined_strip("driver", "heavy", H, H + 2 * h, span, theta, o - E * s, v0 * s));
  if (turned_lattice) seed_on_turned_lattice(scene, theta_deg, o);
  Simulation sim(scene);
  auto& P = sim.particles();
  const int kHeavy = 2;
  for (std::size_t p = 0; p < P.size(); ++p)
    if (P.material[p] != kHeavy) P.velocity[p] = v0 * std::clamp((P.position[p] - o).dot(n) / H, 0.0, 1.0) * s;
  // The blocks' mean positions along s: the nominal shear is their relative slip over H.
  auto slip = [&] {
    double upper = 0, lower = 0, mu = 0, ml = 0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      if (P.material[p] != kHeavy) continue;
      const double along = P.position[p].dot(s);
      if ((P.position[p] - o).dot(n) > mid) upper += P.mass[p] * along, mu += P.mass[p];
      else lower += P.mass[p] * along, ml += P.mass[p];
    }
    return upper / mu - lower / ml;
  };
  const double slip0 = slip();
  const int bins = static_cast<int>(std::round(2 * H / h));
  std::vector<Sample> out;
  double next = 0.0;
  for (;;) {
    const double gamma = (slip() - slip0) / H;
    if (gamma >= next) {
      // The window: the middle 40 % of the layer's length, moving with its middle (half the slip), so that it
      // stays 9 cells from either end of the layer's halves (the solver reorders particles: no fixed set). Its core,
      // the middle half of the thickness, is away from the blocks: where a layer turned against the grid meets them,
      // nodes shared in a staircase hold some of its particles still, so its deforming part is thinner than H.
      double tau = 0, shear = 0, core_volume = 0;
      std::vector<double> strain(bins, 0.0), weight(bins, 0.0);
      for (std::size_t p = 0; p < P.size(); ++p) {
        if (P.material[p] == kHeavy) continue;
        const double along = (P.position[p] - o).dot(s) - 0.5 * gamma * H, across = (P.position[p] - o).dot(n);
        if (along < 0.3 * L || along > 0.7 * L) continue;
        const int b = std::clamp(static_cast<int>(across / H * bins), 0, bins - 1);
        strain[b] += P.plastic_strain[p] * P.volume[p];
        weight[b] += P.volume[p];
        if (std::abs(across - mid) > 0.25 * H) continue;
        tau += s.dot(P.stress[p].in_plane() * n) * P.volume[p];
        shear += s.dot(P.deformation_gradient[p] * n) * P.volume[p];  // F = I + gamma s n^T in simple shear
        core_volume += P.volume[p];
      }
      double integral = 0, peak = 0, centre = mid;
      for (int b = 0; b < bins; ++b) {
        const double e = weight[b] > 0 ? strain[b] / weight[b] : 0.0;
        integral += e * H / bins;
        if (e > peak) peak = e, centre = (b + 0.5) * H / bins;
      }
      out.push_back({gamma, shear / core_volume, tau / core_volume, peak > 0 ? integral / peak : H, centre});
      next += 0.02;
    }
    if (gamma >= gamma_end || (!out.empty() && out.back().core_gamma >= core_gamma_end)) break;
    sim.step();
    // The blocks are held to their velocities (their mass, 1e4 times the layer's, makes the nodes they share with
    // it follow): the slip rate stays v0 while the layer's stress peaks and falls.
    for (std::size_t p = 0; p < P.size(); ++p)
      if (P.material[p] == kHeavy) P.velocity[p] = (P.position[p] - o).dot(n) > mid ? Vec2(v0 * s) : Vec2::Zero();
  }
  return out;
}

// The layer's largest shear stress (Pa) in a run.
double peak_stress(const std::vector<Sample>& c) {
  double peak = 0.0;
  for (const Sample& x : c) peak = std::max(peak, x.shear_stress);
  return peak;
}

void print_run(const char* what, double theta, VolumetricAverage average, const std::vector<Sample>& c,
               const std::vector<Sample>& homogeneous) {
  const Sample& e = c.back();
  std::printf("%s, %.1f deg to the grid, volumetric average %s: peak %.1f MPa; at nominal shear %.2f (core %.2f) "
              "%.1f MPa (homogeneous %.1f), band %.1f um wide at %.0f um of %.0f\n",
              what, theta, average == VolumetricAverage::Nodal ? "nodal" : "off", peak_stress(c) / 1e6, e.gamma,
              e.core_gamma, e.shear_stress / 1e6, interpolate(homogeneous, e.core_gamma) / 1e6, e.band_width * 1e6,
              e.band_centre * 1e6, kThickness * 1e6);
}

}  // namespace

// Before the peak the core is sheared homogeneously: its shear stress is the material point's at the same shear, at
// every orientation, with and without the nodal volumetric average, on the grid's particle lattice and on the one
// turned with the sandwich (largest difference measured 2.45 %, off at 22.5 deg on the grid's lattice; 0.73 % there
// on the turned one; the peak itself 781 MPa at gamma 0.50). Without the adiabatic heating it would be 7 % higher at
// gamma 0.4 than with it; with volumetric locking in the turned layer, higher too.
TEST(ShearBandOnset, BeforeItsPeakTheLayerFollowsTheHomogeneousAdiabaticResponseAtEveryOrientation) {
  const std::vector<Sample> homogeneous = homogeneous_response(1.0);
  for (bool turned_lattice : {false, true})
    for (VolumetricAverage average : {VolumetricAverage::Off, VolumetricAverage::Nodal})
      for (double theta : {0.0, 22.5, 45.0}) {
        if (turned_lattice && theta == 0.0) continue;  // the same lattice
        const std::vector<Sample> c = sheared_layer(theta, average, 2.0, 0.42, turned_lattice);
        print_run(turned_lattice ? "before the peak, turned lattice" : "before the peak", theta, average, c,
                  homogeneous);
        int compared = 0;
        for (const Sample& x : c)
          if (x.core_gamma > 0.1 && x.core_gamma < 0.4) {
            EXPECT_NEAR(x.shear_stress / interpolate(homogeneous, x.core_gamma), 1.0, 0.03)
                << theta << " deg, core shear " << x.core_gamma;
            ++compared;
          }
        EXPECT_GE(compared, 8) << theta;
      }
}

// Along the grid, past the peak, the layer localises into a band: at a nominal shear of 2 its shear stress is 78 %
// of the homogeneous response's at the core's mean shear (242 against 312 MPa; the band's own shear is higher), and
// the plastic strain across the layer is concentrated in 28 um of its 120 (1.4 cells, next to the seed row).
TEST(ShearBandOnset, AlongTheGridTheLayerLocalisesIntoABandPastItsPeak) {
  const std::vector<Sample> homogeneous = homogeneous_response(4.0);  // beyond the core's shear (3.4)
  const std::vector<Sample> c = sheared_layer(0.0, VolumetricAverage::Off, 2.0);
  print_run("localised", 0.0, VolumetricAverage::Off, c, homogeneous);
  EXPECT_NEAR(peak_stress(c) / peak_stress(homogeneous), 1.0, 0.02);
  EXPECT_LT(c.back().shear_stress, 0.85 * interpolate(homogeneous, c.back().core_gamma));
  EXPECT_LT(c.back().band_width, 0.35 * kThickness);
}

// Turned against the grid the band should be as narrow and soften as fast. It is not (fails today; run with
// --gtest_also_run_disabled_tests): at a nominal shear of 2, 48 um wide and 348 MPa at 22.5 deg, 37 um and 207 MPa
// at 45 deg, against 28 um and 242 MPa along the grid (off); on the particle lattice turned with the sandwich (no
// stepped sides) 48 um and 422 MPa, 34 um and 399 MPa: turned against the grid a band softens slower, and the
// steps of the grid's lattice help it at 45 deg; docs/theory_materials.md §10, "Where a band forms".
TEST(ShearBandOnset, DISABLED_ABandTurnedAgainstTheGridIsAsNarrowAsOneAlongIt) {
  const std::vector<Sample> homogeneous = homogeneous_response(4.0);
  const std::vector<Sample> aligned = sheared_layer(0.0, VolumetricAverage::Off, 2.0);
  for (bool turned_lattice : {false, true})
    for (double theta : {22.5, 45.0}) {
      const std::vector<Sample> c = sheared_layer(theta, VolumetricAverage::Off, 2.0, 1e9, turned_lattice);
      print_run(turned_lattice ? "turned, turned lattice" : "turned", theta, VolumetricAverage::Off, c, homogeneous);
      EXPECT_NEAR(c.back().band_width / aligned.back().band_width, 1.0, 0.2) << theta << " " << turned_lattice;
      EXPECT_NEAR(c.back().shear_stress / aligned.back().shear_stress, 1.0, 0.2) << theta << " " << turned_lattice;
    }
}

