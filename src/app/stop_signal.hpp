#pragma once
// SIGINT/SIGTERM for the whole program (docs/reliability.md, "Signals"). A stop is honoured at any
// moment: outside a step loop (parsing, set-up, analysis, plotting) the first signal terminates
// the registered child processes and exits at once with code 130; while a run loop runs on the
// program's stop token (run/stop_token.hpp) the first signal only requests a stop on it, so that
// the loop stops after the current step and writes a checkpoint and the outputs so far, and a
// second one exits at once.
#include <sys/types.h>

#include "run/stop_token.hpp"

namespace mpmcut {

inline constexpr int kExitOnStop = 130;

// Installs the handlers (idempotent). main() calls it first thing.
void install_stop_handlers();

// The program's stop token, which the signals request stops on (the run options carry it).
StopToken& program_stop_token();

// A child process that must not outlive this one when it exits on a signal: SIGTERM is sent to
// it (and to its process group when `group`) before the exit. Up to 64 at a time.
void register_child(pid_t pid, bool group);
void unregister_child(pid_t pid);

// In a freshly forked child, before exec: the child gets SIGTERM when this process dies, even by
// SIGKILL (Linux PR_SET_PDEATHSIG), so that no child is left running as an orphan.
void die_with_parent(pid_t parent);

}  // namespace mpmcut
