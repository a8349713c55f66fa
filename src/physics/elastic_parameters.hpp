#pragma once
// The elastic constants of a material (every model has them): the struct and its parameter table.
#include "physics/parameter_table.hpp"

namespace mpmcut {

struct ElasticParameters {
  double density = 0.0;         // rho_0, kg/m^3
  double youngs_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;   // nu, -

  double bulk_modulus() const { return youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)); }
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }

  bool operator==(const ElasticParameters&) const = default;
};

// Upper bounds of all tables are caps (Parameter::max_is_cap) unless marked as the model's limit.
inline const ParameterTable<ElasticParameters>& elastic_parameter_table() {
  using P = ElasticParameters;
  static const ParameterTable<P> table{
      "elastic constants",
      {
          number("density", &P::density, "kg/m^3", Range::open_closed(0.0, 1e5), "rho_0, reference density").required_key(),
          number("youngs_modulus", &P::youngs_modulus, "Pa", Range::open_closed(0.0, 1e13), "E").required_key(),
          number("poisson_ratio", &P::poisson_ratio, "-", Range::open(-1.0, 0.5), "nu")
              .required_key()
              .model_limit_above(),
      },
      {}};
  return table;
}

}  // namespace mpmcut
