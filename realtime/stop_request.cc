// The stop request: one lock-free flag written by the signal handler.

#include "cbbg/realtime/stop_request.h"

#include <atomic>
#include <csignal>

namespace cbbg::realtime {
namespace {

std::atomic<int> requested_by{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_stop_signal(int signal) { requested_by.store(signal); }

}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a wait returns at once with EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool stop_requested() { return requested_by.load() != 0; }

const char* stop_signal_name() {
  switch (requested_by.load()) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "";
  }
}

void clear_stop_request() { requested_by.store(0); }

}  // namespace cbbg::realtime
