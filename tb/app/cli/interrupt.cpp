#include "tb/app/cli/interrupt.h"

#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

namespace cli {

namespace {

volatile std::sig_atomic_t g_caught = 0;
struct sigaction g_previous[2];

void on_signal(int signo) {
    g_caught = signo;
}

}  // namespace

interrupt_catcher::interrupt_catcher() {
    g_caught = 0;
    struct sigaction action = {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;  // no SA_RESTART
    sigaction(SIGINT, &action, &g_previous[0]);
    sigaction(SIGTERM, &action, &g_previous[1]);
}

interrupt_catcher::~interrupt_catcher() {
    sigaction(SIGINT, &g_previous[0], nullptr);
    sigaction(SIGTERM, &g_previous[1], nullptr);
}

int interrupt_catcher::caught() const {
    return g_caught;
}

void untie_forked_child() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    // The parent died before the request: nobody will reap this child's work.
    if (getppid() == 1) _exit(128 + SIGTERM);
}

bool read_resumed(const std::string& dir, const std::string& name, nlohmann::json* document,
                  std::string* error) {
    const std::string path = dir + "/" + name;
    std::ifstream in(path);
    if (!in) {
        *error = "--resume: " + path + " not found (the folder of an interrupted run)";
        return false;
    }
    try {
        *document = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
        *error = "--resume: " + path + " is unreadable: " + e.what();
        return false;
    }
    return true;
}

std::string signal_name(int signo) {
    if (signo == SIGTERM) return "SIGTERM";
    if (signo == SIGINT) return "SIGINT";
    return "signal " + std::to_string(signo);
}

}  // namespace cli
