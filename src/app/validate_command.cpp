#include "app/validate_command.hpp"

#include <algorithm>
#include <iostream>
#include <map>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/command_exit.hpp"
#include "app/plot_command.hpp"
#include "app/sweep_command.hpp"
#include "app/validation_conditions.hpp"
#include "app/validation_report.hpp"
#include "app/path_option.hpp"
#include "app/progress_option.hpp"
#include "app/range_option.hpp"
#include "cutting/cutting_scene.hpp"
#include "cutting/input_plausibility.hpp"
#include "cutting/tool_heat_settings.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/scene_writer.hpp"
#include "run/case_loading.hpp"
#include "run/run_case.hpp"
#include "run/run_summary.hpp"
#include "studies/measured_conditions.hpp"
#include "studies/run_records.hpp"
#include "studies/task_farm.hpp"
#include "studies/validation_defaults.hpp"
#include "studies/validation_metrics.hpp"

namespace mpmcut {

namespace {

namespace fs = std::filesystem;
using validation::Condition;
using ValidateOptions = validation::Options;

Case condition_case(const Condition& c, const fs::path& case_file) { return parse_case(c.case_text, case_file.string()); }

// --list: the selected conditions with their resolution and estimated cost; writes their case files.
int list_conditions(const std::vector<Condition>& conditions, const fs::path& out, const ValidateOptions& o) {
  fs::create_directories(out / "cases");
  std::cout << fmt::format("Resolution: {}.\n", validation::resolution_text(o));
  std::cout << fmt::format("{:<36} {:>6} {:>6} {:>8} {:>6} {:>10} {:>7} {:>7} {:>7} {:>6} {:>9} {:>10} {:>9} {:>9}  {}\n",
                           "condition", "kind", "h_mm", "vc_m/min", "r_n_um", "status", "cell_um", "cut_mm", "cells/t0",
                           "f_mass", "particles", "steps", "Gpart·st", "core_h", "in OUT");
  double total_particle_steps = 0, total_to_run = 0;
  int n = 0, complete = 0;
  std::vector<RunCostObservation> observed;  // what the complete ones took against their estimate
  for (const Condition& c : conditions) {
    if (!c.selected) continue;
    const fs::path case_file = out / "cases" / (c.id + ".toml");
    write_file_atomically(case_file, [&](std::ostream& s) { s << c.case_text; });
    const Case condition = condition_case(c, case_file);
    const RunCost cost = estimate_run_cost(condition.scene);
    ExistingRun existing = existing_run(out / c.id, condition);
    const ExistingRun record =
        o.records_dir.empty() ? ExistingRun::None : existing_run(fs::path(o.records_dir) / c.id, condition);
    const bool recorded = existing != ExistingRun::Complete && record == ExistingRun::Complete;
    if (recorded) existing = ExistingRun::Complete;
    // outdated: made by an older model of its scene (solver/model_version.hpp), runs again
    const char* state = recorded ? "record" : existing == ExistingRun::Complete ? "complete"
                        : existing == ExistingRun::Resumable ? "resumable"
                        : existing == ExistingRun::Outdated ? "outdated"
                        : record == ExistingRun::Outdated ? "outdated-record" : "-";
    const double ps = cost.particle_steps();
    total_particle_steps += ps;
    if (existing != ExistingRun::Complete) total_to_run += ps;
    complete += existing == ExistingRun::Complete;
    if (existing == ExistingRun::Complete) {
      const CaseResult done = read_case_result(recorded ? fs::path(o.records_dir) / c.id : out / c.id, {}, 0);
      if (done.steps && done.core_seconds_per_particle_step)
        observed.push_back({cost.steps, *done.steps, *done.core_seconds_per_particle_step});
    }
    ++n;
    const auto& cut = *condition.cutting;
    std::cout << fmt::format("{:<36} {:>6} {:>6g} {:>8g} {:>6g} {:>10} {:>7.3g} {:>7.3g} {:>7.3g} {:>6.3g} {:>9} {:>10.3g} "
                             "{:>9.3g} {:>9.3g}  {}\n",
                             c.id, c.kind, c.h_mm, c.speed_m_per_min(), c.edge_radius_um,
                             c.measured ? c.measured->status : std::string("-"), cut.cell_size * 1e6, cut.cut_length * 1e3,
                             cut.uncut_chip_thickness / cut.cell_size, cost.mass_scaling_factor, cost.particles, cost.steps,
                             ps * 1e-9, ps * kCoreSecondsPerParticleStep / 3600.0, state);
  }
  std::cout << fmt::format(
      "{} conditions, {} already complete in {}{}; {:.3g} G particle-steps, about {:.3g} core-hours in all, {:.3g} "
      "core-hours still to run (estimate: {:.2g} core-s per particle-step, steps at the first step's stable time step; "
      "case files in {})\n",
      n, complete, out.string(), o.records_dir.empty() ? "" : " or --records " + o.records_dir, total_particle_steps * 1e-9, total_particle_steps * kCoreSecondsPerParticleStep / 3600.0,
      total_to_run * kCoreSecondsPerParticleStep / 3600.0, kCoreSecondsPerParticleStep, (out / "cases").string());
  if (const auto fix = observed_cost_correction(observed))
    std::cout << fmt::format(
        "Corrected by the {} complete run(s) listed (steps x {:.2f} of the estimate, median; {:.2f}-{:.2f}; {:.2g} "
        "core-s per particle-step, median, on the machine and load they ran with): about {:.3g} core-hours still "
        "to run\n",
        fix->runs, fix->step_ratio, fix->step_ratio_min, fix->step_ratio_max, fix->core_seconds_per_particle_step,
        fix->core_hours(total_to_run));
  return 0;
}

// Keeps the run of condition `id` in --records if it is complete; warns where a record of another scene is there.
void record_run(const ValidateOptions& o, const fs::path& out, const std::string& id) {
  try {
    if (read_summary(out / id / "summary.json").status != "complete") return;
    if (!save_run_record(out / id, fs::path(o.records_dir) / id))
      std::cerr << fmt::format("warning: {}: the record in {} is of another scene (resolution, material or "
                               "settings); kept, not replaced by this run. Use another --records directory\n",
                               id, o.records_dir);
  } catch (const std::exception& e) {
    std::cerr << fmt::format("warning: {}: no record kept: {}\n", id, e.what());
  }
}

int run_validation(const ValidateOptions& o) {
  const fs::path out = o.out_dir.empty() ? fs::path(o.quick ? "results/validation_quick" : "results/validation")
                                         : fs::path(o.out_dir);
  if (!o.records_dir.empty() && fs::exists(o.records_dir) && !fs::is_directory(o.records_dir))
    throw InputError(fmt::format("--records {}: not a directory (the run records are kept in a directory, one "
                                 "folder per condition)",
                                 o.records_dir));
  const ConditionRunSettings settings = validation::run_settings(o);
  const validation::ForceData data = validation::force_data(o);
  std::vector<Condition> conditions = validation::matrix_conditions(settings, data);
  validation::select_conditions(conditions, o);
  // A changed material key that the material rejects (unknown, out of range) stops the study before any run.
  if (!settings.material_overrides.empty()) {
    const auto first = std::find_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.selected; });
    (void)parse_case(first->case_text, "the case of " + first->id + " (--material-key)");
  }
  if (const std::string w = validation::material_data_mismatch(settings, data); !w.empty())
    std::cerr << "warning: " << w << "\n";
  if (o.list) return list_conditions(conditions, out, o);
  fs::create_directories(out / "cases");
  fs::create_directories(out / "logs");

  // Complete runs of the same scene kept in --records come back into `out` and are not run again.
  if (!o.records_dir.empty()) {
    std::map<std::string, std::vector<std::string>> outdated;  // why -> the selected conditions whose record it is
    for (Condition& c : conditions) {
      const fs::path case_file = out / "cases" / (c.id + ".toml");
      const fs::path record = fs::path(o.records_dir) / c.id;
      const Case condition = condition_case(c, case_file);
      if (c.selected && existing_run(record, condition) == ExistingRun::Outdated)
        outdated[outdated_run_reason(record, condition)].push_back(c.id);
      if (!restore_run_record(record, out / c.id, condition)) continue;
      c.selected = false;
      c.origin = "record";
    }
    for (const auto& [why, ids] : outdated)
      std::cerr << fmt::format("note: {} record(s) in {} are outdated ({}): {}. These conditions run again and their new "
                               "runs replace the records\n",
                               ids.size(), o.records_dir, why, fmt::join(ids, ", "));
  }

  // The runs of this invocation; each child keeps a complete run of the same scene (--keep-complete), so a
  // rerun over a superset runs only what is new.
  std::vector<ChildRun> runs;
  std::vector<Condition*> run_of;
  for (Condition& c : conditions) {
    if (!c.selected) continue;
    const fs::path case_file = out / "cases" / (c.id + ".toml");
    write_file_atomically(case_file, [&](std::ostream& s) { s << c.case_text; });
    // Complete in `out` with the same scene: reported as an earlier run, not launched (nor counted) again.
    try {
      if (existing_run(out / c.id, condition_case(c, case_file)) == ExistingRun::Complete) {
        c.selected = false;
        c.origin = "earlier run";
        continue;
      }
    } catch (const std::exception&) {
      // An unreadable earlier result is the child's to report; it runs.
    }
    ChildRun r;
    r.name = c.id;
    r.args = {"run", case_file.string(), "--out", (out / c.id).string(), "--keep-complete", "--no-progress", "--threads",
              std::to_string(o.threads)};
    // A quick run's pictures take longer than the run and show an unconverged chip.
    if (o.quick) r.args.push_back("--no-plots");
    r.log_file = out / "logs" / (c.id + ".log");
    // A complete run is recorded as soon as it ends, so that an interrupted study keeps it.
    if (!o.records_dir.empty())
      r.on_finished = [&o, &out, id = c.id](const ChildRun& finished) {
        if (finished.exit_code == 0) record_run(o, out, id);
      };
    runs.push_back(r);
    run_of.push_back(&c);
  }
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / o.threads);
  std::cout << fmt::format("mpmcut validate{}: {} of the {} conditions of the matrix, {}, each with --threads {}; "
                           "results in {}\n",
                           o.quick ? " --quick (coarse: 4 cells/t0, 1 particle per cell, 4 cells of travel; checks "
                                     "the pipeline, the numbers are not converged)"
                                   : "",
                           runs.size(), conditions.size(), concurrency_text(jobs), o.threads, out.string())
            << std::flush;
  // What every run would say at its start about the material and the data (unit slips of a --material-key or a
  // --material-file set: in each run's log and summary.json, said once here).
  if (!run_of.empty()) {
    const Case first = condition_case(*run_of.front(), out / "cases" / (run_of.front()->id + ".toml"));
    if (first.cutting)
      for (const std::string& w : input_plausibility_warnings(*first.cutting, first.scene))
        std::cerr << "warning: every run: " << w << "\n";
  }
  const bool completed = run_cases(runs, jobs, true, o.progress_interval_s);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    run_of[i]->result = read_case_result(out / run_of[i]->id, runs[i].log_file, runs[i].exit_code);
    run_of[i]->origin = "this run";
  }
  // Conditions not selected now but complete in `out` from an earlier part with the same scene (the same
  // resolution rule and settings), or restored from a record, are reported too, so that a matrix run in parts
  // ends in one report.
  for (Condition& c : conditions) {
    if (c.selected) continue;
    if (c.origin.empty()) {  // neither a record nor found complete before the launch: look now
      try {
        if (existing_run(out / c.id, condition_case(c, out / "cases" / (c.id + ".toml"))) != ExistingRun::Complete)
          continue;
      } catch (const std::exception&) {
        continue;
      }
      c.origin = "earlier run";
    }
    c.result = read_case_result(out / c.id, out / "logs" / (c.id + ".log"), 0);
  }
  // Every complete run goes into --records (those of earlier parts too), so that the next part (or session) keeps it.
  if (!o.records_dir.empty())
    for (const Condition& c : conditions)
      if (c.complete() && c.origin == "earlier run") record_run(o, out, c.id);
  validation::write_validation_report(conditions, validation::ReportContext{o, settings, data, out, runs.size(), completed});

  if (!o.no_plots && completed) {  // an interrupted validation stops here: no plots of partial results
    std::string why;
    if (!python_plotting_available(false, why))
      std::cerr << "warning: no validation plots: " << why << "\n";
    else if (int code = run_python_tool("plot_validation.py", o.quick ? std::vector<std::string>{out.string(), "--quick"}
                                                                                : std::vector<std::string>{out.string()}); code != 0)
      std::cerr << "warning: plot_validation.py failed (exit status " << code << ")\n";
  }
  if (!completed) return 130;
  const auto failed =
      std::count_if(conditions.begin(), conditions.end(), [](const Condition& c) { return c.selected && !c.complete(); });
  if (failed) {
    std::cerr << fmt::format("mpmcut validate: {} of {} runs did not complete (see validation.md and logs/)\n", failed,
                             runs.size());
    return 1;
  }
  return 0;
}

}  // namespace

void add_validate_command(CLI::App& app) {
  auto o = std::make_shared<ValidateOptions>();
  CLI::App* v = app.add_subcommand(
      "validate",
      "Run the measured conditions of data/experiments (every speed and thickness of the Klippel et al. 2024 force "
      "data with its measured edge radius, and the chip-type conditions) and compare: validation.md (goals, errors, "
      "trends), CSV tables, parity and trend plots. Resumable: a rerun into the same --out keeps the complete "
      "conditions, so the matrix can be run in parts (select with --h, --speeds-m-per-min, --conditions; --list "
      "shows the conditions and their cost); the report covers every complete condition in --out");
  v->add_flag("--quick", o->quick,
              "Coarse and short runs (seconds) of 5 conditions (h 0.04 mm at 100 and 400.1 m/min, 0.1 mm at 100 m/min, "
              "the two built-in chip-type conditions; every row of a --measurements or --chip-observations file) "
              "unless a selection is given: checks the pipeline, numbers not converged");
  v->add_option("--cells-per-feed", o->cells_per_feed,
                "N: cell <= t0/N, cells across the uncut chip thickness (default 10; cost grows as N^3); chip-type "
                "conditions use at least --chip-cells-per-feed")
      ->check(CLI::Range(2, 100));
  v->add_option("--chip-cells-per-feed", o->chip_cells_per_feed,
                fmt::format("Cells across t0 of the chip-type conditions (default {}: at t0/10 the 75 m/s chip's type "
                            "was not decided, at t0/20 it was the observed one, docs/results.md; at least 8, the chip "
                            "analysis' resolved count, and at least --cells-per-feed)",
                            kChipTypeCellsPerFeed))
      ->check(CLI::Range(8, 100));
  v->add_option("--cells-per-edge-radius", o->cells_per_edge_radius,
                "M: cell <= r_n/M, cells across the measured edge radius of the force conditions (default 4: the "
                "edge's quarter arc then spans ~6 cells; 0 = no limit). cell = min(t0/N, r_n/M)")
      ->check(CLI::Range(0.0, 100.0));
  v->add_option("--cells-per-thermal-length", o->cells_per_thermal_length,
                "K: cell <= l_th/K, cells across the thermal length l_th = sqrt(kappa t0/V), the width scale of an "
                "adiabatic shear band (6.8 um at h = 0.1 mm, 381.3 m/min in Ti-6Al-4V; default 0 = no limit; 1.6 "
                "resolves the fast cuts' shear bands to within ~4 % in Fc: docs/results.md)")
      ->check(CLI::Range(0.0, 100.0));
  v->add_option("--h", o->h_mm, "Run only these uncut chip thicknesses, mm (comma-separated, e.g. 0.1,0.04)")
      ->delimiter(',');
  v->add_option("--speeds-m-per-min", o->speeds_m_per_min,
                "Run only these cutting speeds, m/min (comma-separated, e.g. 100,400.1)")
      ->delimiter(',');
  v->add_option("--conditions", o->condition_ids, "Run only these conditions (ids as --list prints them, comma-separated)")
      ->delimiter(',');
  v->add_flag("--list", o->list,
              "Print the selected conditions with cell size, cut length and estimated cost (particles x steps, "
              "core-hours) and whether --out holds them complete; writes their case files, runs nothing");
  v->add_option("-o,--out", o->out_dir, "Output directory (default: results/validation or results/validation_quick)")->check(non_empty_path());
  v->add_option("--records", o->records_dir,
                "Directory of run records (scene.toml, forces.csv, summary.json of each complete condition; small, "
                "meant to be committed): conditions complete there with the same scene are reported without running, "
                "and every complete condition is added to it, so that a matrix run over several sessions or machines "
                "keeps its parts when the result directories are gone")
      ->check(non_empty_path());
  v->add_option("-j,--jobs", o->jobs, "Runs at the same time (default: cores / threads)")->check(CLI::Range(1, 1024));
  v->add_option("-t,--threads", o->threads, "OpenMP threads of each run (default: 1)")->check(CLI::Range(1, kMaxThreads));
  add_progress_option(v, o->progress_interval_s);
  v->add_flag("--no-plots", o->no_plots, "Only the tables");
  v->add_option("--material", o->material,
                fmt::format("Material set to run: a set of the library (default {}, fitted to these measurements "
                            "with crack friction and a conducting tool; ti64-cutting: the default case's; "
                            "docs/materials.md) or of --material-file",
                            kValidationMaterial));
  v->add_option("--measurements", o->measurements,
                "Validate against your own force measurements instead of the built-in Klippel et al. 2024 data: a CSV "
                "in the layout of data/experiments/ti64_klippel2024_orthogonal_forces.csv (columns h_mm, vc_m_per_min, "
                "Fc_mean_N, Ff_mean_N, edge_radius_um; optional Fc_/Ff_min_N, _max_N, n_tests, chip_thickness_um, "
                "status, rake_deg, clearance_deg, width_mm: forces in N are divided by it, else b = 1 mm is assumed); the "
                "conditions are then its rows "
                "(docs/results.md)");
  v->add_option("--chip-observations", o->chip_observations,
                "Compare the chip type with your own observations instead of the built-in statements: a CSV in the "
                "layout of data/experiments/ti64_chip_morphology.csv (columns id, chip_type = continuous | serrated | "
                "discontinuous | serrated->discontinuous, simulate_speed_m_per_s (blank: not simulated), h_min_mm; "
                "optional rake_deg, clearance_deg, edge_radius_um, statement, source, tag, note); each row with a "
                "speed is run at h_min_mm and its simulated chip type compared (docs/results.md)");
  v->add_option("--material-file", o->material_file,
                "A TOML file of [[material]] sets (as materials/*.toml, or the best_material.toml of `mpmcut "
                "calibrate`): --material may name one of them (a file of one set needs no --material); every case "
                "file then carries the file's sets");
  v->add_option("--material-key", o->material_keys,
                "Change a numeric key of the chosen set, KEY=VALUE (repeatable, e.g. --material-key jc_C=0.035): "
                "every case then runs a set \"trial\" that starts from it (library = the set) with these keys; "
                "docs/materials.md lists the keys");
  v->add_option("--friction", o->friction,
                fmt::format("Coulomb coefficient at the tool (default {:g} with the default material set, fitted "
                            "with it; 0.35, the cutting preset's, with any other set)",
                            kValidationMaterialFriction))
      ->check(CLI::Range(0.0, 2.0));
  v->add_option("--contact-detection", o->contact_detection,
                fmt::format("How the tool contact finds the material (solver.contact_detection; default: the cutting "
                            "preset's, {}; penalty: a spring per particle, smooth in the tool's position on the grid; "
                            "node: the nodal constraint of the runs before 2026-12-07, docs/cutting.md)",
                            contact_detection_name(kCuttingPresetContact)))
      ->check(CLI::IsMember(contact_detection_names()));
  v->add_option("--volumetric-average", o->volumetric_average,
                "The volumetric strain rate of every run (solver.volumetric_average; default off; nodal: averaged "
                "through the nodes against volumetric locking of inclined shear bands, docs/solver.md)")
      ->check(CLI::IsMember(volumetric_average_names()));
  // The tool's thermal options: when given, they go into every case file, with the bounds of their [cutting] keys.
  struct ThermalOption {
    const char* name;
    std::optional<double>* value;
    std::string help;
    const ToolHeatKey& key;
  };
  for (const ThermalOption& t : {
           ThermalOption{"--friction-heat-share", &o->friction_heat_share,
                         "Share of the frictional heat that goes into the workpiece, the rest into the tool (default 1: "
                         "all of it; [cutting] friction_heat_share)",
                         kFrictionHeatShare},
           ThermalOption{"--tool-heat-transfer-coefficient", &o->tool_heat_transfer_coefficient,
                         fmt::format("Heat transfer coefficient between the workpiece and the tool, W/(m^2 K) "
                                     "(default {:g} with the default material set, which was fitted with a "
                                     "conducting tool; 0, an adiabatic tool, with any other set; [cutting] "
                                     "tool_heat_transfer_coefficient)",
                                     kValidationToolHeatTransferCoefficient),
                         kToolHeatTransferCoefficient},
           ThermalOption{"--tool-temperature", &o->tool_temperature,
                         "The tool's constant temperature, K, where it exchanges heat (default: the workpiece's "
                         "initial temperature)",
                         kToolTemperature},
           ThermalOption{"--tool-conductivity", &o->tool_conductivity,
                         fmt::format("A conducting tool: its thermal conductivity, W/(m K) (default {:g}, carbide, "
                                     "with the default material set and a heat transfer coefficient > 0; else 0: the "
                                     "tool stays at its temperature, a heat sink; needs a heat transfer coefficient; "
                                     "[cutting] tool_conductivity)",
                                     kValidationToolConductivity),
                         kToolConductivity},
           ThermalOption{"--tool-volumetric-heat-capacity", &o->tool_volumetric_heat_capacity,
                         "A conducting tool's rho c, J/(m^3 K) (default 0: a steady tool; [cutting] "
                         "tool_volumetric_heat_capacity)",
                         kToolVolumetricHeatCapacity}})
    v->add_option(t.name, *t.value, t.help)->check(within(t.key.range));
  v->callback([o]() { finish_command([&] { return run_study([&] { return run_validation(*o); }); }); });
}

}  // namespace mpmcut