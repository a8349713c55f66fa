#pragma once
// SIGINT/SIGTERM for the whole program (docs/reliability.md, "Signals"). A stop is honoured at any
// moment: outside a step loop (parsing, set-up, analysis, plotting) the first signal terminates
// the registered child processes and exits at once with code 130; inside a step loop (DeferStops)
// the first signal only asks the loop to stop after the current step, so that it can write a
// checkpoint and the outputs so far, and a second one exits at once.
#include <sys/types.h>

namespace mpmcut {

inline constexpr int kExitOnStop = 130;

// Installs the handlers (idempotent). main() calls it first thing.
void install_stop_handlers();

// Signals received since the last DeferStops began (or since start).
int stop_requests();
inline bool stop_requested() { return stop_requests() > 0; }

// In its scope the first signal is only recorded (stop_requested()); a second exits at once.
// Nested scopes are not supported (one step loop at a time).
class DeferStops {
 public:
  DeferStops();
  ~DeferStops();
  DeferStops(const DeferStops&) = delete;
  DeferStops& operator=(const DeferStops&) = delete;
};

// A child process that must not outlive this one when it exits on a signal: SIGTERM is sent to
// it (and to its process group when `group`) before the exit. Up to 64 at a time.
void register_child(pid_t pid, bool group);
void unregister_child(pid_t pid);

// In a freshly forked child, before exec: the child gets SIGTERM when this process dies, even by
// SIGKILL (Linux PR_SET_PDEATHSIG), so that no child is left running as an orphan.
void die_with_parent(pid_t parent);

}  // namespace mpmcut
