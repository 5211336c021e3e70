#include "base/progress.h"

#include "base/errors.h"

namespace radbake {

void Progress::begin(const std::string& stage, size_t total) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = stage;
    total_ = total > 0 ? total : 1;
    done_ = 0;
  }
  call(0.0);
}

void Progress::advance(size_t units) {
  size_t done = done_ += units;
  if (cancelled_) throw Cancelled();
  // Rate-limited: a callback per work unit would serialise the worker threads on the mutex.
  auto now = std::chrono::steady_clock::now();
  {
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || now - last_call_ < std::chrono::milliseconds(100)) return;
    last_call_ = now;
  }
  call(double(done) / double(total_));
  if (cancelled_) throw Cancelled();
}

void Progress::end() { call(1.0); }

void Progress::call(double fraction) {
  if (!callback_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (!callback_(stage_, fraction > 1.0 ? 1.0 : fraction)) cancelled_ = true;
  if (cancelled_) throw Cancelled();
}

}  // namespace radbake
