#pragma once
// The simulation state and the explicit step. Built from a Scene; observers (outputs,
// progress, checkpoints) read it between steps and never change it.
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/particles.hpp"
#include "core/scene.hpp"
#include "contact/contact_law.hpp"
#include "contact/rigid_polygon.hpp"
#include "core/shape_functions.hpp"
#include "physics/material.hpp"

namespace mpmcut {

// Thrown by the guards (NaN, particle leaving the grid, penetration): carries the where.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A rigid body's motion and the force the deformable bodies exert on it through contact.
struct RigidBodyState {
  std::string name;
  Vec2 velocity = Vec2::Zero();      // m/s (prescribed)
  Vec2 displacement = Vec2::Zero();  // m since t = 0
  Vec2 force = Vec2::Zero();         // N per m of thickness, on the rigid body, last step
  Vec2 impulse = Vec2::Zero();       // N s per m, accumulated
  Vec2 step_impulse = Vec2::Zero();  // N s per m, this step (both contact passes)
  double work = 0.0;                 // J per m: work done BY the rigid body on the material
};

// Global energies, J per m of thickness. Dissipated terms accumulate from t = 0.
struct EnergyTotals {
  double kinetic = 0.0;
  double elastic = 0.0;
  double plastic_work = 0.0;
  double heat = 0.0;               // plastic heating + frictional heating
  double damage_dissipation = 0.0;
  double friction = 0.0;           // frictional work at rigid contacts
  double viscous = 0.0;            // work of the artificial bulk viscosity (shocks), >= 0
  double external_work = 0.0;      // work by rigid bodies + body force
  // Algorithmic energy changes, so that the ledger closes (docs/cutting.md, "Energy balance"):
  double transfer_dissipation = 0.0;   // kinetic energy the FLIP/PIC blend removes in G2P, >= 0 in practice
  double contact_safeguard = 0.0;      // kinetic energy the rigid-body push-out safeguard removes, >= 0
  double removed_energy = 0.0;         // kinetic + elastic energy of particles removed from the domain
  double initial = 0.0;                // kinetic + elastic at t = 0
};

// (kinetic + elastic + every dissipated or removed term) - (initial + external work): zero for a
// ledger that accounts for every joule.
inline double energy_balance_residual(const EnergyTotals& e) {
  return e.kinetic + e.elastic + e.plastic_work + e.damage_dissipation + e.friction + e.viscous +
         e.transfer_dissipation + e.contact_safeguard + e.removed_energy - e.initial - e.external_work;
}

class Simulation {
 public:
  explicit Simulation(const Scene& scene);

  // One explicit time step of at most max_dt (to land on output times); throws SimulationError
  // from the guards.
  void step(double max_dt = std::numeric_limits<double>::infinity());

  const Scene& scene() const { return scene_; }
  const Particles& particles() const { return particles_; }
  Particles& particles() { return particles_; }  // for set-up, tests and restarts only
  const Grid& grid() const { return grid_; }
  const std::vector<std::unique_ptr<Material>>& materials() const { return materials_; }
  const std::vector<RigidBodyState>& rigid_bodies() const { return rigid_; }
  std::vector<RigidBodyState>& rigid_bodies() { return rigid_; }  // restarts only
  const EnergyTotals& energy() const { return energy_; }
  EnergyTotals& energy() { return energy_; }  // restarts only

  double time() const { return time_; }
  long step_count() const { return step_; }
  double last_dt() const { return dt_; }
  void set_clock(double time, long step) { time_ = time; step_ = step; }  // restarts only
  void set_last_dt(double dt) { dt_ = dt; }  // restarts only

  // Time step the next step() will take: CFL limit, capped so the run ends at end_time.
  double stable_time_step() const;
  // Mass scaling factor of the deformable bodies' inertia in use (1 = none); see SolverSpec.
  double mass_scaling_factor() const { return inertia_factor_; }
  Vec2 total_momentum() const;  // kg m/s per m
  double max_temperature() const;
  long removed_particles() const { return removed_particles_; }
  long pushed_out_particles() const { return pushed_out_particles_; }  // diagnostics (not restart state)
  // What the rigid contact did in the last step: one record per contact node and pass, and per
  // particle the safeguard moved (contact/contact_law.hpp). Diagnostics, not restart state.
  const std::vector<ContactRecord>& contact_records() const { return contact_records_; }
  double removed_mass() const { return removed_mass_; }
  void set_removed(long count, double mass) { removed_particles_ = count; removed_mass_ = mass; }  // restarts only
  // Conduction sub-cycle state: seconds since the last conduction update and steps since.
  std::pair<double, int> conduction_state() const { return {conduction_elapsed_, steps_since_conduction_}; }
  void set_conduction_state(double elapsed, int steps) { conduction_elapsed_ = elapsed; steps_since_conduction_ = steps; }  // restarts only
  // Scenes with fewer particles than this run single-threaded (default 4096; tests lower it).
  void set_parallel_min_particles(std::size_t n) { parallel_min_particles_ = n; }
  // Recomputes kinetic and elastic energy from the particles (dissipation terms are kept).
  void refresh_energy();

 private:
  void build_particles();
  double resolve_mass_scaling();
  double mechanical_time_step() const;
  void particles_to_grid();
  void apply_grid_boundary_conditions(bool momentum_only);
  void update_grid_momentum(double dt);
  enum class ContactPass { AfterP2G, AfterUpdate, MuslRemap };
  void apply_rigid_contact(std::vector<Vec2>& velocity, double dt, ContactPass pass);
  void compute_particle_contact_weights();
  void grid_to_particles(double dt);
  void remap_momentum_musl();
  void update_particle_stress(double dt);
  void conduct_heat(double dt);
  void deposit_frictional_heat();
  void remove_escaped_particles();
  void push_particles_out_of_rigid_bodies(double dt);
  void check_guards() const;
  void sort_particles_by_cell();

  // Sum over particles of f(i), in fixed-size chunks so the result does not depend on the thread count.
  template <class F>
  double deterministic_sum(std::size_t n, F&& f) const;
  const ShapeFunction& shape_of(std::size_t particle) const { return shapes_[particles_.body[particle]]; }
  Vec2 cell_units(const Vec2& x) const { return (x - grid_.origin) / grid_.h; }
  void bucket_particles_by_strip();
  template <class F>
  void for_each_particle_coloured(F&& scatter);

  Scene scene_;
  Grid grid_;
  std::vector<ShapeFunction> shapes_;  // one per body (uGIMP lp depends on its particles per cell)
  std::vector<RigidPolygon> rigid_geometry_;  // outlines at t = 0; current = outline + displacement
  double node_mass_cutoff_ = 0.0;             // nodes lighter than this count as empty, kg/m
  double inertia_factor_ = 1.0;               // mass scaling f: inertial mass = f x mass
  bool has_friction_ = false;                 // some rigid body has mu > 0: frictional heating
  // Conduction sub-cycling (restart state: conduction_elapsed_, steps_since_conduction_)
  static constexpr int conduction_substeps_ = 16;
  double conduction_limit_ = 0.0;   // explicit conduction step limit, s
  double conduction_elapsed_ = 0.0; // mechanical time since the last conduction update, s
  int steps_since_conduction_ = 0;
  bool conduct_now_ = false;        // this step updates conduction (P2G maps temperatures)
  // Small scenes run their loops on one thread: a parallel region costs more than it saves, and
  // on a busy machine waiting threads are worse. Results do not depend on it (fixed orders).
  std::size_t parallel_min_particles_ = 4096;
  bool parallel_ = true;
  Vec2 friction_box_lo_, friction_box_hi_;  // node index box with frictional heat this step
  bool particle_contact_ = false;  // scene_.solver.contact_detection == Particle
  std::vector<std::vector<double>> contact_weight_;  // per rigid body, per node: sum S m phi, kg/m
  std::vector<std::vector<Vec2>> contact_normal_;    // per rigid body, per node: sum S m phi n
  std::vector<ContactRecord> contact_records_;  // last step's contact, see contact_records()
  long pushed_out_particles_ = 0;             // particle corrections by the rigid-body safeguard
  long removed_particles_ = 0;                // left the domain (remove_escaping_particles)
  double removed_mass_ = 0.0;                 // kg/m
  // Scratch, reused every step
  std::vector<Vec2> position_new_;
  std::vector<std::size_t> strip_order_;  // particle indices grouped by strip of grid rows
  std::vector<std::size_t> strip_begin_;  // strip s holds strip_order_[strip_begin_[s] .. strip_begin_[s+1])
  std::vector<ConstitutiveIncrement> increments_;
  std::vector<double> deposited_heat_;  // frictional heat taken by each particle this step, J/m
  std::vector<double> transfer_loss_;   // kinetic energy the FLIP/PIC blend took from each particle this step, J/m
  Particles particles_;
  std::vector<std::unique_ptr<Material>> materials_;
  std::vector<RigidBodyState> rigid_;
  EnergyTotals energy_;
  double time_ = 0.0;
  double dt_ = 0.0;
  long step_ = 0;
};

}  // namespace mpmcut
