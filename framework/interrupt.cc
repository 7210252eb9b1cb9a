#include "cbbg/framework/interrupt.h"

#include <chrono>

namespace cbbg {
namespace {

std::atomic<InterruptCheck> interrupt_check{nullptr};
thread_local InterruptGroup* interrupt_group = nullptr;
// When this thread's simulations next call the interrupt check.
thread_local std::chrono::steady_clock::time_point next_interrupt_check{};
constexpr std::chrono::milliseconds kInterruptCheckInterval{10};

}  // namespace

void poll_interrupt() {
  if (interrupt_check.load(std::memory_order_relaxed) == nullptr) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_interrupt_check) return;
  next_interrupt_check = now + kInterruptCheckInterval;
  check_interrupt();
}

void set_interrupt_check(InterruptCheck check) { interrupt_check.store(check); }

void check_interrupt() {
  InterruptGroup* group = interrupt_group;
  if (group != nullptr && group->interrupted_.load(std::memory_order_acquire)) {
    std::exception_ptr interrupt;
    {
      const std::lock_guard<std::mutex> lock(group->mutex_);
      interrupt = group->interrupt_;
    }
    std::rethrow_exception(interrupt);
  }
  const InterruptCheck check = interrupt_check.load(std::memory_order_acquire);
  if (check == nullptr) return;
  try {
    check();
  } catch (...) {
    throw_interrupt(std::current_exception());
  }
}

void throw_interrupt(std::exception_ptr interrupt) {
  if (InterruptGroup* group = interrupt_group; group != nullptr) {
    const std::lock_guard<std::mutex> lock(group->mutex_);
    if (!group->interrupt_) group->interrupt_ = interrupt;
    group->interrupted_.store(true, std::memory_order_release);
  }
  std::rethrow_exception(interrupt);
}

InterruptGroup::Membership::Membership(InterruptGroup& group) : previous_(interrupt_group) {
  interrupt_group = &group;
}

InterruptGroup::Membership::~Membership() { interrupt_group = previous_; }

}  // namespace cbbg
