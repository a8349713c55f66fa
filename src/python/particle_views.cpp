#include "python/particle_views.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace mpmcut::python {

namespace {

// The view of one field: its name, element layout, and the array's data pointer and element size.
// The field list of core/particles.hpp; when the particle-field registry lands, this table comes from it.
struct FieldView {
  const char* name;
  py::dtype dtype;
  std::vector<py::ssize_t> element_shape;    // after the particle index
  std::vector<py::ssize_t> element_strides;  // bytes
  const void* data;
  py::ssize_t element_bytes;
};

template <class T>
FieldView scalar(const char* name, const std::vector<T>& v) {
  return {name, py::dtype::of<T>(), {}, {}, v.data(), static_cast<py::ssize_t>(sizeof(T))};
}
FieldView vec2(const char* name, const std::vector<Vec2>& v) {
  return {name, py::dtype::of<double>(), {2}, {sizeof(double)}, v.data(), sizeof(Vec2)};
}
// Eigen's Matrix2d is column-major: (row r, column c) at r + 2c.
FieldView mat2(const char* name, const std::vector<Mat2>& v) {
  return {name, py::dtype::of<double>(), {2, 2}, {sizeof(double), 2 * sizeof(double)}, v.data(), sizeof(Mat2)};
}
// xx, yy, zz, xy in that order (core/tensor.hpp).
FieldView tensor(const char* name, const std::vector<PlaneStrainTensor>& v) {
  return {name, py::dtype::of<double>(), {4}, {sizeof(double)}, v.data(), sizeof(PlaneStrainTensor)};
}

std::vector<FieldView> fields(const Particles& p) {
  return {vec2("position", p.position),
          vec2("velocity", p.velocity),
          mat2("velocity_gradient", p.velocity_gradient),
          mat2("deformation_gradient", p.deformation_gradient),
          scalar("mass", p.mass),
          scalar("volume", p.volume),
          scalar("initial_volume", p.initial_volume),
          tensor("stress", p.stress),
          tensor("effective_stress", p.effective_stress),
          scalar("plastic_strain", p.plastic_strain),
          scalar("plastic_strain_rate", p.plastic_strain_rate),
          scalar("temperature", p.temperature),
          scalar("damage_initiation", p.damage_initiation),
          scalar("damage", p.damage),
          scalar("plastic_displacement", p.plastic_displacement),
          scalar("initiation_yield_stress", p.initiation_yield_stress),
          scalar("fracture_energy", p.fracture_energy),
          scalar("damage_dissipation", p.damage_dissipation),
          scalar("body", p.body),
          scalar("material", p.material)};
}

// The base object of the views: keeps the Run alive; its death tells the Run that the views are gone.
struct ViewGuard {
  py::object owner;
};

}  // namespace

void ParticleViews::bind(py::module_& m) { py::class_<ViewGuard>(m, "_ParticleViewGuard"); }

std::vector<std::string> ParticleViews::names() {
  std::vector<std::string> out;
  for (const FieldView& f : fields(Particles{})) out.push_back(f.name);
  return out;
}

py::dict ParticleViews::views(const Particles& particles, py::handle owner) {
  py::object guard = py::cast(ViewGuard{py::reinterpret_borrow<py::object>(owner)});
  guard_ = py::module_::import("weakref").attr("ref")(guard);
  py::dict out;
  const py::ssize_t n = static_cast<py::ssize_t>(particles.size());
  for (const FieldView& f : fields(particles)) {
    std::vector<py::ssize_t> shape{n}, strides{f.element_bytes};
    shape.insert(shape.end(), f.element_shape.begin(), f.element_shape.end());
    strides.insert(strides.end(), f.element_strides.begin(), f.element_strides.end());
    py::array a(f.dtype, shape, strides, f.data, guard);
    a.attr("setflags")(py::arg("write") = false);
    out[f.name] = a;
  }
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
