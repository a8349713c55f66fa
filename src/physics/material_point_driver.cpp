#include "physics/material_point_driver.hpp"

#include <cmath>
#include <stdexcept>

namespace mpmcut {

MaterialPointDriver::MaterialPointDriver(const Material& material, double temperature_K, double cell_size_m)
    : material_(material), cell_size_(cell_size_m) {
  const double V0 = 1.0;
  particles_.add(Vec2::Zero(), Vec2::Zero(), material.parameters().density * V0, V0, temperature_K, 0, 0);
  MaterialPointRecord r;
  static_cast<ParticleRow&>(r) = particles_.row(0);
  r.density = material.parameters().density;
  history_.push_back(r);
}

ConstitutiveIncrement MaterialPointDriver::advance(Particles& p, const Mat2& L, double dt) const {
  advance_deformation(p, 0, L, dt);
  p.velocity_gradient[0] = L;
  return material_.update(p, 0, L, StepContext{dt, cell_size_});
}

const MaterialPointRecord& MaterialPointDriver::record(const Mat2& L, double dt, const ConstitutiveIncrement& inc) {
  const MaterialPointRecord& prev = history_.back();
  MaterialPointRecord r;
  static_cast<ParticleRow&>(r) = particles_.row(0);
  r.step = prev.step + 1;
  r.time = prev.time + dt;
  r.velocity_gradient = L;
  r.density = particles_.mass[0] / particles_.volume[0];
  r.increment = inc;
  r.cumulative = prev.cumulative;
  r.cumulative.plastic_work += inc.plastic_work;
  r.cumulative.heat += inc.heat;
  r.cumulative.damage_dissipation += inc.damage_dissipation;
  r.cumulative.viscous_dissipation += inc.viscous_dissipation;
  r.elastic_energy = material_.elastic_energy(particles_, 0);
  history_.push_back(r);
  return history_.back();
}

MaterialPointRecord MaterialPointDriver::step(const Mat2& L, double dt) {
  const ConstitutiveIncrement inc = advance(particles_, L, dt);
  return record(L, dt, inc);
}

const std::vector<MaterialPointRecord>& MaterialPointDriver::run(const Mat2& L, double dt, long steps) {
  history_.reserve(history_.size() + static_cast<std::size_t>(steps));
  for (long k = 0; k < steps; ++k) step(L, dt);
  return history_;
}

// Finds L_yy with residual(particle after the step) = 0 by bracketing and the Illinois variant of
// regula falsi; residual is assumed to grow with L_yy locally (more stretch in y: more tension).
template <class Residual>
MaterialPointRecord MaterialPointDriver::step_controlled(const Mat2& L, double dt, Residual residual,
                                                                double tolerance) {
  Particles trial;
  ConstitutiveIncrement inc;
  auto eval = [&](double a) {
    trial = particles_;
    Mat2 La = L;
    La(1, 1) = a;
    inc = advance(trial, La, dt);
    return residual(trial);
  };
  double scale = L.cwiseAbs().maxCoeff();
  if (!(scale > 0.0)) scale = 1.0;
  double a0 = have_controlled_lyy_ ? controlled_lyy_ : L(1, 1);
  double f0 = eval(a0);
  double best_a = a0, best_f = f0;
  if (std::abs(f0) > tolerance) {
    // Expand a bracket downhill.
    double step = 1e-3 * scale;
    double a1 = a0 - (f0 > 0.0 ? step : -step);
    double f1 = eval(a1);
    int expansions = 0;
    while (f0 * f1 > 0.0) {
      if (++expansions > 200) throw std::runtime_error("MaterialPointDriver: no bracket for the controlled L_yy");
      step *= 2.0;
      if (std::abs(f1) > std::abs(f0)) {  // went uphill: turn around
        a1 = a0 + (a1 - a0) * -1.0;
      } else {
        a0 = a1;
        f0 = f1;
        a1 = a0 - (f0 > 0.0 ? step : -step);
      }
      f1 = eval(a1);
    }
    // Illinois iterations on [a0, a1].
    double fa = f0, fb = f1, a = a0, b = a1;
    int side = 0;
    best_a = std::abs(fa) < std::abs(fb) ? a : b;
    best_f = std::abs(fa) < std::abs(fb) ? fa : fb;
    for (int it = 0; it < 300 && std::abs(best_f) > tolerance; ++it) {
      const double c = (fa * b - fb * a) / (fa - fb);
      const double fc = eval(c);
      if (std::abs(fc) < std::abs(best_f)) {
        best_a = c;
        best_f = fc;
      }
      if (fc * fb > 0.0) {
        b = c;
        fb = fc;
        if (side == -1) fa *= 0.5;
        side = -1;
      } else {
        a = c;
        fa = fc;
        if (side == 1) fb *= 0.5;
        side = 1;
      }
      if (std::abs(b - a) <= 1e-15 * (std::abs(a) + std::abs(b))) break;
    }
  }
  eval(best_a);  // the state at the best L_yy becomes the new state
  particles_ = trial;
  controlled_lyy_ = best_a;
  have_controlled_lyy_ = true;
  Mat2 La = L;
  La(1, 1) = best_a;
  return record(La, dt, inc);
}

MaterialPointRecord MaterialPointDriver::step_free_yy(const Mat2& L, double dt) {
  const double stress_scale = material_.parameters().youngs_modulus;
  return step_controlled(L, dt, [&](const Particles& p) { return p.stress[0].yy / stress_scale; }, 1e-16);
}

MaterialPointRecord MaterialPointDriver::step_with_triaxiality(const Mat2& L, double dt, double eta) {
  return step_controlled(
      L, dt,
      [&](const Particles& p) {
        const PlaneStrainTensor& s = p.stress[0];
        const double q = s.von_mises();
        return q > 0.0 ? -(-s.mean()) / q - eta : s.mean();  // eta = -p/q, p = -mean
      },
      1e-13);
}

}  // namespace mpmcut
