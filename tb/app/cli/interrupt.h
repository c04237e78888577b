// SIGINT and SIGTERM while a campaign or a sweep runs its children (a Ctrl-C,
// a Slurm time limit): caught, so that the runner stops its children and
// writes what finished, marked incomplete, instead of dying and leaving them
// running (docs/cli.md, "Interrupted runs"). `--resume DIR` then runs only
// what is missing.
#pragma once

#include <string>

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

// In a child a runner forked (no exec): the default actions of SIGINT and
// SIGTERM back, and SIGTERM when its parent dies (PR_SET_PDEATHSIG), so that
// no run outlives the process that started it.
void untie_forked_child();

// "SIGTERM", "SIGINT", else "signal N".
std::string signal_name(int signo);

// --resume DIR: the interrupted run's document DIR/NAME (campaign.json,
// sweep.json); false and *error (one line) if it is missing or unreadable.
bool read_resumed(const std::string& dir, const std::string& name, nlohmann::json* document,
                  std::string* error);

}  // namespace cli
