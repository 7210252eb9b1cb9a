#pragma once
// Threads that stay between calls and share out a range of work: the vectorised
// environment's per-step fan-out, where creating threads at every step would cost more than
// the step. The caller's thread takes the first share, so `threads` includes it. Between
// calls each thread spins a little before it sleeps: a step of 64 robots takes about 100 us,
// less than waking a sleeping thread costs.

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace cbbg::environment {

class WorkerPool {
 public:
  // `threads` >= 1 threads in all (threads - 1 started here).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls work(begin, end) on contiguous shares of [0, count), one per thread, and returns
  // when all are done. The shares depend only on count and threads(). An exception a share
  // throws is rethrown here, the lowest share's first, after all have finished.
  void run(int count, const std::function<void(int begin, int end)>& work);

 private:
  void serve(int share);
  void run_share(int share);
  // Waits until `done` holds: spinning first, then asleep on `wake` (notified under mutex_).
  template <typename Done>
  void wait(std::condition_variable& wake, Done done);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable finished_;
  std::atomic<long long> generation_ = 0;  // bumped by each run; a worker runs once per one
  std::atomic<int> pending_ = 0;           // workers still running this generation
  std::atomic<bool> stopping_ = false;
  int count_ = 0;
  const std::function<void(int, int)>* work_ = nullptr;
  std::vector<std::exception_ptr> errors_;  // one per share
};

}  // namespace cbbg::environment
