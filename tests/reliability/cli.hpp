#pragma once
// Drives the real mpmcut program as a user would (fork + exec), for the reliability tests:
// start, signal, kill, wait, read outputs back.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace mpmcut::testing {

namespace fs = std::filesystem;

inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

struct SpawnOptions {
  fs::path log;                    // stdout and stderr go here
  long file_size_limit_bytes = 0;  // RLIMIT_FSIZE in the child; 0 = none
  fs::path program = MPMCUT_BINARY;  // e.g. a copy of it
};

// Starts `mpmcut args...`; returns the child's pid.
inline pid_t spawn_mpmcut(const std::vector<std::string>& args, const SpawnOptions& options) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(options.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    if (options.file_size_limit_bytes > 0) {
      const rlimit limit{static_cast<rlim_t>(options.file_size_limit_bytes),
                         static_cast<rlim_t>(options.file_size_limit_bytes)};
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    // Threads that wait sleep instead of spinning: the tests share a small, busy machine.
    ::setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
    std::vector<char*> argv;
    std::string program = options.program.string();
    argv.push_back(program.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

// Exit code of a finished child; 128 + signal number when a signal ended it.
inline int wait_exit_code(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

// True when the child has already exited (it is reaped, `exit_code` set).
inline bool exited(pid_t pid, int& exit_code) {
  int status = 0;
  if (::waitpid(pid, &status, WNOHANG) != pid) return false;
  exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return true;
}

struct CliResult {
  int exit_code = -1;
  std::string output;  // stdout + stderr
};

inline CliResult run_mpmcut(const std::vector<std::string>& args, const fs::path& log, long file_size_limit = 0) {
  const pid_t pid = spawn_mpmcut(args, {log, file_size_limit});
  CliResult r;
  r.exit_code = wait_exit_code(pid);
  r.output = read_file(log);
  return r;
}

// Polls `condition` every millisecond for at most `seconds`.
inline bool wait_until(const std::function<bool()>& condition, double seconds = 60.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

// Step of the checkpoint that checkpoints/latest names, or -1.
inline long latest_checkpoint_step(const fs::path& result_dir) {
  const std::string name = read_file(result_dir / "checkpoints" / "latest");
  const auto a = name.find('_'), b = name.find(".bin");
  if (a == std::string::npos || b == std::string::npos || b <= a + 1) return -1;
  return std::stol(name.substr(a + 1, b - a - 1));
}

// The number of rows in a run's history.csv (one per step of these cases): > 1 once it steps.
inline std::size_t history_rows(const fs::path& run_dir) {
  const std::string h = read_file(run_dir / "history.csv");
  return static_cast<std::size_t>(std::count(h.begin(), h.end(), '\n'));
}

inline std::string summary_status(const fs::path& result_dir) {
  const std::string s = read_file(result_dir / "summary.json");
  const auto k = s.find("\"status\": \"");
  if (k == std::string::npos) return "";
  const auto start = k + 11;
  return s.substr(start, s.find('"', start) - start);
}

// Every output file of a result directory that must be bit-identical between an uninterrupted
// and a resumed run: all files except summary.json (wall time) and the checkpoints, by path.
inline std::map<std::string, std::string> comparable_outputs(const fs::path& result_dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(result_dir)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = fs::relative(e.path(), result_dir).string();
    if (rel == "summary.json" || rel.starts_with("checkpoints")) continue;
    files[rel] = read_file(e.path());
  }
  return files;
}

// Compares by file name and bytes; reports names, not megabytes of binary.
inline void expect_identical_outputs(const fs::path& expected_dir, const fs::path& actual_dir) {
  const auto expected = comparable_outputs(expected_dir);
  const auto actual = comparable_outputs(actual_dir);
  std::vector<std::string> names_expected, names_actual;
  for (const auto& [k, v] : expected) names_expected.push_back(k);
  for (const auto& [k, v] : actual) names_actual.push_back(k);
  ASSERT_EQ(names_expected, names_actual) << "the two result directories hold different files";
  ASSERT_TRUE(expected.count("history.csv")) << "no history.csv";
  for (const auto& [name, bytes] : expected) {
    EXPECT_TRUE(bytes == actual.at(name)) << name << " differs between " << expected_dir << " and " << actual_dir
                                          << " (" << bytes.size() << " vs " << actual.at(name).size() << " bytes)";
  }
}

}  // namespace mpmcut::testing
