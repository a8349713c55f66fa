// The explicit MPM step ([Sulsky1994] USL / [SulskyZhouSchreyer1995] MUSL) with uGIMP or
// linear shape functions, multi-velocity-field rigid contact with Coulomb friction and grid
// heat conduction. step() is the list of stages (docs/solver.md); each stage below is a few
// lines that call the transfers, the grid update, the contact law, conduction or the materials.
#include "solver/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "contact/frictional_heating.hpp"
#include "contact/rigid_heat_transfer.hpp"
#include "solver/rigid_body_heat.hpp"
#include "core/cell_order.hpp"
#include "core/deterministic_sum.hpp"
#include "solver/fixed_step_limit.hpp"
#include "solver/grid_update.hpp"
#include "solver/seeding.hpp"
#include "solver/time_step_to_target.hpp"
#include "solver/transfers.hpp"

namespace mpmcut {

// ---------------------------------------------------------------------------------------------
// Construction

Simulation::Simulation(const Scene& scene) : scene_(scene) {
  grid_.build(scene_.grid);
  for (const auto& m : scene_.materials) materials_.push_back(make_material(m));
  for (const auto& b : scene_.bodies)
    shapes_.emplace_back(scene_.solver.shape_function, grid_.h, b.particles_per_cell);
  for (const auto& r : scene_.rigid_bodies) {
    RigidBodyState st;
    st.name = r.name;
    st.velocity = r.velocity;
    state_.rigid_bodies.push_back(st);
  }
  conduction_ = SubcycledConduction(scene_.thermal.conduction, scene_.materials, grid_.h, scene_.solver.cfl);
  seed_particles(scene_, grid_, particles_);
  sort_particles_by_cell(particles_, grid_);
  inertia_factor_ = resolve_mass_scaling();
  double max_density = 0.0;
  for (const auto& m : scene_.materials) max_density = std::max(max_density, m.density);
  // MPM3D's cut-off (1e-5 rho h^3 in 3D), per unit thickness here.
  node_mass_cutoff_ = 1e-5 * inertia_factor_ * max_density * grid_.h * grid_.h;
  RigidContactSettings contact;
  contact.contact_distance = scene_.solver.contact_distance_cells * grid_.h;
  contact.detection = scene_.solver.contact_detection;
  contact.node_mass_cutoff = node_mass_cutoff_;
  contact.penalty_stiffness = scene_.solver.penalty_stiffness;
  contact_ = RigidContact(scene_.rigid_bodies, contact);
  heat_transfer_ = any_heat_transfer(scene_.rigid_bodies);
  body_heat_ = RigidBodyHeat(scene_.rigid_bodies, grid_.h);
  body_heat_.start(state_.rigid_bodies);
  mark_boundary_nodes(scene_.boundaries, scene_.thermal, grid_);
  refresh_energy();
  state_.energy.initial = state_.energy.kinetic + state_.energy.elastic;
  check_fixed_time_step();
}

// A fixed step beyond the wave-speed limit cell / (c + |v|) blows the explicit update up within a few steps, which
// the guards would then report as something else (particles leaving the grid): refused here, with the numbers.
void Simulation::check_fixed_time_step() const {
  const double fixed = scene_.solver.fixed_time_step;
  if (fixed <= 0.0) return;
  const double limit = mechanical_time_step() / scene_.solver.cfl;  // the CFL step at cfl = 1
  if (fixed <= limit) return;
  throw std::invalid_argument("solver.fixed_time_step = " + fixed_step_beyond_stability(fixed, limit, scene_.solver.cfl));
}

// Mass scaling (docs/mass_scaling.md): a fixed factor, or the one that brings the initial
// stable step up to the target, dt_cfl ~ sqrt(f) (f = (target / dt_cfl(f = 1))^2, never below 1).
double Simulation::resolve_mass_scaling() {
  const SolverSpec& s = scene_.solver;
  if (s.mass_scaling_target_time_step <= 0.0) return std::max(1.0, s.mass_scaling_factor);
  inertia_factor_ = 1.0;
  const double dt0 = mechanical_time_step();
  const double ratio = s.mass_scaling_target_time_step / dt0;
  return std::max(1.0, ratio * ratio);
}

void Simulation::restore(const RestartState& state) {
  if (state.rigid_bodies.size() != state_.rigid_bodies.size())
    throw std::invalid_argument("restart state has " + std::to_string(state.rigid_bodies.size()) +
                                " rigid bodies, the scene " + std::to_string(state_.rigid_bodies.size()));
  body_heat_.check(state.rigid_bodies);
  state_ = state;
}

// ---------------------------------------------------------------------------------------------
// The step (docs/solver.md)

void Simulation::step(double max_dt) {
  const double dt = begin_step(max_dt);                 // 1. dt (CFL), particle order, conduction due?
  particles_to_grid();                                  // 2. P2G
  prepare_rigid_contact(dt);                            // 3. rigid bodies at their nodes (penalty: forces)
  apply_rigid_contact(ContactPass::AfterP2G, dt);       // 4. contact on the P2G momenta
  update_grid_momentum(dt);                             // 5. p += dt f, boundary conditions,
  apply_rigid_contact(ContactPass::AfterUpdate, dt);    //    contact (force on the bodies, friction work)
  grid_to_particles(dt);                                // 6. G2P: velocity (FLIP/PIC) and position,
  push_particles_out_of_rigid_bodies(dt);               //    the contact safeguard
  if (scene_.solver.scheme == TimeScheme::MUSL) remap_momentum_musl(dt);  // 7. MUSL remap
  update_stress(dt);                                    // 8. velocity gradient, constitutive update
  heat_particles(dt);                                   // 9. frictional heat, conduction
  advance_clock(dt);                                    //    new positions, rigid bodies, time
  remove_escaped_particles();                           // 10. guards
  check_guards();
}

double Simulation::begin_step(double max_dt) {
  parallel_ = particles_.size() >= parallel_min_particles_;
  stable_dt_ = stable_time_step();
  const double dt = time_step_to_target(max_dt, stable_dt_);
  if (state_.step % 20 == 0) sort_particles_by_cell(particles_, grid_);
  conduct_now_ = conduction_.begin_step(state_.conduction, dt);
  return dt;
}

void Simulation::particles_to_grid() {
  P2GFields fields;
  fields.mass_position = !contact_.empty();
  fields.temperature = conduct_now_;
  fields.heat_capacity = conduct_now_ || contact_.has_friction();
  colouring_.bucket(particles_, grid_, shapes_);
  std::span<const double> node_mean_stress;
  if (averaging_volumetric_rates()) {
    volumetric_average_.project_mean_stress(particles_, grid_, shapes_, colouring_, parallel_);
    node_mean_stress = volumetric_average_.node_mean_stress();
  }
  mpmcut::particles_to_grid(particles_, shapes_, scene_.materials, inertia_factor_, scene_.body_force, fields,
                            node_mean_stress, parallel_, colouring_, grid_);
  apply_velocity_boundary_conditions(BoundaryPhase::AfterP2G, parallel_, grid_);
}

void Simulation::prepare_rigid_contact(double dt) {
  contact_.begin_step(state_.rigid_bodies);
  if (!contact_.empty() && scene_.solver.contact_detection == ContactDetection::Penalty)
    contact_.apply_penalty(particles_, grid_, shapes_, inertia_factor_, dt, std::max(dt, stable_dt_),
                           state_.rigid_bodies, state_.energy);
  if (!contact_.empty() && scene_.solver.contact_detection == ContactDetection::Particle)
    contact_.compute_particle_weights(particles_, grid_, shapes_, inertia_factor_, state_.rigid_bodies);
  if (!contact_.empty() && scene_.solver.contact_detection == ContactDetection::Gap)
    contact_.compute_node_gaps(particles_, grid_, shapes_, state_.rigid_bodies);
}

void Simulation::apply_rigid_contact(ContactPass pass, double dt) {
  contact_.apply(pass, dt, grid_, state_.rigid_bodies, state_.energy);
}

void Simulation::update_grid_momentum(double dt) {
  mpmcut::update_grid_momentum(dt, node_mass_cutoff_, parallel_, grid_);
}

void Simulation::grid_to_particles(double dt) {
  // Work of the body force, sum m_p b.(v_old + v_new)/2 dt = b.(P_old + P_new)/2 dt, from the
  // total momenta (fixed-chunk sums): an OpenMP reduction would make it vary from run to run.
  const Vec2 b = scene_.body_force;
  const bool body_force = b.x() != 0.0 || b.y() != 0.0;
  const Vec2 momentum_old = body_force ? total_momentum() : Vec2::Zero();
  mpmcut::grid_to_particles(particles_, grid_, shapes_, inertia_factor_, scene_.solver.flip_fraction, dt, parallel_,
                     position_new_, transfer_loss_);
  if (body_force) state_.energy.external_work += b.dot(0.5 * (momentum_old + total_momentum())) * dt;
  state_.energy.transfer_dissipation +=
      deterministic_sum(particles_.size(), [&](std::size_t p) { return transfer_loss_[p]; }, parallel_);
}

void Simulation::push_particles_out_of_rigid_bodies(double dt) {
  if (contact_.empty()) return;
  contact_.push_particles_out(particles_, position_new_, dt, inertia_factor_, grid_.h, parallel_, state_.rigid_bodies,
                              state_.energy);
}

// MUSL: the updated particle momenta back on the grid, constrained again (boundary conditions and
// contact at the nodes the momentum update found in contact): the velocity of the strain update.
void Simulation::remap_momentum_musl(double dt) {
  mpmcut::remap_momentum_musl(particles_, shapes_, inertia_factor_, colouring_, parallel_, grid_);
  apply_velocity_boundary_conditions(BoundaryPhase::AfterUpdate, parallel_, grid_);
  apply_rigid_contact(ContactPass::MuslRemap, dt);  // dt: gap detection's allowed approach
}

void Simulation::update_stress(double dt) {
  if (averaging_volumetric_rates()) {
    compute_velocity_gradients(particles_, grid_, shapes_, parallel_);
    volumetric_average_.average_volumetric_rates(particles_, grid_, shapes_, colouring_, parallel_);
    advance_deformation_gradients(particles_, dt, parallel_);
  } else {
    update_velocity_gradients(particles_, grid_, shapes_, dt, parallel_);
  }
  Particles& P = particles_;
  const std::size_t n = P.size();
  increments_.resize(n);
  StepContext ctx;
  ctx.dt = dt;
  ctx.cell_size = grid_.h;
  ctx.inertia_factor = inertia_factor_;
#pragma omp parallel for schedule(static, 512) if (parallel_)  // interleaved: the chip's costly plastic particles are contiguous (sorted by cell)
  for (std::size_t p = 0; p < n; ++p) increments_[p] = materials_[P.material[p]]->update(P, p, P.velocity_gradient[p], ctx);
  EnergyTotals& e = state_.energy;
  auto sum = [&](auto term) { return deterministic_sum(n, [&](std::size_t p) { return increments_[p].*term; }, parallel_); };
  e.plastic_work += sum(&ConstitutiveIncrement::plastic_work);
  e.heat += sum(&ConstitutiveIncrement::heat);
  e.damage_dissipation += sum(&ConstitutiveIncrement::damage_dissipation);
  e.viscous += sum(&ConstitutiveIncrement::viscous_dissipation);
}

void Simulation::heat_particles(double dt) {
  last_sink_heat_ = 0.0;
  if (contact_.has_friction())
    state_.energy.heat += deposit_frictional_heat(particles_, grid_, shapes_, scene_.materials, contact_.heated_nodes(),
                                                  deposited_heat_, parallel_);
  if (const auto elapsed = conduction_.end_step(state_.conduction, dt, conduct_now_)) {
    // Rigid bodies with a heat transfer coefficient are heat sinks on their surface nodes. The heat
    // that flows into them leaves the material; like the heat through fixed-temperature boundaries it
    // is not part of the mechanical energy ledger.
    if (heat_transfer_) {
      mark_heat_sinks(grid_, scene_.rigid_bodies, contact_, state_.rigid_bodies,
                      body_heat_.any() ? body_heat_.surface_temperature(state_.rigid_bodies) : SurfaceTemperature{});
      if (body_heat_.any()) body_heat_.couple_implicitly(grid_, *elapsed);
    }
    last_sink_heat_ =
        conduct_heat(particles_, grid_, shapes_, scene_.materials, colouring_, parallel_, *elapsed, conduction_scratch_);
    // A conducting body takes that heat into its cells under the nodes and conducts it towards its held faces.
    if (body_heat_.any()) body_heat_.deposit_and_advance(grid_, state_.rigid_bodies, *elapsed);
  }
}

void Simulation::advance_clock(double dt) {
  std::swap(particles_.position, position_new_);
  for (auto& r : state_.rigid_bodies) r.displacement += dt * r.velocity;
  state_.last_dt = dt;
  state_.time += dt;
  ++state_.step;
}

// Chips that break off and fly out of the domain are removed rather than stopping the run.
void Simulation::remove_escaped_particles() {
  if (!scene_.solver.remove_escaping_particles) return;
  const Particles& P = particles_;
  const Vec2 lo = grid_.domain_min, hi = grid_.domain_max;
  std::vector<std::size_t> keep;
  keep.reserve(P.size());
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec2 x = P.position[p];
    const bool inside = x.x() >= lo.x() && x.x() <= hi.x() && x.y() >= lo.y() && x.y() <= hi.y();
    if (inside || !std::isfinite(x.x()) || !std::isfinite(x.y())) keep.push_back(p);
  }
  // Nothing left to simulate is not a result: a run would go on to a "complete" end with zero forces. The last
  // particles stay (the failure's snapshot shows them) and are not counted as removed: particles + removed_particles
  // is the count the run started with.
  if (keep.empty() && P.size() > 0)
    throw SimulationError(fmt::format("every particle has left the grid domain by step {}, time {:.6g} s ({} removed "
                                      "before, the last {} now outside it): nothing is left to simulate (is a body "
                                      "placed outside the grid, or thrown out of it?)",
                                      state_.step, state_.time, state_.removed_particles, P.size()));
  if (keep.size() == P.size()) return;
  for (std::size_t p = 0, k = 0; p < P.size(); ++p) {
    if (k < keep.size() && keep[k] == p) {
      ++k;
      continue;
    }
    ++state_.removed_particles;
    state_.removed_mass += P.mass[p];
    // Their energy leaves the ledger's kinetic and elastic sums; booked here so the balance closes.
    state_.energy.removed_energy += 0.5 * inertia_factor_ * P.mass[p] * P.velocity[p].squaredNorm() +
                                    materials_[P.material[p]]->elastic_energy(P, p);
  }
  particles_.permute(keep);
}

void Simulation::check_guards() const {
  mpmcut::check_guards(particles_, grid_, scene_, contact_, state_.rigid_bodies, state_.step, state_.time, parallel_);
}

// ---------------------------------------------------------------------------------------------
// Time step

double Simulation::stable_time_step() const {
  if (scene_.solver.fixed_time_step > 0.0) return scene_.solver.fixed_time_step;
  double dt = mechanical_time_step();
  // Explicit conduction: dt <= h^2/(4 alpha) in 2D, with the same CFL safety factor.
  if (conduction_.enabled()) dt = std::min(dt, conduction_.time_step_limit());
  return dt;
}

// CFL limit of the momentum equation: cfl h / (c + |v|), where mass scaling slows the waves to
// c / sqrt(f) (the stiffness is physical, the inertia f times larger).
double Simulation::mechanical_time_step() const {
  const std::size_t n = particles_.size();
  double c_max = 0.0, v_max = 0.0;
#pragma omp parallel for reduction(max : c_max, v_max) schedule(static) if (parallel_)
  for (std::size_t p = 0; p < n; ++p) {
    c_max = std::max(c_max, materials_[particles_.material[p]]->wave_speed(particles_, p));
    v_max = std::max(v_max, particles_.velocity[p].norm());
  }
  for (const auto& r : state_.rigid_bodies) v_max = std::max(v_max, r.velocity.norm());
  return scene_.solver.cfl * grid_.h / (c_max / std::sqrt(inertia_factor_) + v_max);
}

// ---------------------------------------------------------------------------------------------
// Diagnostics

Vec2 Simulation::total_momentum() const {
  const std::size_t n = particles_.size();
  const double f = inertia_factor_;
  const Particles& P = particles_;
  return {deterministic_sum(n, [&](std::size_t p) { return f * P.mass[p] * P.velocity[p].x(); }, parallel_),
          deterministic_sum(n, [&](std::size_t p) { return f * P.mass[p] * P.velocity[p].y(); }, parallel_)};
}

double Simulation::max_temperature() const {
  double t = 0.0;
  for (double T : particles_.temperature) t = std::max(t, T);
  return t;
}

void Simulation::refresh_energy() {
  const std::size_t n = particles_.size();
  const double f = inertia_factor_;  // the kinetic energy of the (scaled) inertia that is integrated
  const Particles& P = particles_;
  state_.energy.kinetic =
      deterministic_sum(n, [&](std::size_t p) { return 0.5 * f * P.mass[p] * P.velocity[p].squaredNorm(); }, parallel_);
  state_.energy.elastic =
      deterministic_sum(n, [&](std::size_t p) { return materials_[P.material[p]]->elastic_energy(P, p); }, parallel_);
}

}  // namespace mpmcut
