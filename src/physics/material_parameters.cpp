#include "physics/material_parameters.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace mpmcut {

double MaterialParameters::p_wave_speed() const {
  // The bulk modulus the equation of state has at the reference density (Mie-Grueneisen: rho0 c0^2), as the
  // material's own wave speed at the start: a fixed step checked against E and nu alone was refused below the
  // run's own limit. The elastic model has no equation of state (its pressure is K from E and nu whatever `eos` says).
  const bool mie_gruneisen = model == MaterialModel::JohnsonCook && eos == EquationOfState::MieGruneisen;
  const double K = mie_gruneisen ? density * mg_c0 * mg_c0 : bulk_modulus();
  return std::sqrt((K + 4.0 * shear_modulus() / 3.0) / density);
}

const ParameterTable<MaterialParameters>& material_model_table() {
  using P = MaterialParameters;
  static const ParameterTable<P> table{
      "constitutive model",
      {choice<P, &P::model>("model", {"elastic", "johnson_cook"},
                            "linear elastic, or Johnson-Cook thermo-visco-plasticity (with damage)")},
      {}};
  return table;
}

bool in_use(InUse use, const MaterialParameters& m) {
  switch (use) {
    case InUse::Always: return true;
    case InUse::JohnsonCook: return m.model == MaterialModel::JohnsonCook;
    case InUse::MieGruneisen: return m.eos == EquationOfState::MieGruneisen;
    // The damage switch is itself in use only for johnson_cook (on an elastic set it is the error, not its keys).
    case InUse::Damage: return m.model == MaterialModel::JohnsonCook && m.damage_enabled;
    case InUse::RateDependentFractureEnergy: return m.fracture_transition_strain_rate > 0.0;
    case InUse::TanhSoftening: return m.model == MaterialModel::JohnsonCook && m.flow_softening == FlowSoftening::Tanh;
  }
  return true;
}

std::string_view describe(InUse use) {
  switch (use) {
    case InUse::Always: return "always";
    case InUse::JohnsonCook: return "model = \"johnson_cook\"";
    case InUse::MieGruneisen: return "eos = \"mie_gruneisen\"";
    case InUse::Damage: return "damage = true";
    case InUse::RateDependentFractureEnergy: return "fracture_transition_strain_rate > 0";
    case InUse::TanhSoftening: return "flow_softening = \"tanh\"";
  }
  return "";
}

double fracture_energy_from_toughness(double toughness_Pa_sqrt_m, double youngs_modulus, double poisson_ratio) {
  return toughness_Pa_sqrt_m * toughness_Pa_sqrt_m * (1.0 - poisson_ratio * poisson_ratio) / youngs_modulus;
}

const std::vector<AlternativeKey>& alternative_keys() {
  // Toughness is what handbooks give; the damage law needs the energy. Converted with the final E
  // and nu of the material (after library overrides).
  static const std::vector<AlternativeKey> keys{
      {"fracture_toughness", "fracture_energy", "Pa sqrt(m)", Range::open_closed(0.0, 1e10, "Pa sqrt(m)"),
       "K_IC; sets G_f = K_IC^2 (1 - nu^2)/E (plane strain), with this material's final E and nu",
       [](double k, const MaterialParameters& m) {
         return fracture_energy_from_toughness(k, m.youngs_modulus, m.poisson_ratio);
       },
       [](const MaterialParameters& m) {
         return fmt::format("youngs_modulus = {:g} Pa and poisson_ratio = {:g}", m.youngs_modulus, m.poisson_ratio);
       }},
  };
  return keys;
}

template <class P>
std::vector<ParameterProblem> parameter_problems(const ParameterTable<P>& table, const MaterialParameters& m,
                                                 Check check) {
  std::vector<ParameterProblem> out;
  const P& p = m;
  // The parameters always in use first: a switch with a wrong value (fracture_transition_strain_rate
  // = 1e308) is reported at itself, not at a parameter it turns on (fracture_energy_brittle).
  std::vector<const Parameter<P>*> rows;
  for (const bool always : {true, false})
    for (const Parameter<P>& row : table.parameters)
      if ((row.use == InUse::Always) == always) rows.push_back(&row);
  for (const Parameter<P>* row_pointer : rows) {
    const Parameter<P>& row = *row_pointer;
    const bool used = in_use(row.use, m);
    switch (row.kind) {
      case Parameter<P>::Kind::Number: {
        Range r = row.range_at(p);
        if (check == Check::ModelLimits) {
          if (row.min_is_cap) r.min = -std::numeric_limits<double>::infinity(), r.min_open = true;
          if (row.max_is_cap) r.max = std::numeric_limits<double>::infinity(), r.max_open = true;
        }
        // Not in use: its default 0 is allowed too (widened, without the note of the used range).
        if (!used) r.min = std::min(r.min, 0.0), r.min_open = false, r.note = "";
        const double x = p.*row.number;
        if (!r.contains(x)) out.push_back({std::string(row.key), r.text(), x});
        break;
      }
      case Parameter<P>::Kind::Flag:
        if (!used && p.*row.flag)
          out.push_back({std::string(row.key), fmt::format("false unless {}", describe(row.use)), 1.0, true});
        break;
      case Parameter<P>::Kind::Choice:
        break;  // the reader accepts only the listed names
    }
  }
  for (const ParameterRule<P>& rule : table.rules)
    if (in_use(rule.use, m) && !rule.holds(p)) {
      double value = 0.0;
      for (const Parameter<P>& row : table.parameters)
        if (row.key == rule.key && row.number) value = p.*row.number;
      out.push_back({std::string(rule.key), std::string(rule.allowed), value});
    }
  return out;
}

template std::vector<ParameterProblem> parameter_problems(const ParameterTable<MaterialParameters>&,
                                                          const MaterialParameters&, Check);
template std::vector<ParameterProblem> parameter_problems(const ParameterTable<ElasticParameters>&,
                                                          const MaterialParameters&, Check);
template std::vector<ParameterProblem> parameter_problems(const ParameterTable<ThermalParameters>&,
                                                          const MaterialParameters&, Check);
template std::vector<ParameterProblem> parameter_problems(const ParameterTable<FlowStressParameters>&,
                                                          const MaterialParameters&, Check);
template std::vector<ParameterProblem> parameter_problems(const ParameterTable<EquationOfStateParameters>&,
                                                          const MaterialParameters&, Check);
template std::vector<ParameterProblem> parameter_problems(const ParameterTable<DamageParameters>&,
                                                          const MaterialParameters&, Check);

std::vector<ParameterProblem> parameter_problems(const MaterialParameters& m, Check check) {
  std::vector<ParameterProblem> problems;
  for_each_parameter_table([&](const auto& table) {
    const std::vector<ParameterProblem> more = parameter_problems(table, m, check);
    problems.insert(problems.end(), more.begin(), more.end());
  });
  return problems;
}

std::string shown_value(const ParameterProblem& p) {
  return p.is_flag ? (p.value != 0.0 ? "true" : "false") : fmt::format("{}", p.value);
}

void throw_first_problem(const MaterialParameters& m, const std::vector<ParameterProblem>& problems) {
  if (problems.empty()) return;
  const ParameterProblem& p = problems.front();
  throw std::invalid_argument(
      fmt::format("material '{}': key '{}': must be {}, got {}", m.name, p.key, p.allowed, shown_value(p)));
}

}  // namespace mpmcut
