#pragma once
// The simulation state and the explicit step. Built from a Scene; observers (outputs,
// progress, checkpoints) read it between steps and never change it. The step is a short list of
// stages (step() in simulation.cpp, docs/solver.md); the stages are the transfers
// (solver/transfers.hpp), the grid update (solver/grid_update.hpp), the rigid contact
// (contact/), heat conduction (thermal/) and the constitutive update (physics/).
#include <limits>
#include <memory>
#include <vector>

#include "contact/rigid_body.hpp"
#include "contact/rigid_contact.hpp"
#include "core/energy_totals.hpp"
#include "core/grid.hpp"
#include "core/particles.hpp"
#include "solver/scene.hpp"
#include "core/shape_functions.hpp"
#include "core/strip_colouring.hpp"
#include "physics/material.hpp"
#include "solver/guards.hpp"
#include "solver/restart_state.hpp"
#include "solver/rigid_body_heat.hpp"
#include "solver/volumetric_average.hpp"
#include "thermal/heat_conduction.hpp"

namespace mpmcut {

class Simulation {
 public:
  explicit Simulation(const Scene& scene);

  // One explicit time step towards a time max_dt ahead (an output time): the stable step, or
  // exactly max_dt when that is within it, or half of max_dt when that is within two stable steps
  // (no sliver steps; solver/time_step_to_target.hpp). Throws SimulationError from the guards.
  void step(double max_dt = std::numeric_limits<double>::infinity());

  const Scene& scene() const { return scene_; }
  const Particles& particles() const { return particles_; }
  Particles& particles() { return particles_; }  // for set-up, tests and restarts only
  const Grid& grid() const { return grid_; }
  const std::vector<std::unique_ptr<Material>>& materials() const { return materials_; }
  const std::vector<RigidBodyState>& rigid_bodies() const { return state_.rigid_bodies; }
  const EnergyTotals& energy() const { return state_.energy; }

  double time() const { return state_.time; }
  long step_count() const { return state_.step; }
  double last_dt() const { return state_.last_dt; }
  // Heat that flowed from the material into the rigid bodies' heat sinks (heat_transfer_coefficient > 0) in the
  // last step, J/m: nonzero only on steps that end with a conduction update. Observers sum it (not checkpointed).
  double last_step_heat_to_rigid_bodies() const { return last_sink_heat_; }
  // The conducting rigid bodies' cells (their fields are in rigid_bodies()[r].temperature_field).
  const RigidBodyHeat& rigid_body_heat() const { return body_heat_; }

  // Everything besides the particles that the next step depends on (checkpoints write it), and
  // putting it back (a restart; the particles through particles()). The state must come from a
  // simulation of the same scene: throws std::invalid_argument when its rigid bodies do not fit.
  const RestartState& restart_state() const { return state_; }
  void restore(const RestartState& state);

  // Time step the next step() will take: CFL limit, capped so the run ends at end_time.
  double stable_time_step() const;
  // Mass scaling factor of the deformable bodies' inertia in use (1 = none); see SolverSpec.
  double mass_scaling_factor() const { return inertia_factor_; }
  Vec2 total_momentum() const;  // kg m/s per m
  double max_temperature() const;
  long removed_particles() const { return state_.removed_particles; }
  double removed_mass() const { return state_.removed_mass; }
  long pushed_out_particles() const { return contact_.pushed_out_particles(); }  // diagnostics (not restart state)
  // What the rigid contact did in the last step: one record per contact node and pass, and per
  // particle the safeguard moved (contact/contact_law.hpp). Diagnostics, not restart state.
  const std::vector<ContactRecord>& contact_records() const { return contact_.records(); }
  // Scenes with fewer particles than this run single-threaded (default 4096; tests lower it).
  void set_parallel_min_particles(std::size_t n) { parallel_min_particles_ = n; }
  // Recomputes kinetic and elastic energy from the particles (dissipation terms are kept).
  void refresh_energy();

 private:
  // The stages of step(), in its order.
  double begin_step(double max_dt);
  void particles_to_grid();
  void prepare_rigid_contact(double dt);
  void apply_rigid_contact(ContactPass pass, double dt);
  void update_grid_momentum(double dt);
  void grid_to_particles(double dt);
  void push_particles_out_of_rigid_bodies(double dt);
  void remap_momentum_musl(double dt);
  void update_stress(double dt);
  void heat_particles(double dt);
  void advance_clock(double dt);
  void remove_escaped_particles();
  void check_guards() const;

  bool averaging_volumetric_rates() const { return scene_.solver.volumetric_average == VolumetricAverage::Nodal; }
  double resolve_mass_scaling();
  double mechanical_time_step() const;
  void check_fixed_time_step() const;  // std::invalid_argument for a step beyond stability

  Scene scene_;
  Grid grid_;
  std::vector<ShapeFunction> shapes_;  // one per body (uGIMP lp depends on its particles per cell)
  std::vector<std::unique_ptr<Material>> materials_;
  RigidContact contact_;
  bool heat_transfer_ = false;  // a rigid body exchanges heat with the material (conduction steps)
  RigidBodyHeat body_heat_;     // the conducting rigid bodies' temperature fields
  SubcycledConduction conduction_;
  double node_mass_cutoff_ = 0.0;  // nodes lighter than this count as empty, kg/m
  double inertia_factor_ = 1.0;    // mass scaling f: inertial mass = f x mass
  // Small scenes run their loops on one thread: a parallel region costs more than it saves, and
  // on a busy machine waiting threads are worse. Results do not depend on it (fixed orders).
  std::size_t parallel_min_particles_ = 4096;
  bool parallel_ = true;
  double stable_dt_ = 0.0;    // this step's stable step, before landing on an output time (penalty springs)
  bool conduct_now_ = false;  // this step ends with a conduction update (P2G maps temperatures)
  double last_sink_heat_ = 0.0;  // J/m into the rigid bodies' heat sinks in the last step
  Particles particles_;
  RestartState state_;
  // Scratch, reused every step
  StripColouring colouring_;  // this step's P2G strips, reused by the MUSL remap and conduction
  NodalVolumetricAverage volumetric_average_;  // [solver] volumetric_average = "nodal": this step's nodal fields
  std::vector<Vec2> position_new_;
  std::vector<ConstitutiveIncrement> increments_;
  std::vector<double> deposited_heat_;  // frictional heat taken by each particle this step, J/m
  std::vector<double> transfer_loss_;   // kinetic energy the FLIP/PIC blend took from each particle, J/m
  ConductionScratch conduction_scratch_;
};

}  // namespace mpmcut
