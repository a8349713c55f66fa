#include "physics/johnson_cook.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mpmcut {

namespace {
constexpr double kReturnTolerance = 1e-12;  // |r| <= tol * q_trial
constexpr int kMaxReturnIterations = 200;   // bisection alone needs ~60 to reach double precision

// Density of the solid of a particle that is solid plus crack gap, V = V_solid exp(gap) (update step 4). Most
// particles have no gap: no exp on the hot path for them.
double solid_density(double density, double gap) { return gap > 0.0 ? density * std::exp(gap) : density; }
double solid_density(const Particles& p, std::size_t i) {
  return solid_density(p.mass[i] / p.volume[i], p.crack_opening[i]);
}
}  // namespace

JohnsonCookMaterial::JohnsonCookMaterial(const MaterialParameters& params)
    : Material(params),
      flow_(params),
      eos_(params),
      damage_(params),
      G_(params.shear_modulus()),
      two_G_(2.0 * G_),
      three_G_(3.0 * G_),
      smoothing_time_(params.strain_rate_smoothing_time),
      taylor_quinney_(params.taylor_quinney),
      heat_per_work_(0.0),
      sure_elastic_q_(flow_.elastic_limit_at_room_temperature()),
      room_temperature_(params.room_temperature) {
  // Validated by Material (the parameter tables): for johnson_cook, specific_heat > 0.
  if (params.taylor_quinney > 0.0) heat_per_work_ = params.taylor_quinney / params.specific_heat;
}

JohnsonCookMaterial::ReturnMapping JohnsonCookMaterial::return_mapping(double q_tr, double eps0, double old_rate,
                                                                       double T0, double h, double dt) const {
  // rate(x) = rate_base + x * rate_slope, T(x) = T0 + h (q_tr - 3G x) x
  const double rate_slope = 1.0 / (smoothing_time_ + dt);
  const double rate_base = smoothing_time_ * old_rate * rate_slope;
  const double tol = kReturnTolerance * q_tr;

  ReturnMapping out;
  double lo = 0.0;                  // r(lo) > 0
  double hi = q_tr / three_G_;      // r(hi) = -sigma_y <= 0
  // Initial guess: last step's increment (exact in steady flow), else the perfectly plastic estimate.
  double x = old_rate * dt;
  if (!(x > 0.0 && x < hi)) x = 0.5 * hi;
  if (!(x > 0.0)) x = hi;
  for (int it = 1; it <= kMaxReturnIterations; ++it) {
    const double rate = rate_base + x * rate_slope;
    const double q = q_tr - three_G_ * x;
    const double T = T0 + h * q * x;
    const FlowStressValue f = flow_.evaluate(eps0 + x, rate, T);
    const double r = q - f.stress;
    out = {x, f.stress, rate, T, f.log_rate_ratio, it};
    if (std::abs(r) <= tol) break;
    if (r > 0.0) lo = x; else hi = x;
    const double dr =
        -three_G_ - f.d_strain - f.d_rate * rate_slope - f.d_temperature * h * (q_tr - 2.0 * three_G_ * x);
    double next = x - r / dr;  // a NaN (inf slope) fails the bracket test below
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == x) break;  // bracket collapsed to one double
    x = next;
  }
  return out;
}

ConstitutiveIncrement JohnsonCookMaterial::update(Particles& p, std::size_t i, const Mat2& L,
                                                  const StepContext& ctx) const {
  const double dt = ctx.dt;
  ConstitutiveIncrement inc;
  if (!(dt > 0.0)) return inc;

  // 1. Strain increment, plane strain: dEps = sym(L) dt, dEps_zz = 0; deviatoric part has
  //    de_zz = -dEps_v/3 != 0.
  const double exx = L(0, 0) * dt;
  const double eyy = L(1, 1) * dt;
  const double exy = 0.5 * (L(0, 1) + L(1, 0)) * dt;
  const double ev = exx + eyy;
  const double ev3 = ev / 3.0;

  // 2. Objective (Jaumann) rotation of the undamaged stress; the rotation keeps the trace.
  const PlaneStrainTensor rotated = jaumann_rotate(p.effective_stress[i], L, dt);
  const double old_pressure = -rotated.mean();
  PlaneStrainTensor s = rotated.plus_identity(old_pressure);

  const double volume = p.volume[i];
  const double density = p.mass[i] / volume;
  const double T0 = p.temperature[i];
  const double eps0 = p.plastic_strain[i];
  const double D0 = damage_.enabled() ? p.damage[i] : 0.0;
  const bool failed0 = damage_.failed(D0);

  // 3. Deviatoric predictor-corrector (radial return on the undamaged stress).
  double dep = 0.0;     // plastic strain increment
  double q = 0.0;       // final undamaged von Mises stress (= sigma_y when plastic)
  double T = T0;        // end-of-step temperature
  double rate = smoothed_rate(p.plastic_strain_rate[i], 0.0, dt);
  double log_rate = 0.0;
  bool log_rate_known = false;
  // The closed crack's slider (theory_materials.md §5.8): the cracked part D of a damaged particle, all of a failed
  // one, carries phi of the undamaged deviator, which a failed particle then keeps integrating. It needs the step's
  // start: phi0 of the rotated deviator.
  const bool crack_slider = damage_.has_crack_friction() && D0 > 0.0;
  const double cracked0 = failed0 ? 1.0 : D0;  // the slider's part of the particle
  const PlaneStrainTensor s_start = s;
  const double phi0 = crack_slider ? damage_.closed_crack_share(old_pressure, std::sqrt(1.5 * s.contract(s))) : 0.0;
  if ((failed0 && !crack_slider) || flow_.melted(T0)) {
    s = {};  // failed (without crack friction) or molten: no deviatoric stress, no plastic flow
  } else {
    s.xx += two_G_ * (exx - ev3);
    s.yy += two_G_ * (eyy - ev3);
    s.zz += two_G_ * (-ev3);
    s.xy += two_G_ * exy;
    const double q_tr = std::sqrt(1.5 * s.contract(s));
    q = q_tr;
    const bool surely_elastic = q_tr <= sure_elastic_q_ && T0 <= room_temperature_;
    if (!surely_elastic && q_tr > flow_.yield_stress(eps0, rate, T0)) {
      const double h = heat_per_work_ * (1.0 - D0) / density;
      const ReturnMapping rm = return_mapping(q_tr, eps0, p.plastic_strain_rate[i], T0, h, dt);
      dep = rm.plastic_increment;
      q = q_tr - three_G_ * dep;
      s = s * (q / q_tr);
      rate = rm.rate;
      T = rm.temperature;
      log_rate = rm.log_rate_ratio;
      log_rate_known = flow_.rate_dependent();
    }
  }

  // 4. Crack gap (theory_materials.md §5.3b). A particle whose crack has opened (step 5) is solid plus gap,
  //    V = V_solid exp(gap). Compression beyond zero pressure first closes the gap, at zero pressure, and only
  //    then compresses the solid; tension reopens a gap that has closed, at zero stress, up to the largest
  //    opening so far. Without it an opened particle (V >> V0) bears compression on its stretched volume
  //    after cap/K (~0.7 %) of closing: crack faces that push before they touch.
  const double gap0 = p.crack_opening[i];
  double gap = gap0;
  double gap_max = p.crack_opening_max[i];
  double ev_solid = ev;  // the solid's volumetric strain increment
  if (gap_max > 0.0) {
    const double rho_before = solid_density(density, gap0);
    const double trial = eos_.pressure(old_pressure, ev, rho_before, T);  // the solid takes all of ev
    const double K = eos_.bulk_modulus(rho_before);
    if (trial > 0.0) gap = std::max(gap0 - trial / K, 0.0);
    else if (trial < 0.0) gap = std::min(gap0 - trial / K, gap_max);
    ev_solid = ev - (gap - gap0);
  }
  double rho_solid = solid_density(density, gap);

  // 4b. Pressure from the EOS at the end-of-step density of the solid and temperature (+ bulk viscosity).
  double pressure = eos_.pressure(old_pressure, ev_solid, rho_solid, T);
  double viscous_pressure = 0.0;
  if (eos_.has_bulk_viscosity() && ev_solid < 0.0) {
    const double c = std::sqrt((eos_.bulk_modulus(rho_solid) + 4.0 / 3.0 * G_) / rho_solid);
    const double f = ctx.inertia_factor;  // mass scaling: damp the dynamics that are integrated
    viscous_pressure = eos_.bulk_viscosity(f * rho_solid, ev_solid / dt, ctx.cell_size, c / std::sqrt(f));
    inc.viscous_dissipation = viscous_pressure * (-ev_solid) * volume;
  }

  // 5. Tensile cut-off after initiation (mode I opening, theory_materials.md §5.5): once damage has
  //    initiated, the undamaged hydrostatic tension stays at or below sigma_y0, and the volumetric strain
  //    beyond it opens the crack and drives u_pl as plastic strain does. Without it, a band held laterally
  //    by its neighbours (isochoric flow cannot open it) stores ever more hydrostatic tension and its
  //    dissipation depends on the cell size.
  double opening = 0.0;              // volumetric strain turned into crack opening
  double opening_dissipation = 0.0;  // undamaged energy it dissipates, J/m^3
  if (damage_.enabled() && !failed0 && p.damage_initiation[i] >= 1.0) {
    const double cap = p.initiation_yield_stress[i];
    if (-pressure > cap) {
      const double K = eos_.bulk_modulus(rho_solid);
      // The solid's tension beyond the cap (the pressure is the solid's: past openings are in the gap, so a
      // total law p(rho) does not count them again).
      opening = (-pressure - cap) / K;
      // Work of the final (capped) stress through the opening, as sigma_y d(eps_p) for plastic flow,
      // plus, on the first capped step, the stored tension above the cap that initiation released.
      const double excess_old = std::max(-old_pressure - cap, 0.0);
      opening_dissipation = cap * opening + excess_old * excess_old / (2.0 * K);
      pressure = -cap;
      gap += opening;  // the opening is the crack's gap from now on
      gap_max = std::max(gap_max, gap);
      rho_solid = solid_density(density, gap);
    }
  }
  p.crack_opening[i] = gap;
  p.crack_opening_max[i] = gap_max;

  // 6. Damage: initiation and evolution on the undamaged state, then degradation.
  double D = D0;
  double before = dep, after = 0.0;  // plastic increment before / after initiation
  bool failed = failed0;
  if (damage_.enabled() && !failed0 && (dep > 0.0 || opening > 0.0)) {
    DamageState st{p.damage_initiation[i], D0, p.plastic_displacement[i], p.initiation_yield_stress[i],
                   p.fracture_energy[i]};
    // Hillerborg length: the cell size, stretched with the particle (J = V/V0). An opening band
    // thickens normal to the crack only, so L J is its current thickness and L J d(eps) its opening;
    // then each particle dissipates G_f V0/L whatever its stretch. In shear bands J ~ 1.
    const double band_length = ctx.cell_size * volume / p.initial_volume[i];
    // Plastic flow at a triaxiality at or below the cut-off (compression) neither advances initiation
    // nor softens: it is plastic work (theory_materials.md §5.7).
    const double eta = stress_triaxiality(pressure, q);
    if (dep > 0.0 && damage_.fracture_possible(eta)) {
      double eps_f = 0.0;
      if (st.initiation < 1.0) {
        if (!log_rate_known) log_rate = flow_.log_rate_ratio(rate);
        eps_f = damage_.failure_strain(eta, log_rate, flow_.homologous_temperature(T));
      }
      const DamageStep ds = damage_.advance(st, dep, eps_f, q, band_length, rate);
      before = ds.strain_before_initiation;
      after = ds.strain_after_initiation;
      failed = ds.failed;
    }
    if (opening > 0.0) failed = damage_.open(st, opening, band_length).failed || failed;
    p.damage_initiation[i] = st.initiation;
    p.damage[i] = st.damage;
    p.plastic_displacement[i] = st.plastic_displacement;
    p.initiation_yield_stress[i] = st.initiation_yield_stress;
    p.fracture_energy[i] = st.fracture_energy;
    D = st.damage;
  }

  // 7. Energy increments (theory_materials.md §6). Work of the intact part's stress through plastic flow:
  //    (1 - D0) sigma_y d(eps_p) V. Before initiation it is plastic work; after initiation it belongs to the fracture
  //    process (damage dissipation), together with the elastic energy released as D grows, Y dD V with
  //    Y = e s:s/(4G) + <-p>^2/(2K), e = 1 - phi^2 the part of the stored deviatoric energy the crack takes (§5.8).
  if (dep > 0.0) {
    const double work_density = (1.0 - D0) * q;  // per unit plastic strain and volume
    inc.plastic_work = work_density * before * volume;
    inc.damage_dissipation = work_density * after * volume;
    // Heat = chi x all plastic work (before and after initiation); it equals m c dT exactly.
    inc.heat = taylor_quinney_ * work_density * dep * volume;
  }
  inc.damage_dissipation += (1.0 - D0) * opening_dissipation * volume;  // crack opening: not heat
  const double phi = crack_slider ? damage_.closed_crack_share(pressure, q) : 0.0;
  if (crack_slider) {
    // The closed crack's Coulomb slider (§5.8), D0 phi s: its work through the step's deviatoric strain (trapezoid)
    // less what it stores, D0 phi^2 s:s/(4G), is friction: plastic work, all of it heat (D0 = 1 once failed).
    const PlaneStrainTensor de{exx - ev3, eyy - ev3, -ev3, exy};
    const double work = 0.5 * (s_start * phi0 + s * phi).contract(de);
    const double stored = (phi * phi * s.contract(s) - phi0 * phi0 * s_start.contract(s_start)) / (4.0 * G_);
    const double friction = cracked0 * (work - stored) * volume;
    inc.plastic_work += friction;
    inc.heat += friction;
    T += friction / (p.mass[i] * params_.specific_heat);
  }
  if (D > D0) {
    double Y = s.contract(s) / (4.0 * G_) * (1.0 - phi * phi);
    if (pressure < 0.0) Y += pressure * pressure / (2.0 * eos_.bulk_modulus(rho_solid));
    // At failure the rest of the stored deviatoric and tensile energy goes too: D jumps to 1 (the slider keeps its
    // phi^2 share).
    inc.damage_dissipation += Y * ((failed ? 1.0 : D) - D0) * volume;
  }
  if (failed && !damage_.has_crack_friction()) s = {};
  // Per particle, so that the crack length it stands for, damage_dissipation / G_f, can be summed
  // with each particle's own G_f (rate-dependent, theory_materials.md §5.6).
  if (inc.damage_dissipation != 0.0) p.damage_dissipation[i] += inc.damage_dissipation;

  // 8. Store the state: undamaged stress (no viscosity) for the next step, degraded stress for forces.
  p.effective_stress[i] = s.plus_identity(-pressure);
  p.stress[i] = degraded_stress(s, pressure + viscous_pressure, D, failed ? phi : deviator_share(D, phi), failed);
  p.plastic_strain[i] = eps0 + dep;
  p.plastic_strain_rate[i] = rate;
  p.temperature[i] = T;
  return inc;
}

double JohnsonCookMaterial::wave_speed(const Particles& p, std::size_t i) const {
  // Waves travel in the solid: an open crack's gap (step 4 of update) neither carries them nor makes the
  // particle lighter for them.
  const double density = solid_density(p, i);
  const double K = eos_.bulk_modulus(density);
  if (damage_.failed(damage_.enabled() ? p.damage[i] : 0.0) || flow_.melted(p.temperature[i])) {
    // No shear stiffness (but the closed crack's friction, §5.8). A failed particle that has opened up (V > V0)
    // carries no stress at all; it must not shorten the step through its low density, so use at least the
    // reference density.
    const double phi = flow_.melted(p.temperature[i]) ? 0.0 : closed_crack_share(p, i);
    return std::sqrt((K + phi * 4.0 / 3.0 * G_) / std::max(density, params_.density));
  }
  // A damaged particle is softer: its deviator carries (1 - D) G, and in tension (opened up,
  // density below the reference) its pressure (1 - D) K too. Without this, a damaged particle
  // that has opened up (J >> 1) shortens the step through its low density although it carries
  // almost no stress (seen in cuts: dt fell 4x).
  const double D = damage_.enabled() ? p.damage[i] : 0.0;
  const double bulk = density < params_.density ? (1.0 - D) * K : K;
  const double share = D > 0.0 ? deviator_share(D, closed_crack_share(p, i)) : 1.0;
  return std::sqrt((bulk + share * 4.0 / 3.0 * G_) / density);
}

double JohnsonCookMaterial::closed_crack_share(const Particles& p, std::size_t i) const {
  if (!damage_.has_crack_friction()) return 0.0;  // no stress needed: the hot path of most runs
  const PlaneStrainTensor& sigma = p.effective_stress[i];
  return damage_.closed_crack_share(-sigma.mean(), sigma.von_mises());
}

double JohnsonCookMaterial::elastic_energy(const Particles& p, std::size_t i) const {
  // Stored energy of the damaged solid, (1 - D) psi_dev + psi_vol with psi_vol unscaled in
  // compression: the energy whose release rate Y appears in the damage dissipation of update().
  const PlaneStrainTensor& sigma = p.effective_stress[i];
  const double pressure = -sigma.mean();
  const PlaneStrainTensor s = sigma.plus_identity(pressure);
  const double D = damage_.enabled() ? p.damage[i] : 0.0;
  const bool failed = damage_.failed(D);
  const double keep = failed ? 0.0 : 1.0 - D;
  const double s_s = s.contract(s);
  const double phi = D > 0.0 && damage_.has_crack_friction() ? damage_.closed_crack_share(pressure, std::sqrt(1.5 * s_s))
                                                              : 0.0;
  const double keep_dev = failed ? phi * phi : 1.0 - D * (1.0 - phi * phi);  // the slider stores D phi^2 (§5.8)
  const double K = eos_.bulk_modulus(solid_density(p, i));
  const double vol = pressure * pressure / (2.0 * K) * (pressure >= 0.0 ? 1.0 : keep);
  return p.volume[i] * (keep_dev * s_s / (4.0 * G_) + vol);
}

}  // namespace mpmcut
