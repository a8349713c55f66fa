#include "app/stop_signal.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

#include "run/repeated_signal.hpp"

namespace mpmcut {

namespace {

StopToken g_stop;
RepeatedSignalFilter g_repeats;
// Children to terminate on an immediate exit: +pid (the process) or -pid (its group), 0 = free.
// A fixed array of lock-free atomics: the signal handler may read it at any moment.
constexpr int kMaxChildren = 64;
std::atomic<pid_t> g_children[kMaxChildren];

void say(const char* text) {
  // write(2) is async-signal-safe; the return value is irrelevant when stderr is gone.
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, text, std::strlen(text));
}

extern "C" void on_stop_signal(int signal_number) {
  if (!g_repeats.is_new_stop()) return;  // the same stop, delivered twice
  if (g_stop.request_stop(signal_number)) return;  // the run loop stops after this step
  for (auto& child : g_children) {
    const pid_t target = child.load();
    if (target != 0) ::kill(target, SIGTERM);
  }
  // After a run has completed (its loop over, the program on its way out) the results are whole: say so.
  say(g_stop.results_complete()
          ? "\ninterrupted after the run completed: results complete, pictures not drawn (exit code 130)\n"
          : "\ninterrupted: stopped by a signal (exit code 130)\n");
  ::_exit(kExitOnStop);
}

}  // namespace

void install_stop_handlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

StopToken& program_stop_token() { return g_stop; }

void register_child(pid_t pid, bool group) {
  for (auto& child : g_children) {
    pid_t expected = 0;
    if (child.compare_exchange_strong(expected, group ? -pid : pid)) return;
  }
}

void unregister_child(pid_t pid) {
  for (auto& child : g_children) {
    pid_t target = child.load();
    if (target == pid || target == -pid) child.compare_exchange_strong(target, 0);
  }
}

void die_with_parent(pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) ::_exit(kExitOnStop);  // the parent died before prctl took effect
}

}  // namespace mpmcut
