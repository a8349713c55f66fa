#include "physics/elastic.hpp"

namespace mpmcut {

ConstitutiveIncrement LinearElastic::update(Particles& p, std::size_t i, const Mat2& L,
                                            const StepContext& ctx) const {
  const double K = params_.bulk_modulus();
  const double G = params_.shear_modulus();
  const double dt = ctx.dt;
  // Strain increment dEps = sym(L) dt, with dEps_zz = 0 (plane strain).
  const double exx = L(0, 0) * dt;
  const double eyy = L(1, 1) * dt;
  const double exy = 0.5 * (L(0, 1) + L(1, 0)) * dt;
  const double ev = exx + eyy;
  const double lambda = K - 2.0 * G / 3.0;

  PlaneStrainTensor s = jaumann_rotate(p.effective_stress[i], L, dt);
  s.xx += lambda * ev + 2.0 * G * exx;
  s.yy += lambda * ev + 2.0 * G * eyy;
  s.zz += lambda * ev;
  s.xy += 2.0 * G * exy;
  p.effective_stress[i] = s;
  p.stress[i] = s;
  return {};
}

}  // namespace mpmcut
