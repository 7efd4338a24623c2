// A flag for work done at most once, by whichever thread asks first, as
// std::call_once, without its cost on a fresh flag: glibc's pthread_once
// ends every first call with a futex wake (a system call), and a check
// makes its flags afresh for each query (Filtered_runner builds an object's
// exact model only when asked). Here the first call takes an uncontended
// mutex instead. As std::call_once, a call that throws leaves the flag
// unset for the next caller.
#ifndef CLASH4D_EXACT_LAZY_ONCE_H
#define CLASH4D_EXACT_LAZY_ONCE_H

#include <atomic>
#include <mutex>

namespace clash4d {

class Lazy_once {
public:
  template <class F>
  void call(F&& f)
  {
    if (done_.load(std::memory_order_acquire)) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (done_.load(std::memory_order_relaxed)) return;
    f();
    done_.store(true, std::memory_order_release);
  }
  // The work to be done again by the next call (a prepared scene's object
  // moved: exact/Exact_checker.h). Only while no call runs.
  void reset() { done_.store(false, std::memory_order_relaxed); }

private:
  std::atomic<bool> done_{false};
  std::mutex mutex_;
};

} // namespace clash4d

#endif
