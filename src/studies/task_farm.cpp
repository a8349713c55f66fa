#include "studies/task_farm.hpp"

#include <mpi.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace mpmcut {

namespace {

using json = nlohmann::json;

// Message tags of the farm: rank 0 -> worker: a case or the release; worker -> rank 0: a case's outcome.
constexpr int kTagCase = 1;
constexpr int kTagRelease = 2;
constexpr int kTagResult = 3;

// Both sides poll (MPI_Iprobe, then sleep) instead of blocking in MPI_Recv: OpenMPI's blocking receive
// spins a core at 100 %, which would take that core from the case the worker's child process runs.
constexpr auto kPollInterval = std::chrono::milliseconds(20);

struct Farm {
  bool active = false;  // inside run_study under MPI with >= 2 ranks
  int rank = 0, size = 1;
};
Farm g_farm;

volatile std::sig_atomic_t g_farm_stop = 0;
void on_farm_stop(int) { g_farm_stop = g_farm_stop + 1; }

bool env_set(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0';
}

void send_text(const std::string& text, int dest, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD);
}

// Waits (polling) for a message with `tag` from `source` (or any) and returns its text and status.
std::string receive_text(int source, int tag, MPI_Status& status, bool poll_forever = true) {
  int flag = 0;
  while (true) {
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status);
    if (flag || !poll_forever) break;
    std::this_thread::sleep_for(kPollInterval);
  }
  if (!flag) return {};
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

// A worker rank: runs the cases rank 0 sends, one at a time, until released.
void serve_cases() {
  while (true) {
    MPI_Status status;
    int flag = 0;
    while (true) {
      MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      if (flag) break;
      std::this_thread::sleep_for(kPollInterval);
    }
    if (status.MPI_TAG == kTagRelease) {
      MPI_Recv(nullptr, 0, MPI_CHAR, 0, kTagRelease, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return;
    }
    const json task = json::parse(receive_text(0, kTagCase, status));
    std::vector<ChildRun> one(1);
    one[0].name = task.at("name").get<std::string>();
    one[0].args = task.at("args").get<std::vector<std::string>>();
    one[0].log_file = task.at("log").get<std::string>();
    run_children(one, 1, false);
    send_text(json{{"index", task.at("index")}, {"exit_code", one[0].exit_code}, {"wall_time_s", one[0].wall_time_s}}
                  .dump(),
              0, kTagResult);
  }
}

void release_workers() {
  for (int r = 1; r < g_farm.size; ++r) MPI_Send(nullptr, 0, MPI_CHAR, r, kTagRelease, MPI_COMM_WORLD);
}

std::string exit_word(int code) {
  if (code == 0) return "complete";
  if (code == 130) return "interrupted";
  if (code > 128) return fmt::format("killed by signal {}", code - 128);
  return fmt::format("failed (exit status {})", code);
}

// Rank 0: hands the cases out to the workers in order, one per idle worker, and gathers the outcomes.
bool farm_out(std::vector<ChildRun>& runs, bool print_progress) {
  g_farm_stop = 0;
  struct sigaction action {}, old_int{}, old_term{};
  action.sa_handler = on_farm_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &old_int);
  sigaction(SIGTERM, &action, &old_term);

  std::vector<int> case_of_worker(static_cast<std::size_t>(g_farm.size), -1);
  std::size_t next = 0, finished = 0;
  bool warned = false;
  while (true) {
    for (int w = 1; w < g_farm.size && g_farm_stop == 0 && next < runs.size(); ++w) {
      if (case_of_worker[w] >= 0) continue;
      const ChildRun& r = runs[next];
      send_text(json{{"index", next}, {"name", r.name}, {"args", r.args}, {"log", r.log_file.string()}}.dump(), w,
                kTagCase);
      case_of_worker[w] = static_cast<int>(next++);
    }
    bool busy = false;
    for (int w = 1; w < g_farm.size; ++w) busy = busy || case_of_worker[w] >= 0;
    if (!busy) break;
    if (g_farm_stop != 0 && !warned && print_progress) {
      warned = true;
      std::cerr << "\ninterrupted: no more cases handed out; waiting for the running ones (each MPI rank passes "
                   "the signal on to its case, which writes a checkpoint)\n";
    }
    MPI_Status status;
    const std::string text = receive_text(MPI_ANY_SOURCE, kTagResult, status, false);
    if (text.empty()) {
      std::this_thread::sleep_for(kPollInterval);
      continue;
    }
    const json result = json::parse(text);
    ChildRun& run = runs.at(result.at("index").get<std::size_t>());
    run.exit_code = result.at("exit_code").get<int>();
    run.wall_time_s = result.at("wall_time_s").get<double>();
    case_of_worker[status.MPI_SOURCE] = -1;
    ++finished;
    if (print_progress)
      std::cout << fmt::format("[{}/{}] {}: {} ({:.1f} s, rank {}){}\n", finished, runs.size(), run.name,
                               exit_word(run.exit_code), run.wall_time_s, status.MPI_SOURCE,
                               run.exit_code == 0 ? "" : ", log: " + run.log_file.string())
                << std::flush;
    if (run.on_finished) run.on_finished(run);
  }
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  return g_farm_stop == 0;
}

}  // namespace

bool launched_under_mpi() {
  return env_set("OMPI_COMM_WORLD_SIZE") || env_set("PMI_SIZE") || env_set("PMIX_RANK");
}

std::string concurrency_text(int jobs) {
  return g_farm.active ? fmt::format("on {} MPI ranks (rank 0 hands them out)", g_farm.size - 1)
                       : fmt::format("at most {} at a time", jobs);
}

int farm_worker_count() { return g_farm.active ? g_farm.size - 1 : 0; }

int run_study(const std::function<int()>& body) {
  if (!launched_under_mpi() || g_farm.active) return body();
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &g_farm.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_farm.size);
  if (g_farm.size < 2) {  // mpirun -n 1: the local pool, as without MPI
    const int code = body();
    MPI_Finalize();
    return code;
  }
  g_farm.active = true;
  if (g_farm.rank != 0) {
    serve_cases();
    g_farm.active = false;
    MPI_Finalize();
    return 0;
  }
  std::cout << fmt::format("MPI task farm: rank 0 hands out the cases, {} ranks run them\n", g_farm.size - 1)
            << std::flush;
  int code = 0;
  try {
    code = body();
  } catch (...) {
    release_workers();
    g_farm.active = false;
    MPI_Finalize();
    throw;
  }
  release_workers();
  g_farm.active = false;
  MPI_Finalize();
  return code;
}

bool run_cases(std::vector<ChildRun>& runs, int jobs, bool print_progress, double progress_interval_s) {
  if (g_farm.active && g_farm.rank == 0) return farm_out(runs, print_progress);
  return run_children(runs, jobs, print_progress, progress_interval_s);
}

}  // namespace mpmcut
