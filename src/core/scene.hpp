#pragma once
// The scene: plain data that fully describes a run. Parsing (TOML) produces it, the
// cutting preset produces it, the solver consumes it. The solver never sees TOML.
// All quantities SI unless the name says otherwise.
#include <optional>
#include <string>
#include <vector>

#include "core/tensor.hpp"
#include "cutting/cutting_parameters.hpp"

namespace mpmcut {

enum class ShapeFunctionKind { Linear, UGimp };
enum class TimeScheme { USL, MUSL };
enum class BoundaryKind { Free, Fixed, Roller };  // Roller = slip: normal velocity zero
enum class MaterialModel { Elastic, JohnsonCook };
enum class EquationOfState { Linear, MieGruneisen };
enum class DamageEvolution { Linear, Exponential };

struct MaterialParameters {
  std::string name;                       // as referenced by bodies
  std::string citation;                   // where the numbers come from
  MaterialModel model = MaterialModel::Elastic;
  // Elastic
  double density = 0.0;        // kg/m^3
  double youngs_modulus = 0.0; // Pa
  double poisson_ratio = 0.0;  // -
  // Thermal
  double specific_heat = 0.0;         // J/(kg K)
  double thermal_conductivity = 0.0;  // W/(m K)
  double taylor_quinney = 0.9;        // fraction of plastic work turned into heat, -
  double room_temperature = 298.0;    // T_r, K
  double melting_temperature = 0.0;   // T_m, K
  // Johnson-Cook flow stress: (A + B eps^n)(1 + C ln(epsdot/epsdot0))(1 - T*^m)
  double jc_A = 0.0;  // Pa
  double jc_B = 0.0;  // Pa
  double jc_n = 1.0;  // -
  double jc_C = 0.0;  // -
  double jc_m = 1.0;  // -
  double reference_strain_rate = 1.0;  // epsdot0, 1/s
  // Time scale of the exponential moving average of the plastic strain rate, s (0: no smoothing)
  double strain_rate_smoothing_time = 0.0;
  // Pressure
  EquationOfState eos = EquationOfState::Linear;
  double mg_c0 = 0.0;     // Mie-Grueneisen bulk sound speed, m/s
  double mg_s = 0.0;      // Hugoniot slope s, -
  double mg_gamma0 = 0.0; // Grueneisen coefficient, -
  double bulk_viscosity_linear = 0.0;     // b1, - (0 = off)
  double bulk_viscosity_quadratic = 0.0;  // b2, -
  // Johnson-Cook damage initiation: eps_f = (D1 + D2 exp(D3 eta))(1 + D4 ln epsdot*)(1 + D5 T*)
  bool damage_enabled = false;
  double jc_D1 = 0.0, jc_D2 = 0.0, jc_D3 = 0.0, jc_D4 = 0.0, jc_D5 = 0.0;
  double min_failure_strain = 0.01;  // clamp for eps_f, -
  // No ductile fracture at or below this stress triaxiality eta = -p/q: neither initiation nor softening
  // advance there (Bao & Wierzbicki 2005: -1/3). theory_materials.md §5.7.
  double damage_triaxiality_cutoff = -1.0 / 3.0;
  // Hillerborg evolution after initiation
  DamageEvolution damage_evolution = DamageEvolution::Linear;
  double fracture_energy = 0.0;   // G_f, J/m^2 (or from K_IC); the low-rate value when rate-dependent
  // Ductile-to-brittle transition of the fracture energy with the plastic strain rate at initiation:
  // G_f(rate) = G_b + (G_f - G_b) / (1 + (rate/rate_t)^n)   (theory_materials.md §5.6)
  double fracture_energy_brittle = 0.0;          // G_b, J/m^2 (high-rate limit)
  double fracture_transition_strain_rate = 0.0;  // rate_t, 1/s (0: G_f does not depend on rate)
  double fracture_transition_exponent = 2.0;     // n, -
  double max_damage = 0.999;      // D at which a particle counts as fully failed, -

  double bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  // Elastic P-wave speed sqrt((K + 4G/3)/rho), m/s
  double p_wave_speed() const;

  bool operator==(const MaterialParameters&) const = default;  // field-wise, for round-trip tests
};

struct Rectangle {
  Vec2 min = Vec2::Zero(), max = Vec2::Zero();
  bool operator==(const Rectangle&) const = default;
};
struct Disk {
  Vec2 center = Vec2::Zero();
  double radius = 0.0;
  bool operator==(const Disk&) const = default;
};
struct Polygon {
  std::vector<Vec2> vertices;  // counter-clockwise or clockwise, simple
  bool operator==(const Polygon&) const = default;
};

enum class ShapeKind { Rectangle, Polygon, Disk };

struct Shape {
  ShapeKind kind = ShapeKind::Rectangle;
  Rectangle rectangle;
  Disk disk;
  Polygon polygon;
  bool contains(const Vec2& x) const;
  // Axis-aligned bounding box.
  void bounds(Vec2& lo, Vec2& hi) const;

  bool operator==(const Shape&) const = default;  // field-wise, for round-trip tests
};

// A deformable body filled with particles on a regular sub-grid of the background grid.
struct BodySpec {
  std::string name;
  Shape shape;
  std::string material;          // name of a MaterialParameters
  int particles_per_cell = 2;    // per direction
  Vec2 velocity = Vec2::Zero();  // initial, m/s
  double temperature = 298.0;    // initial, K

  bool operator==(const BodySpec&) const = default;  // field-wise, for round-trip tests
};

// A rigid body: exact geometry (signed distance and normal), prescribed velocity. Its shape is
// the polygon grown by rounding_radius (every corner becomes an arc of that radius, e.g. a
// cutting edge radius); with rounding_radius = 0 it is the polygon itself.
struct RigidBodySpec {
  std::string name;
  Polygon polygon;               // the rigid body's outline at t = 0 (its core when rounded)
  double rounding_radius = 0.0;  // m
  Vec2 velocity = Vec2::Zero();  // prescribed, m/s
  double friction = 0.0;         // Coulomb coefficient against deformable bodies, -

  bool operator==(const RigidBodySpec&) const = default;  // field-wise, for round-trip tests
};

struct GridSpec {
  double cell_size = 0.0;  // h, m
  Vec2 min = Vec2::Zero(); // lower-left corner of the domain, m
  Vec2 max = Vec2::Zero(); // upper-right corner, m

  bool operator==(const GridSpec&) const = default;  // field-wise, for round-trip tests
};

struct BoundarySpec {
  BoundaryKind left = BoundaryKind::Free;
  BoundaryKind right = BoundaryKind::Free;
  BoundaryKind bottom = BoundaryKind::Free;
  BoundaryKind top = BoundaryKind::Free;

  bool operator==(const BoundarySpec&) const = default;  // field-wise, for round-trip tests
};

struct ThermalSpec {
  bool conduction = false;
  // Fixed temperature per side, K; empty = insulated.
  std::optional<double> left, right, bottom, top;

  bool operator==(const ThermalSpec&) const = default;  // field-wise, for round-trip tests
};

// Largest mass scaling factor accepted (the step grows by sqrt(f): 1000x at most).
inline constexpr double kMaxMassScalingFactor = 1e6;

struct SolverSpec {
  ShapeFunctionKind shape_function = ShapeFunctionKind::UGimp;
  TimeScheme scheme = TimeScheme::MUSL;
  double cfl = 0.4;             // -
  double flip_fraction = 0.99;  // FLIP/PIC blend, 1 = pure FLIP
  double end_time = 0.0;        // s
  long max_steps = 0;           // 0 = unlimited
  double fixed_time_step = 0.0; // s; 0 = adaptive from CFL
  // Particles that leave the grid domain are removed (with a count in the summary) instead of
  // stopping the run: for chips that break off and fly away.
  bool remove_escaping_particles = false;
  // Rigid contact acts at a node when the material's mass-weighted mean position there lies
  // closer to the rigid surface than this many cells (position check, no one-cell gap).
  double contact_distance_cells = 0.5;  // -
  // Mass scaling (docs/mass_scaling.md): the deformable bodies' inertia is multiplied by a factor
  // f >= 1, which lengthens the CFL step by sqrt(f). Heat capacity, conduction, the equation of
  // state and all times stay physical. Either a fixed factor or a target time step (the factor
  // is then chosen at the start so that the stable step reaches it); 1 and 0 = off.
  double mass_scaling_factor = 1.0;            // f, -
  double mass_scaling_target_time_step = 0.0;  // s; 0 = no target

  bool operator==(const SolverSpec&) const = default;  // field-wise, for round-trip tests
};

struct OutputSpec {
  double snapshot_interval = 0.0;  // s between VTU snapshots; 0 = first and last only
  double history_interval = 0.0;   // s between history rows; 0 = every step
  bool vtu = true;

  bool operator==(const OutputSpec&) const = default;  // field-wise, for round-trip tests
};

struct Scene {
  std::string title;
  std::string source_file;  // where it came from, for messages
  GridSpec grid;
  BoundarySpec boundaries;
  ThermalSpec thermal;
  SolverSpec solver;
  OutputSpec output;
  Vec2 body_force = Vec2::Zero();  // gravity-like acceleration, m/s^2
  std::vector<MaterialParameters> materials;
  std::vector<BodySpec> bodies;
  std::vector<RigidBodySpec> rigid_bodies;
  // Set when the scene was built by the cutting preset: the process it stands for (the solver
  // ignores it; the cutting outputs read it). The tool is rigid_bodies[0].
  std::optional<CuttingParameters> cutting;

  // Index of the material called `name`, or -1.
  int material_index(const std::string& name) const;

  bool operator==(const Scene&) const = default;  // field-wise, for round-trip tests
};

}  // namespace mpmcut
