// The nodal average of the volumetric rate and its force-side transpose (solver/volumetric_average.hpp): a uniform
// volumetric rate and a uniform mean stress come back unchanged (partition of unity), the deviatoric part of the
// velocity gradient is never touched, and the two projections are transposes of each other, so that the nodal forces
// do exactly the volumetric work the constitutive update books with the averaged rate (the energy balance). The
// particles are jittered off their seeding lattice and carry different masses and volumes, so that none of this
// holds by symmetry alone.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/stencil.hpp"
#include "solver/scene.hpp"
#include "solver/seeding.hpp"
#include "solver/volumetric_average.hpp"
#include "../support/scene_builders.hpp"

using namespace mpmcut;

namespace {

struct Cloud {
  Grid grid;
  Particles particles;
  std::vector<ShapeFunction> shapes;
  StripColouring colouring;
};

// A 12 x 8 cell block of particles (2 per cell direction) on 1 mm cells, jittered by up to a fifth of their spacing,
// with masses and volumes scattered by +-30 % (non-uniform density) when `uniform_density` is false.
Cloud jittered_block(bool uniform_density, unsigned seed = 3) {
  const double h = 1e-3;
  Scene scene;
  scene.grid = {h, Vec2(0, 0), Vec2(16 * h, 12 * h)};
  scene.materials.push_back(mpmcut::testing::elastic_material("m", 1e9, 0.3, 1000.0));
  scene.bodies.push_back(mpmcut::testing::rectangle_body("block", "m", Vec2(2 * h, 2 * h), Vec2(14 * h, 10 * h), 2));
  Cloud c;
  c.grid.build(scene.grid);
  seed_particles(scene, c.grid, c.particles);
  c.shapes.emplace_back(ShapeFunctionKind::UGimp, h, 2);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.1 * h, 0.1 * h), scatter(0.7, 1.3);
  Particles& P = c.particles;
  for (std::size_t p = 0; p < P.size(); ++p) {
    P.position[p] += Vec2(jitter(rng), jitter(rng));
    if (!uniform_density) {
      P.mass[p] *= scatter(rng);
      P.volume[p] *= scatter(rng);
    }
  }
  c.colouring.bucket(P, c.grid, c.shapes);
  return c;
}

// The mean stress P2G's internal force uses for particle p: (m_p / V_p) sum_n S_pn node_mean_stress[n].
double projected_mean_stress(const Cloud& c, const NodalVolumetricAverage& a, std::size_t p) {
  double sum = 0.0;
  for_each_stencil_weight(c.grid, particle_stencil(c.grid, c.shapes, c.particles, p),
                          [&](int n, double w) { sum += w * a.node_mean_stress()[n]; });
  return c.particles.mass[p] / c.particles.volume[p] * sum;
}

TEST(NodalVolumetricAverage, AUniformRateAndAUniformMeanStressComeBackUnchanged) {
  Cloud c = jittered_block(true);
  Particles& P = c.particles;
  Mat2 L;
  L << 3.0e3, -1.5e3, 0.7e3, -1.2e3;  // 1/s, tr L = 1.8e3
  for (std::size_t p = 0; p < P.size(); ++p) {
    P.velocity_gradient[p] = L;
    P.stress[p] = {4.0e8, -1.0e8, 0.9e8, 0.5e8};  // xx, yy, zz, xy: in-plane mean 1.5e8 Pa
  }
  NodalVolumetricAverage a;
  a.project_mean_stress(P, c.grid, c.shapes, c.colouring, false);
  a.average_volumetric_rates(P, c.grid, c.shapes, c.colouring, false);
  for (std::size_t p = 0; p < P.size(); ++p) {
    EXPECT_NEAR((P.velocity_gradient[p] - L).norm(), 0.0, 1e-9 * L.norm()) << p;
    EXPECT_NEAR(projected_mean_stress(c, a, p), 1.5e8, 1e-9 * 1.5e8) << p;
  }
}

TEST(NodalVolumetricAverage, OnlyTheVolumetricRateChangesAndItIsSmoothed) {
  Cloud c = jittered_block(false);
  Particles& P = c.particles;
  std::mt19937 rng(11);
  std::normal_distribution<double> N(0.0, 1e3);
  std::vector<Mat2> before(P.size());
  double spread_before = 0.0, spread_after = 0.0, mean = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    P.velocity_gradient[p] << N(rng), N(rng), N(rng), N(rng);
    before[p] = P.velocity_gradient[p];
    mean += before[p].trace() / P.size();
  }
  NodalVolumetricAverage a;
  a.project_mean_stress(P, c.grid, c.shapes, c.colouring, false);
  a.average_volumetric_rates(P, c.grid, c.shapes, c.colouring, false);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Mat2 dev_before = before[p] - 0.5 * before[p].trace() * Mat2::Identity();
    const Mat2 dev_after = P.velocity_gradient[p] - 0.5 * P.velocity_gradient[p].trace() * Mat2::Identity();
    EXPECT_NEAR((dev_after - dev_before).norm(), 0.0, 1e-9 * before[p].norm()) << p;
    spread_before += std::pow(before[p].trace() - mean, 2);
    spread_after += std::pow(P.velocity_gradient[p].trace() - mean, 2);
  }
  // An average over about three cells of white noise: its spread falls several times.
  EXPECT_LT(spread_after, 0.25 * spread_before);
}

// sum_p V_p s_p dbar_p (the volumetric work the materials book with the averaged rate) equals sum_p V_p sbar_p d_p
// (the work of the nodal forces built from the projected mean stress), for any fields: the projections are
// transposes.
TEST(NodalVolumetricAverage, TheForceProjectionIsTheTransposeOfTheRateAverage) {
  for (unsigned seed : {1u, 2u, 3u}) {
    Cloud c = jittered_block(false, seed);
    Particles& P = c.particles;
    std::mt19937 rng(seed + 100);
    std::normal_distribution<double> N(0.0, 1.0);
    std::vector<double> rate(P.size()), mean_stress(P.size());
    for (std::size_t p = 0; p < P.size(); ++p) {
      rate[p] = 1e3 * N(rng);
      mean_stress[p] = 1e8 * N(rng);
      const double deviatoric = 1e8 * N(rng);
      P.stress[p] = {mean_stress[p] + deviatoric, mean_stress[p] - deviatoric, 0.3e8 * N(rng), 1e8 * N(rng)};
      P.velocity_gradient[p] << 0.5 * rate[p] + 1e3 * N(rng), 1e3 * N(rng), 1e3 * N(rng), 0.0;
      P.velocity_gradient[p](1, 1) = rate[p] - P.velocity_gradient[p](0, 0);
    }
    NodalVolumetricAverage a;
    a.project_mean_stress(P, c.grid, c.shapes, c.colouring, false);
    double force_work = 0.0, scale = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      force_work += P.volume[p] * projected_mean_stress(c, a, p) * rate[p];
      scale += P.volume[p] * std::abs(mean_stress[p] * rate[p]);
    }
    a.average_volumetric_rates(P, c.grid, c.shapes, c.colouring, false);
    double material_work = 0.0, unaveraged_work = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      material_work += P.volume[p] * mean_stress[p] * P.velocity_gradient[p].trace();
      unaveraged_work += P.volume[p] * mean_stress[p] * rate[p];
    }
    EXPECT_NEAR(material_work, force_work, 1e-10 * scale) << seed;
    // The averaging does change the work of these fields (the check is not trivially met).
    EXPECT_GT(std::abs(material_work - unaveraged_work), 1e-3 * scale) << seed;
  }
}

}  // namespace
