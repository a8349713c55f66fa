// Property-based fuzz of the whole input surface (docs/reliability.md, "Input fuzz"): every key of
// every shipped case in cases/ (the keys written in the file, every key of the expanded scene,
// every [cutting] preset key) is set through --set to each hostile value below, and the real
// program (`mpmcut run --check`) must exit 2 within 5 s with a message naming the key, or, where
// the value is legitimately allowed (kAllowed), accept it and then really start and finish a
// 2-step run. Never a crash, a hang, or a result directory that looks complete.
#include <gtest/gtest.h>

#include <toml++/toml.h>

#include <algorithm>
#include <set>
#include <sstream>

#include "cli.hpp"
#include "cutting/cutting_input.hpp"
#include "run/case_loading.hpp"
#include "io/scene_writer.hpp"

namespace mpmcut::testing {
namespace {

const std::vector<std::string> kHostileValues = {"\"wrong\"", "true", "nan", "inf", "-inf", "0", "-1", "1e308", "\"\""};

// (key suffix, value) pairs that are legitimate and must start a run. A key suffix matches the
// end of the key path, so one row covers every case and every body. Mirrored in docs/reliability.md.
const std::vector<std::pair<std::string, std::string>> kAllowed = {
    {"title", "\"wrong\""},  {"title", "\"\""},  // any text
    {"body[*].name", "\"wrong\""}, {"rigid_body[*].name", "\"wrong\""},  // not a material's: bodies refer to it
    {"citation", "\"wrong\""}, {"citation", "\"\""},
    {"solver.max_steps", "0"},                     // 0 = unlimited
    {"solver.fixed_time_step", "0"},               // 0 = from the CFL condition
    {"solver.mass_scaling_target_time_step", "0"},  // 0 = no target
    {"solver.contact_distance_cells", "0"},        // contact only where the body is reached
    {"solver.flip_fraction", "0"},                 // pure PIC
    {"solver.remove_escaping_particles", "true"},  //
    {"output.snapshot_interval", "0"},             // first and last only
    {"output.history_interval", "0"},              // every step
    {"output.vtu", "true"},
    {"cutting.conduction", "true"},
    {"cutting.workpiece_length", "0"},  // 0 = automatic, as are the next ones
    {"cutting.workpiece_height", "0"},
    {"cutting.tool_length", "0"},
    {"cutting.tool_height", "0"},
    {"cutting.chip_room", "0"},
    {"cutting.cell_size", "0"},  // t0 / 10
    {"cutting.rake_angle_deg", "0"},
    {"cutting.rake_angle_deg", "-1"},
    {"cutting.edge_radius", "0"},  // a sharp tool
    {"cutting.friction", "0"},     // frictionless
    {"cutting.tool_conductivity", "0"},              // a tool at its temperature
    {"cutting.tool_volumetric_heat_capacity", "0"},  // a steady conducting tool
    {"cutting.steady_start_fraction", "0"},
    {"rounding_radius", "0"},
    {"friction", "0"},
    {"friction_heat_share", "0"},
    {"vtu", "true"},
    {"jc_C", "0"}, {"jc_n", "0"}, {"jc_A", "0"}, {"jc_B", "0"},  // Johnson-Cook terms switched off
    {"jc_D1", "0"}, {"jc_D2", "0"}, {"jc_D3", "0"}, {"jc_D4", "0"}, {"jc_D5", "0"},
    {"jc_D1", "-1"}, {"jc_D2", "-1"}, {"jc_D3", "-1"}, {"jc_D4", "-1"}, {"jc_D5", "-1"},
    {"damage_triaxiality_cutoff", "0"}, {"damage_triaxiality_cutoff", "-1"},  // a triaxiality: any sign
    {"thermal_conductivity", "0"}, {"strain_rate_smoothing_time", "0"}, {"bulk_viscosity_linear", "0"},
    {"bulk_viscosity_quadratic", "0"}, {"mg_s", "0"}, {"mg_gamma0", "0"}, {"taylor_quinney", "0"},
    {"fracture_transition_strain_rate", "0"}, {"poisson_ratio", "0"}, {"specific_heat", "0"}, {"fracture_energy", "0"},
    {"crack_friction", "0"},
};

// Allowed in some cases and refused in others, with a message naming the key: conduction needs a
// heat capacity (elastic-unit has none), damage needs model = "johnson_cook", and:
const std::vector<std::pair<std::string, std::string>> kAllowedInContext = {
    {"thermal.conduction", "true"}, {"damage", "true"}, {"specific_heat", "0"},
    // 0 (the default) for a key the material's model does not use (e.g. Johnson-Cook keys of an
    // elastic material); refused where the model uses it.
    {"melting_temperature", "0"}, {"jc_m", "0"}, {"reference_strain_rate", "0"}, {"mg_c0", "0"},
    {"min_failure_strain", "0"}, {"fracture_energy_brittle", "0"}, {"fracture_transition_exponent", "0"},
    // All frictional heat into the tool, an adiabatic tool: refused where the tool conducts (it takes its heat
    // through the coefficient, and the frictional heat by conduction from the workpiece).
    {"cutting.friction_heat_share", "0"}, {"cutting.tool_heat_transfer_coefficient", "0"}};

// `pattern` matches `key` exactly or as its last dotted part(s); '*' stands for an index.
bool matches(const std::string& pattern, const std::string& key) {
  std::string k;
  for (std::size_t i = 0; i < key.size(); ++i) {
    if (key[i] == '[') {
      k += "[*]";
      i = key.find(']', i);
    } else {
      k += key[i];
    }
  }
  return k == pattern || k.ends_with("." + pattern);
}

bool listed(const std::vector<std::pair<std::string, std::string>>& table, const std::string& key,
            const std::string& value) {
  for (const auto& [pattern, v] : table)
    if (v == value && matches(pattern, key)) return true;
  return false;
}
bool allowed(const std::string& key, const std::string& value) {
  return listed(kAllowed, key, value) || listed(kAllowedInContext, key, value);
}

void leaves(const toml::table& t, const std::string& prefix, std::set<std::string>& out) {
  for (const auto& [k, v] : t) {
    const std::string path = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const toml::table* sub = v.as_table()) {
      leaves(*sub, path, out);
    } else if (const toml::array* a = v.as_array(); a && !a->empty() && a->is_array_of_tables()) {
      for (std::size_t i = 0; i < a->size(); ++i) leaves(*a->get(i)->as_table(), path + "[" + std::to_string(i) + "]", out);
    } else {
      out.insert(path);
    }
  }
}

// Every key of a case: in its file; in its expanded scene (every material and body key) where the
// case is a plain scene; every preset key and the [solver]/[output] keys where it is a cutting case.
std::set<std::string> input_surface(const fs::path& file) {
  std::set<std::string> keys;
  leaves(toml::parse_file(file.string()), "", keys);
  const Case c = load_case(file);
  std::ostringstream expanded;
  write_scene(c, expanded);
  std::set<std::string> all;
  leaves(toml::parse(expanded.str()), "", all);
  if (c.cutting) {
    std::ostringstream preset;
    write_cutting_parameters(*c.cutting, preset, "cutting");
    leaves(toml::parse(preset.str()), "", keys);
    keys.insert("cutting.cutting_speed_m_per_min");
    for (const std::string& k : all)
      if (k.starts_with("solver.") || k.starts_with("output.")) keys.insert(k);
  } else {
    for (const std::string& k : all)
      if (!k.starts_with("cutting_process")) keys.insert(k);
  }
  return keys;
}

TEST(InputFuzz, EveryKeyOfEveryShippedCaseRejectsHostileValuesOrStartsFine) {
  const fs::path cases = fs::path(MPMCUT_TEST_DIR) / ".." / "cases";
  const fs::path dir = fs::temp_directory_path() / ("mpmcut_fuzz_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path log = dir / "log";
  int checked = 0, accepted = 0;
  std::vector<std::string> accepted_list;
  // Cases with the same input surface (cases/speeds/ differ from each other only in values) are
  // fuzzed once: the same keys through the same reader give the same answers.
  std::set<std::set<std::string>> surfaces_done;
  std::vector<fs::path> files;
  // Run cases only: cases/calibration/ holds `mpmcut calibrate` configurations, another format.
  for (const auto& e : fs::recursive_directory_iterator(cases))
    if (e.path().extension() == ".toml" && e.path().parent_path().filename() != "calibration") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    const std::set<std::string> surface = input_surface(file);
    if (!surfaces_done.insert(surface).second) continue;
    const fs::directory_entry e(file);
    for (const std::string& key : surface) {
      for (const std::string& value : kHostileValues) {
        const std::string set = key + "=" + value;
        const auto start = std::chrono::steady_clock::now();
        const pid_t pid = spawn_mpmcut({"run", e.path().string(), "--check", "--set", set}, {log});
        int code = -1;
        if (!wait_until([&] { return exited(pid, code); }, 5.0)) {
          ::kill(pid, SIGKILL);
          wait_exit_code(pid);
          ADD_FAILURE() << e.path().filename() << " --set " << set << ": no answer within 5 s (a hang)";
          continue;
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string output = read_file(log);
        ++checked;
        const std::string where = e.path().filename().string() + " --set " + set + ": ";
        if (code == 2) {
          EXPECT_FALSE(listed(kAllowed, key, value)) << where << "refused a value listed as allowed:\n" << output;
          // The key itself, or (for a material's name) the key that refers to it.
          const std::string canonical = key;
          const bool named = output.find(canonical) != std::string::npos ||
                             (key.ends_with(".name") && output.find("material") != std::string::npos);
          EXPECT_TRUE(named) << where << "the message does not name the key:\n" << output;
          EXPECT_LT(seconds, 5.0);
          // The real run refuses it too, before it creates a result directory.
          if (value == "nan") {
            const fs::path out = dir / "refused";
            const CliResult r = run_mpmcut({"run", e.path().string(), "--set", set, "--out", out.string(),
                                            "--no-progress", "--no-plots"},
                                           log);
            EXPECT_EQ(r.exit_code, 2) << where << r.output;
            EXPECT_FALSE(fs::exists(out)) << where << "a refused run created its result directory";
          }
          continue;
        }
        EXPECT_EQ(code, 0) << where << "neither an input error (2) nor accepted (0), exit " << code << ":\n" << output;
        EXPECT_TRUE(allowed(key, value)) << where << "accepted a value not in the table of allowed values:\n" << output;
        if (code != 0) continue;
        ++accepted;
        accepted_list.push_back(where);
        // Accepted: it must really start, and a 2-step run must finish complete.
        const fs::path out = dir / ("run" + std::to_string(accepted));
        std::vector<std::string> args{"run", e.path().string(), "--set", set, "--out", out.string(),
                                      "--no-progress", "--no-plots", "--threads", "1", "--checkpoint-every", "off"};
        args.insert(args.end(), {"--set", key == "solver.max_steps" ? "solver.end_time=1e-9" : "solver.max_steps=2"});
        const pid_t run = spawn_mpmcut(args, {log});
        int run_code = -1;
        if (!wait_until([&] { return exited(run, run_code); }, 60.0)) {
          ::kill(run, SIGKILL);
          wait_exit_code(run);
          ADD_FAILURE() << where << "the 2-step run did not finish in 60 s";
          continue;
        }
        EXPECT_EQ(run_code, 0) << where << "accepted by --check but the run failed:\n" << read_file(log);
        EXPECT_EQ(summary_status(out), run_code == 0 ? "complete" : summary_status(out));
        if (run_code != 0) EXPECT_NE(summary_status(out), "complete") << where;
        fs::remove_all(out);
      }
    }
  }
  std::printf("input fuzz: %d values checked, %d accepted and run\n", checked, accepted);
  EXPECT_GT(checked, 1000);
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace mpmcut::testing
