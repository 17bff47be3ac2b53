#include "interrupt.h"

#include <csignal>

#include "orb/cli/tool_main.h"

namespace orb::render_cli {
namespace {

std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_first_signal = 0;

static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");

extern "C" void on_stop_signal(int signal_number) {
    if (g_first_signal == 0) g_first_signal = signal_number;
    g_stop.store(true);
}

void install(int signal_number) {
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    // One-shot: the next identical signal kills, for a user who will not wait.
    // SA_RESTART keeps OpenCL runtime threads' system calls from failing.
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    sigaction(signal_number, &action, nullptr);
}

}  // namespace

void install_interrupt_handlers() {
    install(SIGINT);
    install(SIGTERM);
    install(SIGHUP);  // a dropped ssh session or a closed terminal: save the work, like SIGTERM
}

const std::atomic<bool>& interrupt_requested() { return g_stop; }

int interrupt_exit_code() { return g_first_signal == 0 ? 0 : 128 + static_cast<int>(g_first_signal); }

int stopped_exit_code() { return interrupt_exit_code() ? interrupt_exit_code() : cli::kFailure; }

}  // namespace orb::render_cli
