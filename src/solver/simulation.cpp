// The explicit MPM step (Sulsky 1994 USL / Sulsky, Zhou & Schreyer 1995 MUSL) with uGIMP or
// linear shape functions, multi-velocity-field rigid contact with Coulomb friction and grid
// heat conduction. step() reads like the algorithm; each stage is one function below.
#include "solver/simulation.hpp"

#include "contact/contact_law.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace mpmcut {

namespace {
constexpr std::size_t kSumChunk = 4096;  // particles per partial sum (fixed: thread-count independent)
constexpr int kStripRows = 4;            // grid rows per colouring strip (>= 2 so even strips never share nodes)
}  // namespace

// ---------------------------------------------------------------------------------------------
// Construction

Simulation::Simulation(const Scene& scene) : scene_(scene) {
  grid_.build(scene_.grid);
  for (const auto& m : scene_.materials) materials_.push_back(make_material(m));
  for (const auto& b : scene_.bodies)
    shapes_.emplace_back(scene_.solver.shape_function, grid_.h, b.particles_per_cell);
  for (const auto& r : scene_.rigid_bodies) {
    rigid_geometry_.emplace_back(r.polygon, r.rounding_radius);
    RigidBodyState st;
    st.name = r.name;
    st.velocity = r.velocity;
    rigid_.push_back(st);
  }
  for (const auto& r : scene_.rigid_bodies) has_friction_ = has_friction_ || r.friction > 0.0;
  particle_contact_ = scene_.solver.contact_detection == ContactDetection::Particle;
  conduction_limit_ = std::numeric_limits<double>::infinity();
  for (const auto& m : scene_.materials) {
    if (m.thermal_conductivity <= 0.0 || m.specific_heat <= 0.0) continue;
    const double alpha = m.thermal_conductivity / (m.density * m.specific_heat);
    conduction_limit_ = std::min(conduction_limit_, scene_.solver.cfl * grid_.h * grid_.h / (4.0 * alpha));
  }
  double max_density = 0.0;
  for (const auto& m : scene_.materials) max_density = std::max(max_density, m.density);
  // MPM3D's cut-off (1e-5 rho h^3 in 3D), per unit thickness here.
  build_particles();
  sort_particles_by_cell();
  inertia_factor_ = resolve_mass_scaling();
  node_mass_cutoff_ = 1e-5 * inertia_factor_ * max_density * grid_.h * grid_.h;

  // Boundary flags on the domain sides and on the padding beyond them.
  const int il = Grid::kPadding, ir = grid_.nx - 1 - Grid::kPadding;
  const int jb = Grid::kPadding, jt = grid_.ny - 1 - Grid::kPadding;
  auto mark = [&](BoundaryKind kind, bool x_side, auto in_side) {
    if (kind == BoundaryKind::Free) return;
    const std::uint8_t bits = kind == BoundaryKind::Fixed ? 3 : (x_side ? 1 : 2);
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i)
        if (in_side(i, j)) grid_.fixed[grid_.index(i, j)] |= bits;
  };
  mark(scene_.boundaries.left, true, [&](int i, int) { return i <= il; });
  mark(scene_.boundaries.right, true, [&](int i, int) { return i >= ir; });
  mark(scene_.boundaries.bottom, false, [&](int, int j) { return j <= jb; });
  mark(scene_.boundaries.top, false, [&](int, int j) { return j >= jt; });
  auto mark_temperature = [&](const std::optional<double>& T, auto in_side) {
    if (!T) return;
    for (int j = 0; j < grid_.ny; ++j)
      for (int i = 0; i < grid_.nx; ++i)
        if (in_side(i, j)) {
          grid_.fixed[grid_.index(i, j)] |= 4;
          grid_.fixed_temperature[grid_.index(i, j)] = *T;
        }
  };
  mark_temperature(scene_.thermal.left, [&](int i, int) { return i <= il; });
  mark_temperature(scene_.thermal.right, [&](int i, int) { return i >= ir; });
  mark_temperature(scene_.thermal.bottom, [&](int, int j) { return j <= jb; });
  mark_temperature(scene_.thermal.top, [&](int, int j) { return j >= jt; });
  refresh_energy();
  energy_.initial = energy_.kinetic + energy_.elastic;
}

void Simulation::build_particles() {
  // Particles sit on a regular sub-grid aligned with the background grid: ppc per direction
  // per cell, each owning a square of side h/ppc (its uGIMP domain).
  for (std::size_t b = 0; b < scene_.bodies.size(); ++b) {
    const BodySpec& body = scene_.bodies[b];
    const int mat = scene_.material_index(body.material);
    if (mat < 0) throw std::invalid_argument("body '" + body.name + "' uses unknown material '" + body.material + "'");
    const double d = grid_.h / body.particles_per_cell;
    Vec2 lo, hi;
    body.shape.bounds(lo, hi);
    const long k0 = static_cast<long>(std::floor((lo.x() - grid_.domain_min.x()) / d));
    const long k1 = static_cast<long>(std::ceil((hi.x() - grid_.domain_min.x()) / d));
    const long l0 = static_cast<long>(std::floor((lo.y() - grid_.domain_min.y()) / d));
    const long l1 = static_cast<long>(std::ceil((hi.y() - grid_.domain_min.y()) / d));
    const double rho = scene_.materials[mat].density;
    for (long l = l0; l < l1; ++l)
      for (long k = k0; k < k1; ++k) {
        const Vec2 x = grid_.domain_min + d * Vec2(k + 0.5, l + 0.5);
        if (!body.shape.contains(x)) continue;
        particles_.add(x, body.velocity, rho * d * d, d * d, body.temperature, static_cast<int>(b), mat);
      }
  }
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

// Physically reorders particles by cell (row-major) so neighbours in space are neighbours in
// memory; done every few steps, it keeps P2G/G2P cache friendly.
void Simulation::sort_particles_by_cell() {
  const std::size_t n = particles_.size();
  std::vector<long> key(n);
  for (std::size_t p = 0; p < n; ++p) {
    const Vec2 u = cell_units(particles_.position[p]);
    key[p] = static_cast<long>(std::floor(u.y())) * grid_.nx + static_cast<long>(std::floor(u.x()));
  }
  std::vector<std::size_t> order(n);
  for (std::size_t p = 0; p < n; ++p) order[p] = p;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  particles_.permute(order);
}

// ---------------------------------------------------------------------------------------------
// The step

void Simulation::step(double max_dt) {
  parallel_ = particles_.size() >= parallel_min_particles_;
  const double dt = std::min(stable_time_step(), max_dt);
  if (step_ % 20 == 0) sort_particles_by_cell();
  // Conduction is sub-cycled: its explicit limit h^2/(4 alpha) is thousands of mechanical steps
  // for metals, so it runs once per conduction_substeps_ steps over the time they covered.
  conduct_now_ = scene_.thermal.conduction &&
                 (++steps_since_conduction_ >= conduction_substeps_ || conduction_elapsed_ + 2 * dt > conduction_limit_);
  particles_to_grid();
  apply_grid_boundary_conditions(true);
  for (auto& r : rigid_) r.step_impulse = Vec2::Zero();
  contact_records_.clear();
  friction_box_lo_ = Vec2::Constant(std::numeric_limits<double>::max());
  friction_box_hi_ = Vec2::Constant(-std::numeric_limits<double>::max());
  if (!rigid_.empty() && particle_contact_) compute_particle_contact_weights();
  apply_rigid_contact(grid_.velocity, dt, ContactPass::AfterP2G);
  update_grid_momentum(dt);
  apply_rigid_contact(grid_.velocity_new, dt, ContactPass::AfterUpdate);
  grid_to_particles(dt);
  if (!rigid_.empty()) push_particles_out_of_rigid_bodies(dt);
  if (scene_.solver.scheme == TimeScheme::MUSL) remap_momentum_musl();
  update_particle_stress(dt);
  if (has_friction_) deposit_frictional_heat();
  if (scene_.thermal.conduction) {
    conduction_elapsed_ += dt;
    if (conduct_now_) {
      conduct_heat(conduction_elapsed_);
      conduction_elapsed_ = 0.0;
      steps_since_conduction_ = 0;
    }
  }
  std::swap(particles_.position, position_new_);
  for (std::size_t r = 0; r < rigid_.size(); ++r) rigid_[r].displacement += dt * rigid_[r].velocity;
  dt_ = dt;
  time_ += dt;
  ++step_;
  if (scene_.solver.remove_escaping_particles) remove_escaped_particles();
  check_guards();
}

// Safeguard behind the grid contact: a particle whose new position lies inside a rigid body
// (possible at a sharp edge, where neighbouring nodes have different normals) is moved back to
// the surface and its approach velocity removed. The momentum this takes counts as contact
// impulse on the rigid body, like the grid corrections.
void Simulation::push_particles_out_of_rigid_bodies(double dt) {
  Particles& P = particles_;
  const std::size_t n = P.size();
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    const RigidPolygon& geom = rigid_geometry_[r];
    const Vec2 shift = rigid_[r].displacement + dt * rigid_[r].velocity;  // where it is at the end of the step
    const Vec2 lo = geom.lower() + shift, hi = geom.upper() + shift;
    const Vec2 vr = rigid_[r].velocity;
    std::vector<std::size_t> inside;
#pragma omp parallel if (parallel_)
    {
      std::vector<std::size_t> mine;
#pragma omp for schedule(static) nowait
      for (std::size_t p = 0; p < n; ++p) {
        const Vec2 x = position_new_[p];
        if (x.x() < lo.x() || x.x() > hi.x() || x.y() < lo.y() || x.y() > hi.y()) continue;
        Vec2 normal;
        if (geom.signed_distance(x - shift, normal) < 0.0) mine.push_back(p);
      }
#pragma omp critical
      inside.insert(inside.end(), mine.begin(), mine.end());
    }
    std::sort(inside.begin(), inside.end());  // fixed order: deterministic sums
    Vec2 impulse = Vec2::Zero();
    double work = 0.0, lost = 0.0;
    for (std::size_t p : inside) {
      Vec2 normal;
      const double d = geom.signed_distance(position_new_[p] - shift, normal);
      position_new_[p] -= (d - 1e-9 * grid_.h) * normal;  // onto the surface, a hair outside
      const double vn = (P.velocity[p] - vr).dot(normal);
      if (vn < 0.0) {
        const Vec2 dp = -inertia_factor_ * P.mass[p] * vn * normal;
        P.velocity[p] -= vn * normal;
        impulse += dp;
        contact_records_.push_back({static_cast<int>(r), 2, position_new_[p], normal, dp, false});
        work += dp.dot(vr);
        // Removing the approach velocity relative to the body is a perfectly inelastic impact:
        // the particle's kinetic energy changes by dp.vr - m vn^2 / 2, so m vn^2 / 2 is lost.
        lost += 0.5 * inertia_factor_ * P.mass[p] * vn * vn;
      }
      ++pushed_out_particles_;
    }
    rigid_[r].step_impulse -= impulse;
    rigid_[r].force = rigid_[r].step_impulse / dt;
    rigid_[r].impulse -= impulse;
    rigid_[r].work += work;
    energy_.external_work += work;
    energy_.contact_safeguard += lost;
  }
}

// Frictional work found at contact nodes heats the particles there: node i's heat q_i goes to
// particle p in proportion to S_ip m_p c_p, so that sum_p m_p c_p dT_p = sum_i q_i exactly.
// The workpiece surface cannot be heated by friction beyond its melting temperature: a molten
// film would carry no shear, so that part of the frictional heat is taken to flow into the tool
// (it stays in the friction work, not in the workpiece's heat).
void Simulation::deposit_frictional_heat() {
  Particles& P = particles_;
  const Grid& G = grid_;
  const std::size_t n = P.size();
  if (friction_box_lo_.x() > friction_box_hi_.x()) return;  // no frictional heat this step
  // Only particles whose stencil can reach a heated node (2 cells around the heated box).
  const Vec2 lo = friction_box_lo_ - Vec2::Constant(2.0), hi = friction_box_hi_ + Vec2::Constant(2.0);
  deposited_heat_.assign(n, 0.0);
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t p = 0; p < n; ++p) {
    const Vec2 u = cell_units(P.position[p]);
    if (u.x() < lo.x() || u.x() > hi.x() || u.y() < lo.y() || u.y() > hi.y()) continue;
    Stencil st;
    shape_of(p).evaluate(u.x(), u.y(), st);
    double dT = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        const int node = G.index(st.i0 + a, st.j0 + c);
        if (st.w[a][c] != 0.0 && G.friction_heat[node] > 0.0) dT += st.w[a][c] * G.friction_heat[node] / G.heat_capacity[node];
      }
    const MaterialParameters& mat = scene_.materials[P.material[p]];
    if (mat.melting_temperature > 0.0) dT = std::clamp(mat.melting_temperature - P.temperature[p], 0.0, dT);
    P.temperature[p] += dT;
    deposited_heat_[p] = P.mass[p] * mat.specific_heat * dT;
  }
  energy_.heat += deterministic_sum(n, [&](std::size_t p) { return deposited_heat_[p]; });
}

// Chips that break off and fly out of the domain are removed rather than stopping the run.
void Simulation::remove_escaped_particles() {
  const Particles& P = particles_;
  const Vec2 lo = grid_.domain_min, hi = grid_.domain_max;
  std::vector<std::size_t> keep;
  keep.reserve(P.size());
  for (std::size_t p = 0; p < P.size(); ++p) {
    const Vec2 x = P.position[p];
    const bool inside = x.x() >= lo.x() && x.x() <= hi.x() && x.y() >= lo.y() && x.y() <= hi.y();
    if (inside || !std::isfinite(x.x()) || !std::isfinite(x.y())) {
      keep.push_back(p);
    } else {
      ++removed_particles_;
      removed_mass_ += P.mass[p];
      // Their energy leaves the ledger's kinetic and elastic sums; booked here so the balance closes.
      energy_.removed_energy += 0.5 * inertia_factor_ * P.mass[p] * P.velocity[p].squaredNorm() +
                                materials_[P.material[p]]->elastic_energy(P, p);
    }
  }
  if (keep.size() != P.size()) particles_.permute(keep);
}

double Simulation::stable_time_step() const {
  if (scene_.solver.fixed_time_step > 0.0) return scene_.solver.fixed_time_step;
  double dt = mechanical_time_step();
  // Explicit conduction: dt <= h^2/(4 alpha) in 2D, with the same CFL safety factor.
  if (scene_.thermal.conduction) dt = std::min(dt, conduction_limit_);
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
  for (const auto& r : rigid_) v_max = std::max(v_max, r.velocity.norm());
  return scene_.solver.cfl * grid_.h / (c_max / std::sqrt(inertia_factor_) + v_max);
}

// Groups particles by strips of kStripRows grid rows (counting sort, stable in particle order).
void Simulation::bucket_particles_by_strip() {
  const std::size_t n = particles_.size();
  const int strips = grid_.ny / kStripRows + 1;
  std::vector<int> strip_of(n);
  strip_begin_.assign(strips + 1, 0);
  for (std::size_t p = 0; p < n; ++p) {
    const double lp_cells = shape_of(p).half_width() / grid_.h;
    const int j0 = static_cast<int>(std::floor(cell_units(particles_.position[p]).y() - lp_cells));
    strip_of[p] = std::clamp(j0, 0, grid_.ny - 1) / kStripRows;
    ++strip_begin_[strip_of[p] + 1];
  }
  for (int s = 0; s < strips; ++s) strip_begin_[s + 1] += strip_begin_[s];
  strip_order_.resize(n);
  std::vector<std::size_t> fill(strip_begin_.begin(), strip_begin_.end() - 1);
  for (std::size_t p = 0; p < n; ++p) strip_order_[fill[strip_of[p]]++] = p;
}

// Scatter to the grid without atomics: strips of rows are coloured even/odd; strips of one
// colour never share a node, so they run in parallel. Each node always receives its
// contributions in the same order, whatever the number of threads: bit-identical results.
template <class F>
void Simulation::for_each_particle_coloured(F&& scatter) {
  const int strips = static_cast<int>(strip_begin_.size()) - 1;
  for (int colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, 1) if (parallel_)
    for (int s = colour; s < strips; s += 2)
      for (std::size_t k = strip_begin_[s]; k < strip_begin_[s + 1]; ++k) scatter(strip_order_[k]);
  }
}

template <class F>
double Simulation::deterministic_sum(std::size_t n, F&& f) const {
  const std::size_t chunks = (n + kSumChunk - 1) / kSumChunk;
  std::vector<double> partial(chunks, 0.0);
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t c = 0; c < chunks; ++c) {
    double s = 0.0;
    const std::size_t end = std::min(n, (c + 1) * kSumChunk);
    for (std::size_t i = c * kSumChunk; i < end; ++i) s += f(i);
    partial[c] = s;
  }
  double total = 0.0;
  for (double s : partial) total += s;
  return total;
}

void Simulation::particles_to_grid() {
  grid_.reset();
  bucket_particles_by_strip();
  const bool thermal = conduct_now_;
  const bool heat_capacity = thermal || has_friction_;
  const bool has_rigid = !rigid_.empty();  // the position check needs sum S m x
  const Vec2 b = scene_.body_force;
  Particles& P = particles_;
  Grid& G = grid_;
  for_each_particle_coloured([&](std::size_t p) {
    Stencil st;
    const Vec2 u = cell_units(P.position[p]);
    shape_of(p).evaluate(u.x(), u.y(), st);
    const double m = inertia_factor_ * P.mass[p];  // inertial (scaled) mass
    const Vec2 mv = m * P.velocity[p];
    const Mat2 sigma = P.stress[p].in_plane();
    const double V = P.volume[p];
    // Heat capacity from the true mass: mass scaling changes inertia only.
    const double mc = heat_capacity ? P.mass[p] * scene_.materials[P.material[p]].specific_heat : 0.0;
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        const double w = st.w[a][c];
        const Vec2 grad(st.dwdx[a][c], st.dwdy[a][c]);
        if (w == 0.0 && grad.x() == 0.0 && grad.y() == 0.0) continue;
        const int n = G.index(st.i0 + a, st.j0 + c);
        G.mass[n] += w * m;
        G.momentum[n] += w * mv;
        G.force[n] += -V * (sigma * grad) + (w * m) * b;
        if (has_rigid) G.mass_position[n] += (w * m) * P.position[p];
        if (heat_capacity) G.heat_capacity[n] += w * mc;
        if (thermal) G.temperature[n] += w * mc * P.temperature[p];  // sum S m c T; divided below
      }
  });
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t n = 0; n < nn; ++n) {
    G.velocity[n] = G.mass[n] > 0.0 ? Vec2(G.momentum[n] / G.mass[n]) : Vec2::Zero();
    if (thermal) G.temperature[n] = G.heat_capacity[n] > 0.0 ? G.temperature[n] / G.heat_capacity[n] : 0.0;
  }
}

// Zero the constrained velocity components at fixed and roller nodes. With momentum_only the
// P2G velocities are constrained; otherwise the updated velocities and the forces.
void Simulation::apply_grid_boundary_conditions(bool momentum_only) {
  Grid& G = grid_;
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t n = 0; n < nn; ++n) {
    const std::uint8_t f = G.fixed[n];
    if ((f & 3) == 0) continue;
    for (int d = 0; d < 2; ++d) {
      if (!(f & (1 << d))) continue;
      if (momentum_only) {
        G.velocity[n][d] = 0.0;  // the raw P2G momentum stays: FLIP sees the constraint as a change
      } else {
        G.force[n][d] = 0.0;
        G.velocity_new[n][d] = 0.0;
      }
    }
  }
}

void Simulation::update_grid_momentum(double dt) {
  Grid& G = grid_;
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t n = 0; n < nn; ++n) {
    // From the velocity (which carries the first contact pass), not the raw P2G momentum.
    // Nodes lighter than the cut-off keep their velocity: a / m there would be noise.
    const bool has_mass = G.mass[n] > node_mass_cutoff_;
    G.velocity_new[n] = has_mass ? Vec2(G.velocity[n] + dt * G.force[n] / G.mass[n]) : G.velocity[n];
  }
  apply_grid_boundary_conditions(false);
}

// Contact detected from the particles rather than the nodes: a particle is in contact with a rigid
// body when its uGIMP domain reaches the surface (signed distance of its centre d <= lp), fading
// linearly to out of contact at d = lp + contact_distance_cells h. A node's contact weight is the
// share of its mass carried by particles in contact, sum S m phi / sum S m, and its normal is the
// mass-weighted mean of their exact surface normals. Both move smoothly with the rigid body
// across the grid, instead of switching when the tool crosses a node line.
void Simulation::compute_particle_contact_weights() {
  const Particles& P = particles_;
  const Grid& G = grid_;
  const std::size_t nn = G.node_count();
  contact_weight_.resize(rigid_.size());
  contact_normal_.resize(rigid_.size());
  const double band = scene_.solver.contact_distance_cells * G.h;
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    std::vector<double>& W = contact_weight_[r];
    std::vector<Vec2>& N = contact_normal_[r];
    W.assign(nn, 0.0);
    N.assign(nn, Vec2::Zero());
    const RigidPolygon& geom = rigid_geometry_[r];
    const Vec2 shift = rigid_[r].displacement;
    const Vec2 lo = geom.lower() + shift - Vec2::Constant(2.0 * G.h), hi = geom.upper() + shift + Vec2::Constant(2.0 * G.h);
    for (std::size_t p = 0; p < P.size(); ++p) {
      const Vec2 x = P.position[p];
      if (x.x() < lo.x() || x.x() > hi.x() || x.y() < lo.y() || x.y() > hi.y()) continue;
      Vec2 normal;
      const double lp = shape_of(p).half_width();
      const double d = geom.signed_distance(x - shift, normal);
      const double phi = band > 0.0 ? std::clamp(1.0 - (d - lp) / band, 0.0, 1.0) : (d <= lp ? 1.0 : 0.0);
      if (phi <= 0.0) continue;
      Stencil st;
      const Vec2 u = cell_units(x);
      shape_of(p).evaluate(u.x(), u.y(), st);
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) {
          const double w = st.w[a][c];
          if (w == 0.0) continue;
          const int n = G.index(st.i0 + a, st.j0 + c);
          const double m = inertia_factor_ * P.mass[p];  // as the grid mass it is compared with
          W[n] += w * m * phi;
          N[n] += (w * m * phi) * normal;
        }
    }
  }
}

// Multi-velocity-field contact with rigid bodies (Bardenhagen et al. 2000; Nairn's rigid
// form): a rigid body has infinite mass, so at a contact node only the material's velocity
// changes. Contact holds where the material approaches the rigid surface and its mean
// position at the node lies within contact_distance_cells of it (no one-cell gap). The normal
// is the exact outward normal of the rigid outline. Normal approach is removed; the
// tangential slip is reduced by at most mu times the normal change (Coulomb stick/slip).
// With accumulate_force (the passes after P2G and after the momentum update, whose corrections
// reach the particles) the impulse on each rigid body, its work and the frictional work are
// recorded; the force of a step is the sum of both passes' impulses over dt.
void Simulation::apply_rigid_contact(std::vector<Vec2>& v, double dt, ContactPass pass) {
  if (rigid_.empty()) return;
  Grid& G = grid_;
  const bool accumulate_force = pass != ContactPass::MuslRemap;
  if (pass == ContactPass::AfterUpdate) std::fill(G.in_contact.begin(), G.in_contact.end(), 0);
  const double cutoff = scene_.solver.contact_distance_cells * G.h;
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    const RigidPolygon& geom = rigid_geometry_[r];
    const Vec2 shift = rigid_[r].displacement;
    const Vec2 vr = rigid_[r].velocity;
    const double mu = scene_.rigid_bodies[r].friction;
    // Only nodes near the rigid body's bounding box can be in contact.
    const Vec2 lo = (geom.lower() + shift - grid_.origin) / G.h - Vec2::Constant(2.0);
    const Vec2 hi = (geom.upper() + shift - grid_.origin) / G.h + Vec2::Constant(2.0);
    const int i0 = std::max(0, static_cast<int>(std::floor(lo.x())));
    const int i1 = std::min(G.nx - 1, static_cast<int>(std::ceil(hi.x())));
    const int j0 = std::max(0, static_cast<int>(std::floor(lo.y())));
    const int j1 = std::min(G.ny - 1, static_cast<int>(std::ceil(hi.y())));
    Vec2 impulse = Vec2::Zero();
    double work = 0.0, friction_work = 0.0;
    // Rows in a fixed order, columns in parallel per row: deterministic sums.
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const int n = G.index(i, j);
        const double m = G.mass[n];
        if (m <= node_mass_cutoff_ || (G.fixed[n] & 3)) continue;  // never change BC nodes
        const Vec2 xbar = G.mass_position[n] / m;
        Vec2 normal;
        double weight = 1.0;
        if (particle_contact_) {
          weight = std::min(1.0, contact_weight_[r][n] / m);
          if (weight <= 0.0) continue;
          const double nn = contact_normal_[r][n].norm();
          if (nn <= 0.0) continue;
          normal = contact_normal_[r][n] / nn;
        } else {
          const double dist = geom.signed_distance(xbar - shift, normal);
          if (dist > cutoff) continue;
        }
        const Vec2 rel = v[n] - vr;
        const double vn = rel.dot(normal);
        if (pass == ContactPass::MuslRemap) {
          // Only where the momentum update found contact, and there whatever the sign: the
          // strain update must see the same constraint that moved the particles (an approach
          // test here lets the strain velocity disagree with the motion and creates energy).
          if (!G.in_contact[n]) continue;
        } else if (vn >= 0.0) {
          continue;  // separating
        }
        if (pass == ContactPass::AfterUpdate) G.in_contact[n] = 1;
        const ContactCorrection cc = coulomb_rigid_correction(rel, normal, mu, weight);
        const Vec2& new_rel = cc.new_relative;
        const Vec2 dv = new_rel - rel;
        v[n] = vr + new_rel;
        if (accumulate_force) {
          const Vec2 dp = m * dv;  // momentum given to the material by the rigid body
          impulse += dp;
          contact_records_.push_back({static_cast<int>(r), pass == ContactPass::AfterP2G ? 0 : 1, xbar, normal, dp,
                                      cc.sliding});
          work += dp.dot(vr);
          // Frictional work = friction impulse x the slip that goes on (Coulomb force times slip
          // distance); sticking does no frictional work. It becomes heat in the deformable body at
          // this node (a rigid tool takes none). The rest of the kinetic energy the correction
          // removes at the node is the velocity jump of imposing contact on the grid; with FLIP
          // it is not lost by the particles, so it is not counted as a dissipation (counting it
          // overstated friction heat and broke the energy balance of a cut by ~15%).
          const double q = m * cc.friction_dv * cc.slip_after;
          friction_work += q;
          G.friction_heat[n] += q;
          if (q > 0.0) {
            friction_box_lo_ = friction_box_lo_.cwiseMin(Vec2(i, j));
            friction_box_hi_ = friction_box_hi_.cwiseMax(Vec2(i, j));
          }
        }
      }
    }
    if (accumulate_force) {
      rigid_[r].step_impulse -= impulse;
      rigid_[r].force = rigid_[r].step_impulse / dt;
      rigid_[r].impulse -= impulse;
      rigid_[r].work += work;
      energy_.external_work += work;
      energy_.friction += friction_work;

    }
  }
}

void Simulation::grid_to_particles(double dt) {
  Particles& P = particles_;
  const Grid& G = grid_;
  const std::size_t n = P.size();
  position_new_.resize(n);
  transfer_loss_.resize(n);
  const double flip = scene_.solver.flip_fraction;
  const Vec2 b = scene_.body_force;
  // Work of the body force, sum m_p b.(v_old + v_new)/2 dt = b.(P_old + P_new)/2 dt, from the
  // total momenta (fixed-chunk sums): an OpenMP reduction would make it vary from run to run.
  const bool body_force = b.x() != 0.0 || b.y() != 0.0;
  const Vec2 momentum_old = body_force ? total_momentum() : Vec2::Zero();
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t p = 0; p < n; ++p) {
    Stencil st;
    const Vec2 u = cell_units(P.position[p]);
    shape_of(p).evaluate(u.x(), u.y(), st);
    Vec2 v_pic = Vec2::Zero(), dv = Vec2::Zero();
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        const double w = st.w[a][c];
        if (w == 0.0) continue;
        const int node = G.index(st.i0 + a, st.j0 + c);
        v_pic += w * G.velocity_new[node];
        // FLIP increment from the raw P2G velocity, so the particles receive the contact and
        // boundary corrections of both passes: momentum given = contact impulse + f dt.
        const Vec2 v_p2g = G.momentum[node] / G.mass[node];  // w > 0, so the node has mass
        dv += w * (G.velocity_new[node] - v_p2g);
      }
    const Vec2 v_flip = P.velocity[p] + dv;
    const Vec2 v_new = flip * v_flip + (1.0 - flip) * v_pic;
    // The grid's work reaches the particles through the FLIP increment; the PIC share replaces the
    // part of the particle velocity the grid does not carry, and that kinetic energy is lost
    // (docs/cutting.md, "Energy balance").
    transfer_loss_[p] = 0.5 * inertia_factor_ * P.mass[p] * (v_flip.squaredNorm() - v_new.squaredNorm());
    P.velocity[p] = v_new;
    position_new_[p] = P.position[p] + dt * v_pic;
  }
  if (body_force) energy_.external_work += b.dot(0.5 * (momentum_old + total_momentum())) * dt;
  energy_.transfer_dissipation += deterministic_sum(n, [&](std::size_t p) { return transfer_loss_[p]; });
}

// MUSL: the updated particle momenta are mapped back to the grid (same weights as this step's
// P2G), constrained again, and give the velocity used for the strain update.
void Simulation::remap_momentum_musl() {
  Particles& P = particles_;
  Grid& G = grid_;
  std::fill(G.momentum.begin(), G.momentum.end(), Vec2::Zero());
  for_each_particle_coloured([&](std::size_t p) {
    Stencil st;
    const Vec2 u = cell_units(P.position[p]);
    shape_of(p).evaluate(u.x(), u.y(), st);
    const Vec2 mv = inertia_factor_ * P.mass[p] * P.velocity[p];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        if (st.w[a][c] != 0.0) G.momentum[G.index(st.i0 + a, st.j0 + c)] += st.w[a][c] * mv;
  });
  const std::size_t nn = G.node_count();
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t n = 0; n < nn; ++n)
    G.velocity_new[n] = G.mass[n] > 0.0 ? Vec2(G.momentum[n] / G.mass[n]) : Vec2::Zero();
  apply_grid_boundary_conditions(false);
  apply_rigid_contact(G.velocity_new, 0.0, ContactPass::MuslRemap);
}

void Simulation::update_particle_stress(double dt) {
  Particles& P = particles_;
  const Grid& G = grid_;
  const std::size_t n = P.size();
  increments_.resize(n);
  StepContext ctx;
  ctx.dt = dt;
  ctx.cell_size = G.h;
  ctx.inertia_factor = inertia_factor_;
#pragma omp parallel for schedule(static, 512) if (parallel_)  // interleaved: the chip's costly plastic particles are contiguous (sorted by cell)
  for (std::size_t p = 0; p < n; ++p) {
    Stencil st;
    const Vec2 u = cell_units(P.position[p]);
    shape_of(p).evaluate(u.x(), u.y(), st);
    Mat2 L = Mat2::Zero();
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        const Vec2 grad(st.dwdx[a][c], st.dwdy[a][c]);
        if (grad.x() == 0.0 && grad.y() == 0.0) continue;
        L += G.velocity_new[G.index(st.i0 + a, st.j0 + c)] * grad.transpose();
      }
    P.velocity_gradient[p] = L;
    P.deformation_gradient[p] = (Mat2::Identity() + dt * L) * P.deformation_gradient[p];
    P.volume[p] = P.deformation_gradient[p].determinant() * P.initial_volume[p];
    increments_[p] = materials_[P.material[p]]->update(P, p, L, ctx);
  }
  energy_.plastic_work += deterministic_sum(n, [&](std::size_t p) { return increments_[p].plastic_work; });
  energy_.heat += deterministic_sum(n, [&](std::size_t p) { return increments_[p].heat; });
  energy_.damage_dissipation +=
      deterministic_sum(n, [&](std::size_t p) { return increments_[p].damage_dissipation; });
  energy_.viscous += deterministic_sum(n, [&](std::size_t p) { return increments_[p].viscous_dissipation; });
}

// Explicit heat conduction on the grid (Nairn's transport task structure): nodal
// temperature from P2G, conductive nodal heat rate -sum V k gradS . gradT_p, fixed-temperature
// nodes, and temperature increments (not values) back to the particles to avoid smearing.
void Simulation::conduct_heat(double dt) {
  Particles& P = particles_;
  Grid& G = grid_;
  const std::size_t n = P.size();
  // Particle temperature gradient from the nodal temperatures, and its conductive flux
  // scattered back (the nodal temperatures are only read here, the heat rates only written).
  for_each_particle_coloured([&](std::size_t p) {
    Stencil st;
    const Vec2 u = cell_units(P.position[p]);
    shape_of(p).evaluate(u.x(), u.y(), st);
    Vec2 grad_T = Vec2::Zero();
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        grad_T += G.temperature[G.index(st.i0 + a, st.j0 + c)] * Vec2(st.dwdx[a][c], st.dwdy[a][c]);
    const double k = scene_.materials[P.material[p]].thermal_conductivity;
    const Vec2 flux = -k * grad_T;  // W/m^2
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        G.heat_rate[G.index(st.i0 + a, st.j0 + c)] += P.volume[p] * flux.dot(Vec2(st.dwdx[a][c], st.dwdy[a][c]));
  });
  const std::size_t nn = G.node_count();
  std::vector<double>& dT = G.heat_rate;  // reused: becomes the nodal temperature increment
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t node = 0; node < nn; ++node) {
    if (G.heat_capacity[node] <= 0.0) {
      dT[node] = 0.0;
    } else if (G.fixed[node] & 4) {
      dT[node] = G.fixed_temperature[node] - G.temperature[node];
    } else {
      dT[node] = dt * G.heat_rate[node] / G.heat_capacity[node];
    }
  }
#pragma omp parallel for schedule(static) if (parallel_)
  for (std::size_t p = 0; p < n; ++p) {
    Stencil st;
    const Vec2 u = cell_units(P.position[p]);
    shape_of(p).evaluate(u.x(), u.y(), st);
    double inc = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        if (st.w[a][c] != 0.0) inc += st.w[a][c] * dT[G.index(st.i0 + a, st.j0 + c)];
    P.temperature[p] += inc;
  }
}

// ---------------------------------------------------------------------------------------------
// Diagnostics and guards

Vec2 Simulation::total_momentum() const {
  const std::size_t n = particles_.size();
  const double f = inertia_factor_;
  return {deterministic_sum(n, [&](std::size_t p) { return f * particles_.mass[p] * particles_.velocity[p].x(); }),
          deterministic_sum(n, [&](std::size_t p) { return f * particles_.mass[p] * particles_.velocity[p].y(); })};
}

double Simulation::max_temperature() const {
  double t = 0.0;
  for (double T : particles_.temperature) t = std::max(t, T);
  return t;
}

void Simulation::refresh_energy() {
  const std::size_t n = particles_.size();
  const double f = inertia_factor_;  // the kinetic energy of the (scaled) inertia that is integrated
  energy_.kinetic =
      deterministic_sum(n, [&](std::size_t p) { return 0.5 * f * particles_.mass[p] * particles_.velocity[p].squaredNorm(); });
  energy_.elastic = deterministic_sum(
      n, [&](std::size_t p) { return materials_[particles_.material[p]]->elastic_energy(particles_, p); });
}

// Stops the run the moment a particle carries a NaN or leaves the domain, or sinks more than
// a cell into a rigid body; the message names step, time, particle, body and field.
void Simulation::check_guards() const {
  const Particles& P = particles_;
  const std::size_t n = P.size();
  const Vec2 lo = grid_.domain_min, hi = grid_.domain_max;
  long bad = -1;
#pragma omp parallel for schedule(static) reduction(max : bad) if (parallel_)
  for (std::size_t p = 0; p < n; ++p) {
    const PlaneStrainTensor& s = P.stress[p];
    const bool finite = std::isfinite(P.position[p].x()) && std::isfinite(P.position[p].y()) &&
                        std::isfinite(P.velocity[p].x()) && std::isfinite(P.velocity[p].y()) &&
                        std::isfinite(s.xx + s.yy + s.zz + s.xy) && std::isfinite(P.temperature[p]) &&
                        std::isfinite(P.volume[p]);
    const Vec2 x = P.position[p];
    const bool inside = x.x() >= lo.x() && x.x() <= hi.x() && x.y() >= lo.y() && x.y() <= hi.y();
    if (!finite || !inside) bad = std::max(bad, static_cast<long>(p));
  }
  const auto where = [&](std::size_t p) {
    return fmt::format("step {}, time {:.6g} s, particle {} of body '{}' at ({:.6g}, {:.6g}) m", step_, time_, p,
                       scene_.bodies[P.body[p]].name, P.position[p].x(), P.position[p].y());
  };
  if (bad >= 0) {
    // Report the first offending particle, deterministically.
    for (std::size_t p = 0; p < n; ++p) {
      const PlaneStrainTensor& s = P.stress[p];
      const char* field = nullptr;
      if (!std::isfinite(P.position[p].x()) || !std::isfinite(P.position[p].y())) field = "position";
      else if (!std::isfinite(P.velocity[p].x()) || !std::isfinite(P.velocity[p].y())) field = "velocity";
      else if (!std::isfinite(s.xx + s.yy + s.zz + s.xy)) field = "stress";
      else if (!std::isfinite(P.temperature[p])) field = "temperature";
      else if (!std::isfinite(P.volume[p])) field = "volume";
      if (field) throw SimulationError(fmt::format("non-finite {} at {}", field, where(p)));
      const Vec2 x = P.position[p];
      if (x.x() < lo.x() || x.x() > hi.x() || x.y() < lo.y() || x.y() > hi.y())
        throw SimulationError(fmt::format("particle left the grid domain [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] m at {}",
                                          lo.x(), hi.x(), lo.y(), hi.y(), where(p)));
    }
  }
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    const RigidPolygon& geom = rigid_geometry_[r];
    const Vec2 shift = rigid_[r].displacement;
    const Vec2 blo = geom.lower() + shift, bhi = geom.upper() + shift;
    for (std::size_t p = 0; p < n; ++p) {
      const Vec2 x = P.position[p];
      if (x.x() < blo.x() || x.x() > bhi.x() || x.y() < blo.y() || x.y() > bhi.y()) continue;
      Vec2 normal;
      const double d = geom.signed_distance(x - shift, normal);
      if (d < -grid_.h)
        throw SimulationError(fmt::format("particle penetrated rigid body '{}' by {:.3g} m (more than a cell) at {}",
                                          rigid_[r].name, -d, where(p)));
    }
  }
}

}  // namespace mpmcut
