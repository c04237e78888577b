#include "tb/app/cli/interrupt.h"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <thread>

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

pid_t fork_untied() {
    sigset_t held, previous;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    sigprocmask(SIG_BLOCK, &held, &previous);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid == 0) {
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        // The parent died before the request: nobody will reap this child's work.
        if (getppid() != parent) _exit(128 + SIGTERM);
    }
    sigprocmask(SIG_SETMASK, &previous, nullptr);
    return pid;
}

pid_t wait_child(const interrupt_catcher& interrupt, int* status) {
    for (;;) {
        const pid_t pid = waitpid(-1, status, WNOHANG);
        if (pid > 0) return pid;
        if (pid < 0 && errno != EINTR) return -1;
        if (interrupt.caught()) return 0;
        // Polled: a child's end interrupts no sleep (SIGCHLD is ignored).
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

void stop_children(const std::vector<pid_t>& children, double grace_s) {
    for (pid_t pid : children) kill(pid, SIGTERM);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(grace_s);
    std::vector<pid_t> left = children;
    while (!left.empty() && std::chrono::steady_clock::now() < deadline) {
        std::vector<pid_t> still;
        for (pid_t pid : left) {
            int status = 0;
            const pid_t r = waitpid(pid, &status, WNOHANG);
            if (r == 0 || (r < 0 && errno == EINTR)) still.push_back(pid);
        }
        left.swap(still);
        if (!left.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    for (pid_t pid : left) {
        kill(pid, SIGKILL);
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
}

void die_of(int signo) {
    std::fflush(nullptr);
    std::signal(signo, SIG_DFL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, signo);
    sigprocmask(SIG_UNBLOCK, &set, nullptr);
    raise(signo);
    _exit(128 + signo);
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
