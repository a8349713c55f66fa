#include "app/plot_command.hpp"
#include "app/stop_signal.hpp"
#include "app/path_option.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/input_error.hpp"
#include "io/pvd_writer.hpp"
#include "run/case_loading.hpp"
#include "run/run_outputs.hpp"
#include "run/run_options.hpp"
#include "run/run_summary.hpp"

namespace mpmcut {

namespace {

// A temporary folder holding tools/*.py (and data/experiments/*), removed when it goes out of scope.
class ToolFolder {
 public:
  ToolFolder() {
    if (const char* dir = std::getenv("MPMCUT_TOOLS_DIR"); dir && *dir) {
      tools_ = dir;
      return;
    }
    std::string pattern = (std::filesystem::temp_directory_path() / "mpmcut_tools_XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder for the plot scripts");
    root_ = pattern;
    for (const EmbeddedText& f : embedded_tool_files()) {
      const std::filesystem::path p = root_ / std::filesystem::path(f.path);
      std::filesystem::create_directories(p.parent_path());
      std::ofstream(p, std::ios::binary) << f.text;
    }
    tools_ = root_ / "tools";
  }
  ~ToolFolder() {
    std::error_code ec;
    if (!root_.empty()) std::filesystem::remove_all(root_, ec);
  }
  ToolFolder(const ToolFolder&) = delete;
  ToolFolder& operator=(const ToolFolder&) = delete;
  const std::filesystem::path& tools() const { return tools_; }

 private:
  std::filesystem::path root_, tools_;
};

// fork + exec + wait; stdout/stderr inherited unless `quiet`. Returns the exit status, 127 if exec failed.
int run_and_wait(const std::vector<std::string>& argv, bool quiet) {
  std::vector<char*> c_argv;
  for (const std::string& a : argv) c_argv.push_back(const_cast<char*>(a.c_str()));
  c_argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    die_with_parent(parent);
    if (quiet) {
      const FILE* devnull = freopen("/dev/null", "w", stdout);
      (void)devnull;
      dup2(STDOUT_FILENO, STDERR_FILENO);
    }
    execv(c_argv[0], c_argv.data());
    _exit(127);
  }
  // A signal now ends this program at once (app/stop_signal); the plotter goes with it.
  register_child(pid, false);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      unregister_child(pid);
      return 127;
    }
  }
  unregister_child(pid);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// --snapshots: "last", "all" or snapshot numbers N,M,... each of which the run wrote (particles.pvd lists them), and
// the files of the snapshots to draw present. An InputError naming the first that is not: a number the run does not
// have was a warning (and the last was drawn), a deleted snapshot file a Python traceback.
void check_snapshot_choice(const std::filesystem::path& dir, const std::string& choice) {
  namespace fs = std::filesystem;
  std::vector<PvdSeries::Entry> entries;
  try {
    if (fs::exists(dir / "particles.pvd")) entries = PvdSeries::read(dir / "particles.pvd").entries();  // a copy
  } catch (const std::exception& e) {
    throw InputError(fmt::format("cannot read the run's particles.pvd: {}", e.what()));
  }
  if (entries.empty()) return;  // the plotter says that there is no snapshot to draw
  const auto name_of = [](const PvdSeries::Entry& e) { return fs::path(e.file).filename().string(); };
  std::vector<const PvdSeries::Entry*> drawn{&entries.back()};  // the last is always drawn
  if (choice == "all") {
    drawn.clear();
    for (const PvdSeries::Entry& e : entries) drawn.push_back(&e);
  } else if (choice != "last") {
    std::size_t start = 0;
    while (start <= choice.size()) {
      const std::size_t comma = std::min(choice.find(',', start), choice.size());
      const std::string item = choice.substr(start, comma - start);
      const long n = snapshot_number(item);
      if (n < 0)
        throw InputError(fmt::format("--snapshots '{}': expected last, all, or snapshot numbers N,M,... (0, 1, ...); "
                                     "got '{}'",
                                     choice, item));
      const auto it =
          std::find_if(entries.begin(), entries.end(), [&](const auto& e) { return snapshot_index(name_of(e)) == n; });
      if (it == entries.end())
        throw InputError(fmt::format("--snapshots {}: no such snapshot; this run has {} ({} to {})", n, entries.size(),
                                     name_of(entries.front()), name_of(entries.back())));
      drawn.push_back(&*it);
      start = comma + 1;
    }
  }
  for (const PvdSeries::Entry* e : drawn)
    if (!fs::exists(dir / e->file))
      throw InputError(fmt::format("the snapshot {} that particles.pvd lists is missing from '{}' (deleted or moved?)",
                                   e->file, dir.string()));
}

}  // namespace

std::string_view embedded_tool_file(std::string_view path) {
  for (const EmbeddedText& f : embedded_tool_files())
    if (f.path == path) return f.text;
  throw std::runtime_error(fmt::format("{} was not compiled into this mpmcut (CMakeLists.txt, embedded plot scripts)", path));
}

std::string python_interpreter() {
  if (const char* p = std::getenv("MPMCUT_PYTHON"); p && *p) return p;
  return "/usr/bin/python3";
}

bool python_plotting_available(bool need_meshio, std::string& why) {
  const std::string python = python_interpreter();
  if (access(python.c_str(), X_OK) != 0) {
    why = fmt::format("{} not found: plots need Python 3 with numpy and matplotlib{} "
                      "(Debian/Ubuntu: apt install python3-matplotlib{}; or set MPMCUT_PYTHON)",
                      python, need_meshio ? " and meshio" : "", need_meshio ? " python3-meshio" : "");
    return false;
  }
  const std::string imports = need_meshio ? "import numpy, matplotlib, meshio" : "import numpy, matplotlib";
  if (run_and_wait({python, "-c", imports}, true) != 0) {
    why = fmt::format("{} cannot '{}': install them (Debian/Ubuntu: apt install python3-matplotlib{}) "
                      "or point MPMCUT_PYTHON at a Python that has them",
                      python, imports, need_meshio ? " python3-meshio" : "");
    return false;
  }
  return true;
}

int run_python_tool(const std::string& script, const std::vector<std::string>& args) {
  ToolFolder folder;
  const std::filesystem::path path = folder.tools() / script;
  if (!std::filesystem::exists(path)) {
    std::cerr << "error: plot script " << path << " not found\n";
    return 127;
  }
  std::vector<std::string> argv{python_interpreter(), path.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_and_wait(argv, false);
}

void add_plot_command(CLI::App& app) {
  struct Options {
    std::string result_dir;
    std::string snapshots = "last";
  };
  auto options = std::make_shared<Options>();
  CLI::App* plot = app.add_subcommand(
      "plot", "Draw PNG pictures of a result directory: the chip coloured by temperature, plastic strain and "
              "damage with the tool, and the force history (needs /usr/bin/python3 with matplotlib and meshio)");
  plot->add_option("result_dir", options->result_dir, "Result directory of a run")->required()->check(non_empty_path());
  plot->add_option("--snapshots", options->snapshots,
                   "Snapshots to draw: last (default), all, or snapshot numbers N,M,... (the last is always drawn)");
  plot->callback([options]() {
    try {
      (void)load_cutting_result_scene(options->result_dir, "the pictures are of a cut's chip, tool and forces; open "
                                                            "its particles.pvd in ParaView instead");
      check_snapshot_choice(options->result_dir, options->snapshots);
      // The pictures of the steady window and the profile come from the summary: a damaged one is the user's to fix.
      try {
        (void)read_summary(std::filesystem::path(options->result_dir) / "summary.json");
      } catch (const std::exception& e) {
        throw InputError(fmt::format("{}/summary.json cannot be read ({}): the run's results are damaged; rerun it "
                                     "or resume it",
                                     options->result_dir, e.what()));
      }
    } catch (const InputError& e) {
      std::cerr << "error: " << e.what() << "\n";
      throw CLI::RuntimeError(kExitInputError);
    }
    std::string why;
    if (!python_plotting_available(true, why)) {
      std::cerr << "warning: cannot plot: " << why << "\n";
      throw CLI::RuntimeError(5);
    }
    const int code = run_python_tool("plot_result.py", {options->result_dir, "--snapshots", options->snapshots});
    if (code != 0) std::cerr << "error: plotting failed (plot_result.py exit status " << code << ")\n";
    throw CLI::RuntimeError(code);  // also on success: the subcommand is done, main() must not go on
  });
}

}  // namespace mpmcut
