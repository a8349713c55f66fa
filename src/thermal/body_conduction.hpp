#pragma once
// Heat conduction inside a rigid body (the cutting tool) on square cells fixed to the body: finite
// volumes, adiabatic along the body's free outline, held at one temperature in the cells along the
// faces where the body is mounted, heated in its surface cells by what the material's conduction
// update gave to it (solver/rigid_body_heat couples the two). Either transient (explicit steps with
// the body's heat capacity) or steady (the field that a constant heat input would settle to: a linear
// solve). docs/cutting.md, "Contact", item 7.
#include <cstdint>
#include <memory>
#include <vector>

#include "core/tensor.hpp"

namespace mpmcut {

enum class BodyCell : std::uint8_t { Outside, Conducting, Held };

class BodyConduction {
 public:
  BodyConduction() = default;
  // nx x ny cells of size h from `origin` (their lower-left corner, in the body's frame at t = 0), their kinds
  // row by row (i fastest); conductivity k, W/(m K); volumetric heat capacity rho c, J/(m^3 K); the held cells'
  // temperature, which is also the whole body's at t = 0, K.
  // A volumetric heat capacity of 0 makes a body that can only be steady (advance and stable_step refuse it).
  BodyConduction(const Vec2& origin, int nx, int ny, double h, std::vector<BodyCell> kinds, double conductivity,
                 double volumetric_heat_capacity, double held_temperature);

  bool active() const { return !kinds_.empty(); }
  int cell_count() const { return static_cast<int>(kinds_.size()); }
  BodyCell kind(int cell) const { return kinds_[cell]; }
  Vec2 cell_centre(int cell) const;
  double cell_size() const { return h_; }
  double volumetric_heat_capacity() const { return volumetric_heat_capacity_; }
  double held_temperature() const { return held_temperature_; }
  // The cell of the body (conducting or held) that contains x, or else the one nearest to x within two cells;
  // -1 where there is none.
  int body_cell_near(const Vec2& x) const;

  // The field at t = 0: the held temperature in every cell (outside cells included, unused).
  std::vector<double> initial_field() const;
  // Explicit stability limit of one update, h^2 rho c / (4 k), s.
  double stable_step() const;
  // Advances `field` over dt in as many explicit steps as stability needs; heat[cell] (J/m) enters each cell at a
  // constant rate over dt; held cells keep their temperature. Returns the heat that left the body through its held
  // cells over dt, J/m.
  double advance(std::vector<double>& field, const std::vector<double>& heat, double dt) const;
  // Heat stored above the held temperature, sum rho c h^2 (T - T_held) over the conducting cells, J/m.
  double stored_heat(const std::vector<double>& field) const;
  // The steady field under a constant heat input heat_rate[cell], W/m: the sum of the flows k (T_nb - T) into each
  // conducting cell plus its input is zero, held cells at the held temperature (input there leaves through them).
  // The matrix is factorised on the first call. Throws std::invalid_argument where conducting cells have no path
  // to a held cell (their steady temperature would be unbounded).
  void steady_field(const std::vector<double>& heat_rate, std::vector<double>& field) const;
  // The steady rise above the held temperature under heat_rate[cell], W/m (the linear part of steady_field): its
  // response to a heat input, K per W/m.
  void steady_rise(const std::vector<double>& heat_rate, std::vector<double>& rise) const;

 private:
  Vec2 origin_ = Vec2::Zero();
  int nx_ = 0, ny_ = 0;
  double h_ = 0.0;
  std::vector<BodyCell> kinds_;
  double conductivity_ = 0.0, volumetric_heat_capacity_ = 0.0, held_temperature_ = 0.0;
  std::vector<int> conducting_;  // the conducting cells' indices
  struct SteadySolver;           // the factorised steady matrix (Eigen), built on first use
  mutable std::shared_ptr<SteadySolver> steady_;
  // The steady field with the held cells at `held`.
  void solve_steady(const std::vector<double>& heat_rate, double held, std::vector<double>& field) const;
};

}  // namespace mpmcut
