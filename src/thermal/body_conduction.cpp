#include "thermal/body_conduction.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/SparseCholesky>

namespace mpmcut {

BodyConduction::BodyConduction(const Vec2& origin, int nx, int ny, double h, std::vector<BodyCell> kinds,
                               double conductivity, double volumetric_heat_capacity, double held_temperature)
    : origin_(origin), nx_(nx), ny_(ny), h_(h), kinds_(std::move(kinds)), conductivity_(conductivity),
      volumetric_heat_capacity_(volumetric_heat_capacity), held_temperature_(held_temperature) {
  if (nx <= 0 || ny <= 0 || h <= 0.0 || kinds_.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny))
    throw std::invalid_argument("BodyConduction: the cell kinds do not fill nx x ny cells of a positive size");
  if (!(conductivity > 0.0) || !(volumetric_heat_capacity >= 0.0))
    throw std::invalid_argument("BodyConduction: the conductivity must be positive, the heat capacity not negative");
  for (int c = 0; c < cell_count(); ++c)
    if (kinds_[c] == BodyCell::Conducting) conducting_.push_back(c);
}

Vec2 BodyConduction::cell_centre(int cell) const {
  return origin_ + h_ * Vec2((cell % nx_) + 0.5, (cell / nx_) + 0.5);
}

int BodyConduction::body_cell_near(const Vec2& x) const {
  const int i = static_cast<int>(std::floor((x.x() - origin_.x()) / h_));
  const int j = static_cast<int>(std::floor((x.y() - origin_.y()) / h_));
  int best = -1;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int dj = -2; dj <= 2; ++dj) {
    for (int di = -2; di <= 2; ++di) {
      const int ii = i + di, jj = j + dj;
      if (ii < 0 || jj < 0 || ii >= nx_ || jj >= ny_) continue;
      const int c = jj * nx_ + ii;
      if (kinds_[c] == BodyCell::Outside) continue;
      const double d2 = (cell_centre(c) - x).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = c;
    }
  }
  return best;
}

std::vector<double> BodyConduction::initial_field() const {
  return std::vector<double>(kinds_.size(), held_temperature_);
}

double BodyConduction::stable_step() const { return h_ * h_ * volumetric_heat_capacity_ / (4.0 * conductivity_); }

double BodyConduction::advance(std::vector<double>& field, const std::vector<double>& heat, double dt) const {
  if (dt <= 0.0) return 0.0;
  if (volumetric_heat_capacity_ <= 0.0) throw std::logic_error("BodyConduction::advance on a body without heat capacity");
  const int substeps = static_cast<int>(std::ceil(dt / (0.9 * stable_step())));
  const double dt_sub = dt / substeps;
  const double capacity = volumetric_heat_capacity_ * h_ * h_;  // J/(K m) per cell
  // Between two cells' centres the face is h long and h away: the conductance is k h / h = k, W/(K m).
  const double k = conductivity_;
  double out = 0.0;
  for (int c = 0; c < cell_count(); ++c)
    if (kinds_[c] == BodyCell::Held) out += heat[c];  // what enters a held cell leaves through it
  std::vector<double> rate(conducting_.size());
  const int offsets[4] = {-1, 1, -nx_, nx_};
  for (int s = 0; s < substeps; ++s) {
    for (std::size_t m = 0; m < conducting_.size(); ++m) {
      const int c = conducting_[m];
      const int i = c % nx_;
      double q = heat[c] / dt;
      for (int f = 0; f < 4; ++f) {
        if ((f == 0 && i == 0) || (f == 1 && i == nx_ - 1)) continue;
        const int nb = c + offsets[f];
        if (nb < 0 || nb >= cell_count() || kinds_[nb] == BodyCell::Outside) continue;  // adiabatic face
        const double flow = k * (field[nb] - field[c]);
        q += flow;
        if (kinds_[nb] == BodyCell::Held) out -= flow * dt_sub;
      }
      rate[m] = q;
    }
    for (std::size_t m = 0; m < conducting_.size(); ++m) field[conducting_[m]] += dt_sub * rate[m] / capacity;
  }
  return out;
}

double BodyConduction::stored_heat(const std::vector<double>& field) const {
  double sum = 0.0;
  for (const int c : conducting_) sum += field[c] - held_temperature_;
  return sum * volumetric_heat_capacity_ * h_ * h_;
}

struct BodyConduction::SteadySolver {
  std::vector<int> unknown;  // per cell: its row among the conducting cells, -1 for the others
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
};

void BodyConduction::solve_steady(const std::vector<double>& heat_rate, double held, std::vector<double>& field) const {
  const int offsets[4] = {-1, 1, -nx_, nx_};
  auto neighbour = [&](int c, int f) {  // -1 beyond the box or outside the body
    const int i = c % nx_;
    if ((f == 0 && i == 0) || (f == 1 && i == nx_ - 1)) return -1;
    const int nb = c + offsets[f];
    return nb < 0 || nb >= cell_count() || kinds_[nb] == BodyCell::Outside ? -1 : nb;
  };
  if (!steady_) {
    auto solver = std::make_shared<SteadySolver>();
    solver->unknown.assign(kinds_.size(), -1);
    for (std::size_t m = 0; m < conducting_.size(); ++m) solver->unknown[conducting_[m]] = static_cast<int>(m);
    std::vector<Eigen::Triplet<double>> entries;
    for (std::size_t m = 0; m < conducting_.size(); ++m) {
      const int c = conducting_[m];
      for (int f = 0; f < 4; ++f) {
        const int nb = neighbour(c, f);
        if (nb < 0) continue;
        entries.emplace_back(static_cast<int>(m), static_cast<int>(m), conductivity_);
        if (kinds_[nb] == BodyCell::Conducting) entries.emplace_back(static_cast<int>(m), solver->unknown[nb], -conductivity_);
      }
    }
    const auto n = static_cast<Eigen::Index>(conducting_.size());
    Eigen::SparseMatrix<double> K(n, n);
    K.setFromTriplets(entries.begin(), entries.end());
    solver->ldlt.compute(K);
    bool bounded = solver->ldlt.info() == Eigen::Success;
    for (Eigen::Index m = 0; bounded && m < n; ++m) bounded = solver->ldlt.vectorD()(m) > 1e-12 * conductivity_;
    if (!bounded)
      throw std::invalid_argument("a conducting rigid body has cells with no path to a held face: its steady "
                                  "temperature would be unbounded (hold a face that reaches every part of it)");
    steady_ = std::move(solver);
  }
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(conducting_.size()));
  for (std::size_t m = 0; m < conducting_.size(); ++m) {
    const int c = conducting_[m];
    double b = heat_rate[c];
    for (int f = 0; f < 4; ++f) {
      const int nb = neighbour(c, f);
      if (nb >= 0 && kinds_[nb] == BodyCell::Held) b += conductivity_ * held;
    }
    rhs(static_cast<Eigen::Index>(m)) = b;
  }
  const Eigen::VectorXd T = steady_->ldlt.solve(rhs);
  for (std::size_t m = 0; m < conducting_.size(); ++m) field[conducting_[m]] = T(static_cast<Eigen::Index>(m));
  for (int c = 0; c < cell_count(); ++c)
    if (kinds_[c] == BodyCell::Held) field[c] = held;
}

void BodyConduction::steady_field(const std::vector<double>& heat_rate, std::vector<double>& field) const {
  solve_steady(heat_rate, held_temperature_, field);
}

void BodyConduction::steady_rise(const std::vector<double>& heat_rate, std::vector<double>& rise) const {
  rise.assign(kinds_.size(), 0.0);  // outside cells stay 0
  solve_steady(heat_rate, 0.0, rise);
}

}  // namespace mpmcut
