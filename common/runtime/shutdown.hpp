// Clean shutdown on SIGINT/SIGTERM: the signals are blocked in every thread and collected by one
// watcher thread, so no DDS thread is interrupted mid-write and the frame loop ends between
// frames.
#pragma once

#include <chrono>

namespace fedsim::runtime {

/// Blocks SIGINT/SIGTERM process-wide and starts the watcher thread. Call first thing in main,
/// before any other thread exists (threads inherit the signal mask). Idempotent.
void install_shutdown_handler();

/// True once a signal arrived or request_shutdown() was called.
bool shutdown_requested();
void request_shutdown();
/// Waits until shutdown is requested or the timeout passes; true if requested.
bool wait_for_shutdown(std::chrono::milliseconds timeout);
/// The signal that triggered shutdown (0 if none, e.g. a programmatic request).
int shutdown_signal();

}  // namespace fedsim::runtime
