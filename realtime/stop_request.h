#pragma once
// SIGINT and SIGTERM as a request to stop a real-time loop cleanly (the motors at zero, the
// peer told), rather than the end of the process: the loop polls stop_requested() and waits
// no longer than a period at a time.

namespace cbbg::realtime {

// From now on SIGINT and SIGTERM set the request instead of ending the process.
void install_stop_handlers();
bool stop_requested();
// "SIGINT" or "SIGTERM": the signal that asked; "" before any.
const char* stop_signal_name();
// Forgets a request (tests, and a server between sessions it was not asked to end).
void clear_stop_request();

}  // namespace cbbg::realtime
