#pragma once
// The particle fields of a running simulation as NumPy arrays that view the structure-of-arrays
// storage (core/particles.hpp) without copying (docs/python.md, "Particle fields").
//
// Lifetime: the solver reorders the particles every few steps (which moves every array), so a view
// is valid until the next step only. Every view of one call holds a guard object; stepping while a
// guard is still referenced raises instead of leaving the views dangling. Copy what you keep
// (numpy.array(view)). The views are read-only: observers read the simulation, they never change it.
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/particles.hpp"

namespace mpmcut::python {

class ParticleViews {
 public:
  // A dict {field name: read-only ndarray} over `particles`; `owner` (the Python Run) is kept
  // alive by the arrays.
  pybind11::dict views(const Particles& particles, pybind11::handle owner);
  // Throws std::runtime_error when views handed out since the last step are still referenced.
  void check_released() const;
  // Registers the guard's Python type (once, in the module's initialisation).
  static void bind(pybind11::module_& m);
  // The field names, in the order views() lists them.
  static std::vector<std::string> names();
  // Each field's unit as output names write it (m_per_s, Pa, K, kg_per_m, m3_per_m; "" dimensionless, "id" an
  // index), per m of thickness where extensive.
  static pybind11::dict units();

 private:
  pybind11::object guard_;  // a weak reference to the guard of the last views() call
};

}  // namespace mpmcut::python
