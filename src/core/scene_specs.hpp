#pragma once
// The plain-data parts of a scene (solver/scene.hpp) that the lower layers use: grid, shapes,
// bodies, boundaries, solver and output settings. All quantities SI unless the name says otherwise.
#include <optional>
#include <string>
#include <vector>

#include "core/tensor.hpp"

namespace mpmcut {

enum class ShapeFunctionKind { Linear, UGimp };
enum class TimeScheme { USL, MUSL };
// How rigid contact finds the material in contact (docs/cutting.md, "Contact"): Node, the node's material
// position within contact_distance_cells of the surface; Particle, the share of the node's mass whose
// particle domains reach the surface; Gap, the gap between the surface and the nearest particle domain of
// the node, which the material may close within the step but not cross.
enum class ContactDetection { Node, Particle, Gap, Penalty };
// The volumetric strain rate a particle's constitutive update sees (docs/solver.md, "Volumetric averaging"): its
// own (Off), or a mass-weighted average through the nodes around it, with the mean stress of the internal force
// projected the same way (Nodal): against volumetric locking of plastic flow that does not follow the grid.
enum class VolumetricAverage { Off, Nodal };
enum class BoundaryKind { Free, Fixed, Roller };  // Roller = slip: normal velocity zero

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

// A deformable body filled with particles on a regular sub-grid of the background grid, or on that sub-grid turned
// by lattice_angle_deg about lattice_origin (a turned body's sides then run along particle rows, not in steps).
struct BodySpec {
  std::string name;
  Shape shape;
  std::string material;          // name of a material of the scene
  int particles_per_cell = 2;    // per direction
  double lattice_angle_deg = 0.0;     // the particle lattice's turn against the grid, counter-clockwise
  std::optional<Vec2> lattice_origin;  // a corner of the lattice's squares; none: the grid's min corner
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
  // Share of the frictional work at this body that heats the deformable body; the rest flows into
  // this body, which is not thermally modelled (a heat sink at its own temperature), -
  double friction_heat_share = 1.0;
  // Heat transfer coefficient between this body's surface and the deformable material in contact with
  // it, W/(m^2 K); 0 = an adiabatic surface. The body itself stays at `temperature` (a heat sink).
  double heat_transfer_coefficient = 0.0;
  double temperature = 298.0;  // K, uniform and constant; used where heat_transfer_coefficient > 0
  // A conducting body (conductivity > 0) has a temperature field of its own (thermal/body_conduction): it starts
  // at `temperature` and is held there in its cells along the outline's edges listed in held_faces (edge k runs
  // from vertex k to vertex k + 1, the last back to the first), where it is mounted; heat enters it from the
  // material through heat_transfer_coefficient. 0 = the body stays at `temperature` (a heat sink).
  // With a volumetric heat capacity the field is transient; without one (0) it is steady: the field the heat input,
  // averaged over the last heat_averaging_time, would settle to (a tool long in the cut).
  double conductivity = 0.0;              // W/(m K)
  double volumetric_heat_capacity = 0.0;  // rho c, J/(m^3 K); 0 = a steady body
  double heat_averaging_time = 0.0;       // s; > 0 for a steady conducting body
  std::vector<int> held_faces;

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
  // With contact_detection = Particle: particles within lp + this many cells of the surface are in
  // contact (fully up to lp), and a node takes the share of its mass they carry (docs/cutting.md).
  // Not used with contact_detection = Gap.
  double contact_distance_cells = 0.5;  // -
  // Mass scaling (docs/mass_scaling.md): the deformable bodies' inertia is multiplied by a factor
  // f >= 1, which lengthens the CFL step by sqrt(f). Heat capacity, conduction, the equation of
  // state and all times stay physical. Either a fixed factor or a target time step (the factor
  // is then chosen at the start so that the stable step reaches it); 1 and 0 = off.
  double mass_scaling_factor = 1.0;            // f, -
  double mass_scaling_target_time_step = 0.0;  // s; 0 = no target
  ContactDetection contact_detection = ContactDetection::Node;
  // With contact_detection = Penalty: the normal stiffness of a particle against a rigid surface,
  // k = penalty_stiffness m / dt^2 per unit overlap of its domain (m its inertial mass, dt the step);
  // the overlap at a contact pressure p is then about 8 C^2 p / (penalty_stiffness rho c^2) of the
  // particle's half-width (C the CFL number): small, and a fixed share of the particle on every grid.
  double penalty_stiffness = 1.0;  // -
  VolumetricAverage volumetric_average = VolumetricAverage::Off;

  bool operator==(const SolverSpec&) const = default;  // field-wise, for round-trip tests
};

struct OutputSpec {
  double snapshot_interval = 0.0;  // s between VTU snapshots; 0 = first and last only
  double history_interval = 0.0;   // s between history rows; 0 = every step
  bool vtu = true;

  bool operator==(const OutputSpec&) const = default;  // field-wise, for round-trip tests
};

}  // namespace mpmcut
