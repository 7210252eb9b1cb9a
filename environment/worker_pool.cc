#include "cbbg/environment/worker_pool.h"

#include <stdexcept>
#include <string>

namespace cbbg::environment {
namespace {

// How long a thread spins before it sleeps: about 100 us of pauses on this kind of machine.
constexpr int kSpins = 2000;

void pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

}  // namespace

WorkerPool::WorkerPool(int threads) {
  if (threads < 1) {
    throw std::invalid_argument("a worker pool needs at least 1 thread; got " +
                                std::to_string(threads));
  }
  errors_.resize(static_cast<std::size_t>(threads));
  for (int share = 1; share < threads; ++share) {
    workers_.emplace_back([this, share] { serve(share); });
  }
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

template <typename Done>
void WorkerPool::wait(std::condition_variable& wake, Done done) {
  for (int spin = 0; spin < kSpins; ++spin) {
    if (done()) return;
    pause();
  }
  std::unique_lock lock(mutex_);
  wake.wait(lock, done);
}

void WorkerPool::run(int count, const std::function<void(int, int)>& work) {
  count_ = count;
  work_ = &work;
  pending_ = static_cast<int>(workers_.size());
  {
    const std::lock_guard lock(mutex_);  // a sleeping worker sees the new generation
    ++generation_;
  }
  start_.notify_all();
  run_share(0);
  wait(finished_, [this] { return pending_.load() == 0; });
  std::exception_ptr first;
  for (std::exception_ptr& error : errors_) {
    if (error && !first) first = error;
    error = nullptr;
  }
  if (first) std::rethrow_exception(first);
}

void WorkerPool::serve(int share) {
  long long seen = 0;
  for (;;) {
    wait(start_, [&] { return stopping_.load() || generation_.load() != seen; });
    if (stopping_) return;
    seen = generation_;
    run_share(share);
    if (pending_.fetch_sub(1) == 1) {
      const std::lock_guard lock(mutex_);  // the caller, asleep or about to be, is woken
      finished_.notify_one();
    }
  }
}

void WorkerPool::run_share(int share) {
  const int n = threads();
  const int begin = static_cast<int>(static_cast<long long>(count_) * share / n);
  const int end = static_cast<int>(static_cast<long long>(count_) * (share + 1) / n);
  if (begin == end) return;
  try {
    (*work_)(begin, end);
  } catch (...) {
    errors_[static_cast<std::size_t>(share)] = std::current_exception();
  }
}

}  // namespace cbbg::environment
