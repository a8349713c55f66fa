#include "app/bench_command.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "core/simulation.hpp"

namespace mpmcut {

namespace {

// An elastic Ti-6Al-4V-like block with a smooth initial velocity field, uGIMP, MUSL, 2x2 ppc:
// every stage of the step does real work.
Scene elastic_block_scene(long particles) {
  const int ppc = 2;
  const long cells = std::max(1L, static_cast<long>(std::lround(std::sqrt(particles / double(ppc * ppc)))));
  const double h = 5e-6;
  Scene s;
  s.title = "benchmark: elastic block";
  s.grid = {h, Vec2(0, 0), Vec2((cells + 8) * h, (cells + 8) * h)};
  MaterialParameters m;
  m.name = "elastic-ti64";
  m.model = MaterialModel::Elastic;
  m.density = 4430;
  m.youngs_modulus = 113.8e9;
  m.poisson_ratio = 0.342;
  s.materials.push_back(m);
  BodySpec b;
  b.name = "block";
  b.material = m.name;
  b.particles_per_cell = ppc;
  b.shape.kind = ShapeKind::Rectangle;
  b.shape.rectangle = {Vec2(4 * h, 4 * h), Vec2((cells + 4) * h, (cells + 4) * h)};
  s.bodies.push_back(b);
  s.solver.end_time = 1.0;
  return s;
}

}  // namespace

int run_benchmark(const BenchOptions& options) {
  const Scene scene = elastic_block_scene(options.particles);
  double single = 0.0;
  std::cout << fmt::format("mpmcut bench: elastic MUSL step, uGIMP, 2x2 ppc, {} steps\n", options.steps);
  for (int threads : options.threads) {
    omp_set_num_threads(threads);
    Simulation sim(scene);
    const double L = (scene.bodies[0].shape.rectangle.max - scene.bodies[0].shape.rectangle.min).x();
    for (std::size_t p = 0; p < sim.particles().size(); ++p) {
      const Vec2 x = sim.particles().position[p];
      sim.particles().velocity[p] = Vec2(std::sin(6.28 * x.y() / L), std::cos(6.28 * x.x() / L));
    }
    for (int k = 0; k < 5; ++k) sim.step();  // warm-up
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < options.steps; ++k) sim.step();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double rate = static_cast<double>(sim.particles().size()) * options.steps / wall;
    if (threads == 1) single = rate;
    std::cout << fmt::format("  threads {:2d}: {:8d} particles, {:7.3f} s, {:.3g} particle-steps/s ({:.3g} per thread){}\n",
                             threads, sim.particles().size(), wall, rate, rate / threads,
                             single > 0 && threads > 1 ? fmt::format(", speed-up {:.2f}x", rate / single) : "");
  }
  return 0;
}

}  // namespace mpmcut
