#include "app/bench_command.hpp"

#include <omp.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "solver/simulation.hpp"
#include "core/thread_tuner.hpp"
#include "io/material_library.hpp"
#include "run/case_loading.hpp"

namespace mpmcut {

namespace {

// Wall-clock and CPU time (all threads of the process) of a timed stretch.
struct Clock {
  std::chrono::steady_clock::time_point wall0;
  double cpu0 = 0.0;
  static double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
  }
  void start() {
    wall0 = std::chrono::steady_clock::now();
    cpu0 = cpu_seconds();
  }
};

struct Timing {
  double wall = 0.0;  // s
  double cpu = 0.0;   // s, summed over threads
  void add(const Clock& c) {
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - c.wall0).count();
    cpu += Clock::cpu_seconds() - c.cpu0;
  }
};

// Below this a timing is mostly thread start-up, cache warm-up and the scheduler: 5 steps of 100 particles
// (a few ms) gave a "speed-up" of 33x on 2 cores.
constexpr double kShortestMeaningfulTiming_s = 0.2;

// One line per thread count: particle-steps/s by wall clock and per thread, and by CPU time.
void report(int threads, std::size_t particles, long steps, const Timing& t, double& single_rate, const std::string& extra) {
  const double work = static_cast<double>(particles) * static_cast<double>(steps);
  const double rate = work / t.wall;
  if (threads == 1) single_rate = rate;
  const std::string speedup = single_rate > 0 && threads > 1 ? fmt::format(", speed-up {:.2f}x", rate / single_rate) : "";
  const std::string too_short =
      t.wall < kShortestMeaningfulTiming_s
          ? fmt::format(" [timed stretch under {:g} s: noise, not a speed; raise --steps or --particles]",
                        kShortestMeaningfulTiming_s)
          : "";
  std::cout << fmt::format(
      "  threads {:2d}: {:8d} particles x {} steps in {:.3f} s: {:.3g} particle-steps/s, {:.3g} per thread; "
      "CPU {:.3f} s: {:.3g} particle-steps per CPU-second{}{}{}\n",
      threads, particles, steps, t.wall, rate, rate / threads, t.cpu, work / t.cpu, speedup, extra, too_short);
}

// Ti-6Al-4V, Johnson 1985 set from the built-in library (JC flow, heating, JC damage + Hillerborg).
MaterialParameters library_ti64() {
  const MaterialParameters* m = builtin_material_library().find("ti64-johnson-1985");
  if (!m) throw std::logic_error("bench: the built-in material library has no 'ti64-johnson-1985'");
  return *m;
}

// A square block of about `particles` particles, 2x2 per cell, h = 5 um, `margin` empty cells around it.
Scene block_scene(long particles, const MaterialParameters& m, int margin, const std::string& title) {
  const int ppc = 2;
  const long cells = std::max(1L, static_cast<long>(std::lround(std::sqrt(particles / double(ppc * ppc)))));
  const double h = 5e-6;
  Scene s;
  s.title = title;
  s.grid = {h, Vec2(0, 0), Vec2((cells + 2 * margin) * h, (cells + 2 * margin) * h)};
  s.materials.push_back(m);
  BodySpec b;
  b.name = "block";
  b.material = m.name;
  b.particles_per_cell = ppc;
  b.shape.kind = ShapeKind::Rectangle;
  b.shape.rectangle = {Vec2(margin * h, margin * h), Vec2((cells + margin) * h, (cells + margin) * h)};
  s.bodies.push_back(b);
  s.solver.end_time = 1.0;
  return s;
}

// An elastic Ti-6Al-4V-like block with a smooth initial velocity field, uGIMP, MUSL, 2x2 ppc:
// every stage of the step does real work, the stress update is the cheap elastic one.
void bench_elastic(const BenchOptions& o) {
  MaterialParameters m;
  m.name = "elastic-ti64";
  m.model = MaterialModel::Elastic;
  m.density = 4430;
  m.youngs_modulus = 113.8e9;
  m.poisson_ratio = 0.342;
  const Scene scene = block_scene(o.particles, m, 4, "benchmark: elastic block");
  std::cout << fmt::format("elastic block (MUSL, uGIMP, 2x2 ppc, linear elastic), {} timed steps:\n", o.steps);
  double single = 0.0;
  for (int threads : o.threads) {
    omp_set_num_threads(threads);
    Simulation sim(scene);
    const double L = (scene.bodies[0].shape.rectangle.max - scene.bodies[0].shape.rectangle.min).x();
    for (std::size_t p = 0; p < sim.particles().size(); ++p) {
      const Vec2 x = sim.particles().position[p];
      sim.particles().velocity[p] = Vec2(std::sin(6.28 * x.y() / L), std::cos(6.28 * x.x() / L));
    }
    for (int k = 0; k < 5; ++k) sim.step();  // warm-up
    Timing t;
    Clock c;
    c.start();
    for (int k = 0; k < o.steps; ++k) sim.step();
    t.add(c);
    report(threads, sim.particles().size(), o.steps, t, single, "");
  }
}

// Ti-6Al-4V Johnson-Cook (rate dependence, adiabatic heating, JC damage initiation + Hillerborg) in
// sustained pure shear: before every step (untimed) the particle velocities are reset to
// v = rate (x - xc, -(y - yc)), a kinematic driver, so every particle keeps flowing plastically however
// large the block or long the run (a free block with only an initial velocity field runs out of kinetic
// energy, and its edges stop yielding first). The rate is chosen so that the block reaches about 5 %
// strain by the last timed step; the elastic loading (about 0.6 % strain, more with the rate term) falls
// in the untimed warm-up.
void bench_plastic(const BenchOptions& o) {
  const MaterialParameters m = library_ti64();
  const Scene scene = block_scene(o.particles, m, 12, "benchmark: plastic Ti-6Al-4V block");
  const double h = scene.grid.cell_size;
  const Rectangle& r = scene.bodies[0].shape.rectangle;
  const Vec2 centre = 0.5 * (r.min + r.max);
  const double dt_estimate = scene.solver.cfl * h / m.p_wave_speed();
  // q = 2 sqrt(3) G eps in plane pure shear; warm-up to 1.3x the yield strain (the rate term of the flow
  // law raises the yield stress by ~15 %), then the timed steps, 5 % strain in all.
  const double yield_strain = m.jc_A / (2.0 * std::sqrt(3.0) * m.shear_modulus());
  const double warmup_share = 2.0 * yield_strain / 0.05;
  const int warmup = static_cast<int>(std::ceil(o.steps * warmup_share / (1.0 - warmup_share)));
  const double rate = 0.05 / ((warmup + o.steps) * dt_estimate);  // 1/s
  std::cout << fmt::format(
      "plastic block (MUSL, uGIMP, 2x2 ppc, {}: Johnson-Cook + heating + damage), pure shear at {:.3g} 1/s, "
      "{} warm-up + {} timed steps:\n",
      m.name, rate, warmup, o.steps);
  double single = 0.0;
  for (int threads : o.threads) {
    omp_set_num_threads(threads);
    Simulation sim(scene);
    auto& P = sim.particles();
    auto drive = [&] {
      for (std::size_t p = 0; p < P.size(); ++p) {
        const Vec2 d = P.position[p] - centre;
        P.velocity[p] = rate * Vec2(d.x(), -d.y());
      }
    };
    for (int k = 0; k < warmup; ++k) {
      drive();
      sim.step();
    }
    // Time each step alone; between steps (untimed) count the particles whose plastic strain grew
    // (skipping the steps that re-sort the particles, where the order changes).
    Timing t;
    long plastic = 0, counted_steps = 0;
    std::vector<double> before;
    const double T0 = sim.max_temperature();
    for (int k = 0; k < o.steps; ++k) {
      const bool count = sim.step_count() % 20 != 0;  // Simulation::step re-sorts every 20 steps
      if (count) before = P.plastic_strain;
      drive();
      Clock c;
      c.start();
      sim.step();
      t.add(c);
      if (!count || P.plastic_strain.size() != before.size()) continue;
      ++counted_steps;
      for (std::size_t p = 0; p < P.size(); ++p) plastic += P.plastic_strain[p] > before[p];
    }
    const double fraction = static_cast<double>(plastic) / (static_cast<double>(P.size()) * std::max(1L, counted_steps));
    double eps_max = 0.0, omega_max = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) {
      eps_max = std::max(eps_max, P.plastic_strain[p]);
      omega_max = std::max(omega_max, P.damage_initiation[p]);
    }
    report(threads, P.size(), o.steps, t, single,
           fmt::format("; plastic in {:.1f} % of the timed particle-steps (max eps_p {:.3f}, max omega {:.2f}, "
                       "max T rise {:.1f} K)",
                       100.0 * fraction, eps_max, omega_max, sim.max_temperature() - T0));
    if (fraction < 0.95)
      std::cout << "  warning: fewer than 95 % of the particle-steps were plastic; the figure mixes in elastic updates\n";
  }
}

// The default cut (cases/ti64_default.toml, what `mpmcut run` runs with no case). One simulation: warmed
// up (at the smallest thread count: results do not depend on it, and on a busy machine it is the one that
// suffers least) until the tool has travelled half the uncut chip thickness past first contact so the
// chip has started to form, then timed for `cutting_steps` steps at each thread count in turn.
void bench_cutting(const BenchOptions& o) {
  const Case cut = default_cutting_case();
  const Scene& scene = cut.scene;
  const CuttingParameters& c = *cut.cutting;
  const int warmup_threads = *std::min_element(o.threads.begin(), o.threads.end());
  omp_set_num_threads(warmup_threads);
  Simulation sim(scene);
  const double warmup_travel = 0.5 * c.uncut_chip_thickness + 0.5 * c.cell_size;  // the tool starts h/2 away
  const auto w0 = std::chrono::steady_clock::now();
  while (sim.time() * c.cutting_speed < warmup_travel) sim.step();
  const double warmup_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  const double H = scene.bodies[0].shape.rectangle.max.y();
  auto chip_particles = [&] {
    long n = 0;
    for (const Vec2& x : sim.particles().position) n += x.y() > H + 0.5 * c.cell_size;
    return n;
  };
  std::cout << fmt::format(
      "cutting (the default cut, cases/ti64_default.toml: V = {} m/s, t0 = {} um, h = {} um, friction {}), warm-up {} steps "
      "to {:.0f} um tool travel ({:.1f} s at {} threads), then {} timed steps per thread count:\n",
      c.cutting_speed, c.uncut_chip_thickness * 1e6, c.cell_size * 1e6, c.friction, sim.step_count(),
      sim.time() * c.cutting_speed * 1e6, warmup_wall, warmup_threads, o.cutting_steps);
  double single = 0.0;
  for (int threads : o.threads) {
    omp_set_num_threads(threads);
    const long chip0 = chip_particles();
    const double travel0 = sim.time() * c.cutting_speed;
    Timing t;
    Clock clock;
    clock.start();
    for (int k = 0; k < o.cutting_steps; ++k) sim.step();
    t.add(clock);
    report(threads, sim.particles().size(), o.cutting_steps, t, single,
           fmt::format("; tool travel {:.1f}-{:.1f} um, particles above the free surface {} -> {}", travel0 * 1e6,
                       sim.time() * c.cutting_speed * 1e6, chip0, chip_particles()));
  }
  // What `mpmcut run --threads N` does by default: the fastest of 1..N, re-timed every 10 s.
  const int most = *std::max_element(o.threads.begin(), o.threads.end());
  if (most > 1) {
    ThreadTuner tuner(most);
    Timing t;
    Clock clock;
    clock.start();
    for (int k = 0; k < o.cutting_steps; ++k) {
      tuner.before_step();
      sim.step();
      tuner.after_step();
    }
    t.add(clock);
    const double rate = static_cast<double>(sim.particles().size()) * o.cutting_steps / t.wall;
    std::cout << fmt::format(
        "  tuned up to {} threads (run's default): {} steps in {:.3f} s: {:.3g} particle-steps/s{}; threads in use at "
        "the end {}\n",
        most, o.cutting_steps, t.wall, rate, single > 0 ? fmt::format(", {:.2f}x the 1-thread rate", rate / single) : "",
        tuner.chosen());
  }
}

// A process that keeps one core busy (a spinning loop) while the benchmarks run: a desktop or a
// shared node doing other work. Killed at the end.
struct BackgroundLoad {
  pid_t pid = -1;
  BackgroundLoad() {
    pid = fork();
    if (pid == 0) {
      volatile unsigned long x = 0;
      for (;;) x = x + 1;
    }
  }
  ~BackgroundLoad() {
    if (pid > 0) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
  }
};

}  // namespace

int run_benchmark(const BenchOptions& options) {
  const std::string& w = options.which;
  if (w != "all" && w != "elastic" && w != "plastic" && w != "cutting") {
    std::cerr << "error: bench --case must be elastic, plastic, cutting or all, got '" << w << "'\n";
    return 2;
  }
  std::cout << fmt::format("mpmcut bench (OpenMP, up to {} threads available){}\n", omp_get_num_procs(),
                           options.background_load ? "; one core kept busy by a spinning background process" : "");
  std::optional<BackgroundLoad> load;
  if (options.background_load) load.emplace();
  if (w == "all" || w == "elastic") bench_elastic(options);
  if (w == "all" || w == "plastic") bench_plastic(options);
  if (w == "all" || w == "cutting") bench_cutting(options);
  return 0;
}

}  // namespace mpmcut
