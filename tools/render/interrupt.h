// SIGINT/SIGTERM/SIGHUP as a request to stop after the pass in flight. The handler
// only sets an atomic flag that the progressive loop polls between passes; a
// second signal of the same kind ends the process the default way.
#pragma once

#include <atomic>

namespace orb::render_cli {

void install_interrupt_handlers();
const std::atomic<bool>& interrupt_requested();

// 128 + the first signal's number (130 for SIGINT, 143 for SIGTERM, 129 for SIGHUP), the
// shell's convention for "ended by a signal"; 0 if none arrived.
int interrupt_exit_code();
// The exit code of a run that stopped short: interrupt_exit_code(), or 1
// (failed) when no signal stopped it.
int stopped_exit_code();

}  // namespace orb::render_cli
