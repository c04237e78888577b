// SIGINT and SIGTERM while a campaign or a sweep runs its children (a Ctrl-C,
// a Slurm time limit): caught, so that the runner stops its children and
// writes what finished, marked incomplete, instead of dying and leaving them
// running (docs/cli.md, "Interrupted runs"). `--resume DIR` then runs only
// what is missing.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cli {

class interrupt_catcher {
  public:
    // Installs the handlers, without SA_RESTART: a blocking wait returns EINTR.
    interrupt_catcher();
    ~interrupt_catcher();
    interrupt_catcher(const interrupt_catcher&) = delete;
    interrupt_catcher& operator=(const interrupt_catcher&) = delete;
    // The signal caught since, 0 if none.
    int caught() const;
};

// fork() for a runner's child that runs on without exec: SIGINT and SIGTERM
// held over the fork (a signal then reaches the parent's handler, not a
// child without its own), their default actions back in the child, and
// SIGTERM to the child when its parent dies (PR_SET_PDEATHSIG), so that no
// run outlives the process that started it. fork()'s result.
pid_t fork_untied();

// Waits for any child to end without missing an interrupt (a signal between
// a look at caught() and a blocking wait would be): the child's pid, 0 when
// an interrupt came first, -1 when there is no child.
pid_t wait_child(const interrupt_catcher& interrupt, int* status);

// SIGTERM to each child, SIGKILL to those still running after `grace_s`;
// reaps them all.
void stop_children(const std::vector<pid_t>& children, double grace_s = 10);

// After the files of an interrupted run are written: the signal's default
// action, so that the caller's shell sees the process killed by it.
[[noreturn]] void die_of(int signo);

// "SIGTERM", "SIGINT", else "signal N".
std::string signal_name(int signo);

// --resume DIR: the interrupted run's document DIR/NAME (campaign.json,
// sweep.json); false and *error (one line) if it is missing or unreadable.
bool read_resumed(const std::string& dir, const std::string& name, nlohmann::json* document,
                  std::string* error);

}  // namespace cli
