// The Python module mpmcut's compiled part, mpmcut._mpmcut (docs/python.md): a case (Case) and a
// run (run/case_run.hpp) as Python objects. src/python/mpmcut/__init__.py adds the Python-side
// conveniences (overrides from a dict). A thin layer: the run is the library's, step for step.
#include <csignal>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "analysis/grid_convergence.hpp"
#include "io/input_error.hpp"
#include "python/csv_columns.hpp"
#include "python/particle_views.hpp"
#include "run/case_loading.hpp"
#include "run/case_run.hpp"
#include "run/run_case.hpp"
#include "run/run_summary.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace mpmcut::python {

namespace {

py::object json_to_python(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

RunOptions run_options(const fs::path& out, bool force, int threads, bool progress, const std::string& checkpoint_every) {
  RunOptions o;
  o.out_dir = out;
  o.force = force;
  o.threads = threads;
  // A fixed thread count: the run then is the CLI's `--threads N --fixed-threads`, bit for bit.
  o.tune_threads = false;
  o.progress = progress;
  o.checkpoint_every = parse_checkpoint_interval(checkpoint_every);
  return o;
}

// The exception's "Type: message" without the traceback pybind11 appends.
std::string first_line(std::string text) {
  if (const auto end = text.find('\n'); end != std::string::npos) text.resize(end);
  return text;
}

// A run driven from Python. The StopToken is the run's own: stop() and Ctrl-C request a clean stop.
class PyRun {
 public:
  explicit PyRun(std::unique_ptr<CaseRun> run) : run_(std::move(run)) {}

  static PyRun open(const Case& c, const fs::path& out, bool force, int threads, bool progress,
                    const std::string& checkpoint_every) {
    RunOptions o = run_options(out, force, threads, progress, checkpoint_every);
    return PyRun(open_run(c, o));
  }
  static PyRun resume(const fs::path& out, bool force, int threads, bool progress,
                      const std::optional<std::string>& checkpoint_every) {
    RunOptions o = run_options(out, force, threads, progress, checkpoint_every.value_or("off"));
    o.checkpoint_every_given = checkpoint_every.has_value();
    return PyRun(open_resumed_run(o));
  }

  // Up to n steps with the GIL released; returns whether the run can go on.
  bool step(long n) {
    if (n < 0) throw py::value_error(fmt::format("Run.step(n): n must be 0 or more, got {}", n));
    views_.check_released();
    bool more = !ended_;
    for (long k = 0; k < n && more; ++k) {
      more = advance("step");
      if (PyErr_CheckSignals() != 0) interrupted_by_python();
    }
    if (!more) ended_ = true;
    return more;
  }

  // To the end; `callback(run)` after every `every` steps (a False return stops the run cleanly).
  std::string run(const std::optional<py::function>& callback, long every, py::handle self) {
    if (every < 1) throw py::value_error(fmt::format("Run.run: every must be 1 or more steps, got {}", every));
    long since = 0;
    while (!ended_) {
      views_.check_released();
      const bool more = advance("run");
      if (!more) ended_ = true;
      if (PyErr_CheckSignals() != 0) interrupted_by_python();
      if (callback && !ended_ && ++since >= every) {
        since = 0;
        py::object keep_going;
        try {
          keep_going = (*callback)(self);
        } catch (py::error_already_set& e) {  // the callback failed (or Ctrl-C in it): stop cleanly, then raise
          if (e.matches(PyExc_KeyboardInterrupt)) run_->stop_token().request_stop(SIGINT);
          else run_->request_stop("the callback raised " + first_line(e.what()));
          ended_ = true;
          finish();
          throw;
        }
        if (!keep_going.is_none() && !keep_going.cast<bool>()) run_->request_stop("the callback returned False");
      }
    }
    return finish();
  }

  // Raises RuntimeError where the outputs could not be written (the CLI's exit 4): a Python caller checks no
  // exit code, and a returned "failed" beside a full disk read like a failed simulation.
  std::string finish() {
    if (!exit_code_) {
      const Stepping busy(*this, "finish");
      py::gil_scoped_release release;
      ended_ = true;
      exit_code_ = run_->finish();
    }
    if (*exit_code_ == kExitOutputError)
      throw std::runtime_error(fmt::format("Run: the results in {} could not be written: {}", run_->root().string(),
                                           run_->final_message()));
    return status();
  }

  // The run's own status once finished: summary.json may be the stale one where writing it failed.
  std::string status() const {
    if (!exit_code_) return run_status::running;
    return run_->final_status();
  }

  void stop() { run_->request_stop("Run.stop()"); }
  fs::path checkpoint() {
    refuse_while_stepping("checkpoint");
    // A checkpoint after the final outputs would be newer than the summary it contradicts: resume would continue
    // a complete run, or one the summary calls failed.
    if (exit_code_)
      throw std::runtime_error(fmt::format("Run.checkpoint: the run has finished (status \"{}\"); {}", status(),
                                           status() == run_status::interrupted
                                               ? "its checkpoint at the stop is in checkpoints/ (Run.resume continues it)"
                                               : "there is nothing left to restart"));
    return run_->write_checkpoint();
  }
  py::dict particles(py::handle self) {
    refuse_while_stepping("particles");
    return views_.views(run_->simulation().particles(), self);
  }
  py::dict csv(const char* name) {
    refuse_while_stepping(name);
    run_->flush_outputs();
    return read_csv_columns(run_->root() / name);
  }
  // Not while another thread steps: the summary walks the particle arrays, which a step reorders and frees.
  py::object summary() const {
    refuse_while_stepping("summary");
    if (exit_code_) return json_to_python(to_json(read_summary(run_->root() / "summary.json")));
    return json_to_python(to_json(run_->summary()));
  }
  const CaseRun& run() const { return *run_; }
  std::optional<int> exit_code() const { return exit_code_; }

 private:
  // One thread steps a run at a time. A step runs with the GIL released so that other Python threads go on; a
  // second thread stepping the same run meanwhile corrupted it (non-finite velocities within 8-400 steps, reported
  // as a failed simulation), and a checkpoint, the particle views or the CSV flush mid-step read a half-made state.
  // `stepping_` is read and set with the GIL held, so a plain flag is enough.
  void refuse_while_stepping(std::string_view what) const {
    if (stepping_)
      throw std::runtime_error(fmt::format("Run.{}: this run is being stepped by another thread; call it from that "
                                           "thread (e.g. in run()'s callback) or after the stepping returns",
                                           what));
  }
  struct Stepping {
    PyRun& r;
    Stepping(PyRun& run, std::string_view what) : r(run) {
      r.refuse_while_stepping(what);
      r.stepping_ = true;
    }
    ~Stepping() { r.stepping_ = false; }  // destroyed after the GIL is taken back
  };
  bool advance(std::string_view what) {
    const Stepping busy(*this, what);
    py::gil_scoped_release release;
    return run_->advance();
  }

  // Ctrl-C in Python: stop cleanly (checkpoint, outputs, summary), then raise KeyboardInterrupt.
  void interrupted_by_python() {
    PyObject *type, *value, *trace;
    PyErr_Fetch(&type, &value, &trace);
    run_->stop_token().request_stop(SIGINT);
    ended_ = true;
    finish();
    PyErr_Restore(type, value, trace);
    throw py::error_already_set();
  }

  std::unique_ptr<CaseRun> run_;
  ParticleViews views_;
  bool ended_ = false;
  bool stepping_ = false;
  std::optional<int> exit_code_;
};

// The result directory's refusals name the command line's options; from Python they are Run's arguments.
std::string in_python_terms(std::string text) {
  for (const auto& [cli, python] : {std::pair<std::string_view, std::string_view>{"--force", "force=True"},
                                    {"--out", "out"}}) {
    for (std::size_t at = text.find(cli); at != std::string::npos; at = text.find(cli, at + python.size()))
      text.replace(at, cli.size(), python);
  }
  return text;
}

}  // namespace

PYBIND11_MODULE(_mpmcut, m) {
  m.doc() = "mpmcut: material point method simulation of orthogonal metal cutting (docs/python.md)";
  m.attr("__version__") = MPMCUT_VERSION;
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const RunOpenError& e) {
      PyErr_SetString(PyExc_RuntimeError, in_python_terms(e.what()).c_str());
    }
  });
  ParticleViews::bind(m);

  py::class_<Case>(m, "Case", "A validated case (scene): what is simulated. Build it with mpmcut.load_case().")
      .def_static(
          "_from_file", [](const fs::path& file, const std::vector<std::string>& overrides) {
            return load_case(file, overrides);
          })
      .def_static("_from_toml",
                  [](const std::string& text, const std::string& name, const std::vector<std::string>& overrides) {
                    return parse_case(text, name, overrides);
                  })
      .def_static("_default_cut", [](const std::vector<std::string>& overrides) { return default_cutting_case(overrides); })
      .def_property_readonly("title", [](const Case& c) { return c.scene.title; })
      .def_property_readonly("source", [](const Case& c) { return c.scene.source_file; })
      .def_property_readonly("end_time_s", [](const Case& c) { return c.scene.solver.end_time; })
      .def_property_readonly("is_cutting", [](const Case& c) { return c.cutting.has_value(); })
      .def("toml", &scene_text, "The expanded scene as TOML (what the run writes as scene.toml).");

  py::class_<PyRun>(m, "Run", "A run writing into a result directory (docs/python.md).")
      .def(py::init(&PyRun::open), py::arg("case"), py::arg("out"), py::kw_only(), py::arg("force") = false,
           py::arg("threads") = 0, py::arg("progress") = false, py::arg("checkpoint_every") = "off",
           "A new run of `case` into the result directory `out` (force: replace an existing one). threads: OpenMP "
           "threads, 0 = all cores. checkpoint_every: as the CLI's --checkpoint-every (\"5000\", \"10min\", \"off\").")
      .def_static("resume", &PyRun::resume, py::arg("out"), py::kw_only(), py::arg("force") = false,
                  py::arg("threads") = 0, py::arg("progress") = false, py::arg("checkpoint_every") = py::none(),
                  "The stopped run in `out`, continued from its newest valid checkpoint.")
      .def("step", &PyRun::step, py::arg("n") = 1,
           "Up to n steps (the GIL released). Returns True while the run can go on.")
      .def(
          "run",
          [](py::object self, const std::optional<py::function>& callback, long every) {
            return self.cast<PyRun&>().run(callback, every, self);
          },
          py::arg("callback") = py::none(), py::arg("every") = 1,
          "To the end (the GIL released while stepping), then the final outputs; returns the status. "
          "callback(run) is called after every `every` steps; returning False stops the run cleanly.")
      .def("finish", &PyRun::finish, "Final outputs and summary.json; returns the status.")
      .def("stop", &PyRun::stop, "Ask the run to stop after the current step (a checkpoint is written).")
      .def("checkpoint", &PyRun::checkpoint, "Write a checkpoint now; returns its file.")
      .def_property_readonly("particles", [](py::object self) { return self.cast<PyRun&>().particles(self); },
                             "{field: read-only ndarray} views on the particle arrays; valid until the next step.")
      .def("forces", [](PyRun& r) { return r.csv("forces.csv"); }, "forces.csv as {column: ndarray} (cutting runs).")
      .def("history", [](PyRun& r) { return r.csv("history.csv"); }, "history.csv as {column: ndarray}.")
      .def("rigid_forces", [](PyRun& r) { return r.csv("rigid_forces.csv"); }, "rigid_forces.csv as {column: ndarray}.")
      .def("summary", &PyRun::summary, "summary.json as a dict (while running: the summary so far).")
      .def_property_readonly("status", &PyRun::status)
      .def_property_readonly("exit_code", &PyRun::exit_code, "The CLI's exit code once finished, else None.")
      .def_property_readonly("time_s", [](const PyRun& r) { return r.run().simulation().time(); })
      .def_property_readonly("step_count", [](const PyRun& r) { return r.run().simulation().step_count(); })
      .def_property_readonly("finished", [](const PyRun& r) { return r.run().finished(); })
      .def_property_readonly("out", [](const PyRun& r) { return r.run().root(); })
      .def_property_readonly("particle_count", [](const PyRun& r) { return r.run().simulation().particles().size(); });

  m.attr("particle_fields") = ParticleViews::names();
  m.attr("particle_field_units") = ParticleViews::units();

  m.def(
      "grid_convergence",
      [](double h1, double phi1, double h2, double phi2, double h3, double phi3) {
        const GridConvergenceEstimate e = three_grid_convergence(h1, phi1, h2, phi2, h3, phi3);
        py::dict d;
        d["behaviour"] = e.behaviour;
        d["observed_order"] = e.observed_order ? py::cast(*e.observed_order) : py::none();
        d["order_plausible"] = e.order_plausible;
        d["extrapolated"] = e.extrapolated ? py::cast(*e.extrapolated) : py::none();
        d["approximate_relative_error"] = e.approximate_relative_error;
        d["extrapolated_relative_error"] =
            e.extrapolated_relative_error ? py::cast(*e.extrapolated_relative_error) : py::none();
        d["gci_fine"] = e.gci_fine ? py::cast(*e.gci_fine) : py::none();
        return d;
      },
      py::arg("h1"), py::arg("phi1"), py::arg("h2"), py::arg("phi2"), py::arg("h3"), py::arg("phi3"),
      "Three-grid Richardson extrapolation (Celik et al. 2008) of results phi1..3 at cell sizes h1 < h2 < h3: "
      "dict with behaviour, observed_order, order_plausible, extrapolated, approximate_relative_error, "
      "extrapolated_relative_error, gci_fine (fractions). ValueError for unordered or non-finite input.");
}

}  // namespace mpmcut::python
