#pragma once
// Everything a material is made of: its name, its constitutive model, and the parameters of each
// physics model it uses (elastic, thermal, Johnson-Cook flow stress, equation of state, damage),
// each model's struct with its own parameter table. The one rule set for them is here: the input
// reader reports a broken rule at the key in the file, the physics constructors refuse a material
// that breaks one (std::invalid_argument), both from parameter_problems().
#include <functional>
#include <string>
#include <vector>

#include "physics/damage_parameters.hpp"
#include "physics/elastic_parameters.hpp"
#include "physics/equation_of_state_parameters.hpp"
#include "physics/flow_stress_parameters.hpp"
#include "physics/thermal_parameters.hpp"

namespace mpmcut {

enum class MaterialModel { Elastic, JohnsonCook };

// The models' parameters are bases, so that each model's constructor takes its own struct and the
// keys read as flat fields (m.jc_A), as in the input file.
struct MaterialParameters : ElasticParameters,
                            ThermalParameters,
                            FlowStressParameters,
                            EquationOfStateParameters,
                            DamageParameters {
  std::string name;      // as referenced by bodies
  std::string citation;  // where the numbers come from
  MaterialModel model = MaterialModel::Elastic;

  // Elastic P-wave speed sqrt((K + 4G/3)/rho) at the reference density, K the equation of state's there, m/s
  double p_wave_speed() const;
  // Thermal diffusivity k / (rho c), m^2/s (0 for a material without heat capacity)
  double thermal_diffusivity() const {
    return density > 0.0 && specific_heat > 0.0 ? thermal_conductivity / (density * specific_heat) : 0.0;
  }

  bool operator==(const MaterialParameters&) const = default;  // field-wise, for round-trip tests
};

// The material's own parameter: which constitutive model.
const ParameterTable<MaterialParameters>& material_model_table();

// Calls f(table) with every parameter table of a material, in the order of the input file:
// model, elastic, thermal, flow stress, equation of state, damage.
template <class F>
void for_each_parameter_table(F&& f) {
  f(material_model_table());
  f(elastic_parameter_table());
  f(thermal_parameter_table());
  f(flow_stress_parameter_table());
  f(equation_of_state_parameter_table());
  f(damage_parameter_table());
}

bool in_use(InUse use, const MaterialParameters& m);
// The switch in words, for messages and docs: "model = \"johnson_cook\"".
std::string_view describe(InUse use);

// A key given in place of a parameter, converted with the material's other parameters:
// fracture_toughness K_IC -> fracture_energy G_f.
struct AlternativeKey {
  std::string_view key;
  std::string_view replaces;  // the parameter's key
  std::string_view unit;
  Range range;
  std::string_view doc;
  double (*convert)(double value, const MaterialParameters& m);
  // The other parameters the conversion reads, named in the error when the converted value is out of its range.
  std::string (*inputs)(const MaterialParameters& m);
};
const std::vector<AlternativeKey>& alternative_keys();

// G_f = K_IC^2 (1 - nu^2) / E (plane strain, LEFM; Mabrouki et al. 2008), J/m^2.
double fracture_energy_from_toughness(double toughness_Pa_sqrt_m, double youngs_modulus, double poisson_ratio);

// A broken rule: the key, what it must be (for "must be <allowed>") and the value it has.
struct ParameterProblem {
  std::string key;
  std::string allowed;
  double value = 0.0;
  bool is_flag = false;  // value is 0 or 1 for false or true
};
// The value as a message shows it: "true" for a flag, the number otherwise.
std::string shown_value(const ParameterProblem& p);
// What is checked: everything (the input reader), or the model's limits only, without the ranges'
// caps (the physics constructors; Parameter::max_is_cap).
enum class Check { Input, ModelLimits };
// The rules of one table that `m` breaks, in table order (defined for the tables above).
template <class P>
std::vector<ParameterProblem> parameter_problems(const ParameterTable<P>& table, const MaterialParameters& m,
                                                 Check check = Check::Input);
// Every rule of every table that `m` breaks, in table order (empty: a usable material).
std::vector<ParameterProblem> parameter_problems(const MaterialParameters& m, Check check = Check::Input);

// Throws std::invalid_argument naming the material, the key, what is allowed and the value, for
// the first problem; nothing when there is none.
void throw_first_problem(const MaterialParameters& m, const std::vector<ParameterProblem>& problems);
// The check of the physics constructors: a whole material (Material), or the tables a model uses
// (JohnsonCookDamage: the damage table), so that a model can be built and tested on its own.
inline void require_valid(const MaterialParameters& m) {
  throw_first_problem(m, parameter_problems(m, Check::ModelLimits));
}
template <class... P>
void require_valid(const MaterialParameters& m, const ParameterTable<P>&... tables) {
  std::vector<ParameterProblem> problems;
  (..., [&] {
    auto more = parameter_problems(tables, m, Check::ModelLimits);
    problems.insert(problems.end(), more.begin(), more.end());
  }());
  throw_first_problem(m, problems);
}

}  // namespace mpmcut
