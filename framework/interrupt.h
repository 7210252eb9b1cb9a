#pragma once
// Interrupts: stopping long work early (Ctrl-C in Python). The process's interrupt check,
// none by default, throws to stop: advance_to calls it between event instants, at most every
// 10 ms of wall time, and lets what it throws end the call (the context at that instant, the
// simulator able to go on). The Python module sets one that raises KeyboardInterrupt once
// Ctrl-C is pressed. Set it before simulating.

#include <atomic>
#include <exception>
#include <mutex>

namespace cbbg {

using InterruptCheck = void (*)();
void set_interrupt_check(InterruptCheck check);
// Calls the interrupt check now (a thread that waits for simulations calls it too). In a
// member of an InterruptGroup, first rethrows the group's interrupt, if it has one.
void check_interrupt();
// Throws `interrupt` (what an interrupt check throws, or an interrupt found another way, such
// as a Python block's KeyboardInterrupt), first making it the interrupt of the calling
// thread's group, if any.
[[noreturn]] void throw_interrupt(std::exception_ptr interrupt);

// Threads that stop together (parallel_runs: the threads of one experiment): an interrupt
// in one is rethrown by the others' next check.
class InterruptGroup {
 public:
  // The calling thread is a member while it lives.
  class Membership {
   public:
    explicit Membership(InterruptGroup& group);
    ~Membership();
    Membership(const Membership&) = delete;
    Membership& operator=(const Membership&) = delete;

   private:
    InterruptGroup* previous_;
  };

 private:
  friend void check_interrupt();
  friend void throw_interrupt(std::exception_ptr interrupt);
  std::atomic<bool> interrupted_{false};
  std::mutex mutex_;
  std::exception_ptr interrupt_;  // the first, guarded by mutex_
};

// In a simulation's loop (Simulator::advance_to, between event instants): calls the check
// where one is set and 10 ms of wall time have passed since this thread's last call.
void poll_interrupt();

}  // namespace cbbg
