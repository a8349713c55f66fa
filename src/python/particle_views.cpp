#include "python/particle_views.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace mpmcut::python {

namespace {

// How one particle's value of a field lies in memory: the array dimensions after the particle
// index, and their strides in bytes.
template <class T>
struct ElementLayout {  // double, std::int32_t: one number
  static std::vector<py::ssize_t> shape() { return {}; }
  static std::vector<py::ssize_t> strides() { return {}; }
  using Number = T;
};
template <>
struct ElementLayout<Vec2> {
  static std::vector<py::ssize_t> shape() { return {2}; }
  static std::vector<py::ssize_t> strides() { return {sizeof(double)}; }
  using Number = double;
};
template <>
struct ElementLayout<Mat2> {  // Eigen's Matrix2d is column-major: (row r, column c) at r + 2c
  static std::vector<py::ssize_t> shape() { return {2, 2}; }
  static std::vector<py::ssize_t> strides() { return {sizeof(double), 2 * sizeof(double)}; }
  using Number = double;
};
template <>
struct ElementLayout<PlaneStrainTensor> {  // xx, yy, zz, xy (core/tensor.hpp)
  static std::vector<py::ssize_t> shape() { return {4}; }
  static std::vector<py::ssize_t> strides() { return {sizeof(double)}; }
  using Number = double;
};
static_assert(sizeof(Vec2) == 2 * sizeof(double) && sizeof(Mat2) == 4 * sizeof(double) &&
              sizeof(PlaneStrainTensor) == 4 * sizeof(double));

// fn(name, array) for every particle field, in the order of the registry (core/particle_fields.hpp).
template <class Fn>
void for_each_field(const Particles& p, Fn&& fn) {
  for_each_particle_field([&](const auto& f) { fn(std::string(f.info.name), p.*f.array); });
}

// The base object of the views: keeps the Run alive; its death tells the Run that the views are gone.
struct ViewGuard {
  py::object owner;
};

}  // namespace

void ParticleViews::bind(py::module_& m) { py::class_<ViewGuard>(m, "_ParticleViewGuard"); }

std::vector<std::string> ParticleViews::names() {
  std::vector<std::string> out;
  for_each_field(Particles{}, [&](const std::string& name, const auto&) { out.push_back(name); });
  return out;
}

py::dict ParticleViews::units() {
  py::dict out;
  for_each_particle_field([&](const auto& f) { out[py::str(std::string(f.info.name))] = std::string(f.info.unit); });
  return out;
}

py::dict ParticleViews::views(const Particles& particles, py::handle owner) {
  py::object guard = py::cast(ViewGuard{py::reinterpret_borrow<py::object>(owner)});
  guard_ = py::module_::import("weakref").attr("ref")(guard);
  py::dict out;
  const py::ssize_t n = static_cast<py::ssize_t>(particles.size());
  for_each_field(particles, [&](const std::string& name, const auto& array) {
    using T = typename std::decay_t<decltype(array)>::value_type;
    using Layout = ElementLayout<T>;
    std::vector<py::ssize_t> shape{n}, strides{static_cast<py::ssize_t>(sizeof(T))};
    for (py::ssize_t d : Layout::shape()) shape.push_back(d);
    for (py::ssize_t s : Layout::strides()) strides.push_back(s);
    py::array a(py::dtype::of<typename Layout::Number>(), shape, strides, array.data(), guard);
    a.attr("setflags")(py::arg("write") = false);
    out[py::str(name)] = a;
  });
  return out;
}

void ParticleViews::check_released() const {
  if (guard_ && !guard_().is_none())
    throw std::runtime_error(
        "particle field views from before this step are still referenced: the solver reorders the particles "
        "while stepping, which would leave them dangling. Copy what you keep (numpy.array(view)) and drop the "
        "views (del) before stepping on");
}

}  // namespace mpmcut::python
