// Long stages report how far they are through a callback that may ask them to stop, the way
// xatlas's ProgressFunc and Godot's BakeStepFunc do. Safe to call from worker threads.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <string>

namespace radbake {

// Wall-clock seconds since `start`: what the report gives each stage.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Receives the stage name and the fraction done in [0, 1]; returns false to cancel the bake.
using ProgressCallback = std::function<bool(const std::string& stage, double fraction)>;

class Progress {
 public:
  explicit Progress(ProgressCallback callback = {}) : callback_(std::move(callback)) {}

  // Starts a stage of `total` work units.
  void begin(const std::string& stage, size_t total);
  // Adds finished work units; throws Cancelled if the callback asked to stop.
  void advance(size_t units = 1);
  void end();

 private:
  void call(double fraction);

  ProgressCallback callback_;
  std::mutex mutex_;
  std::string stage_;
  size_t total_ = 1;
  std::atomic<size_t> done_{0};
  std::atomic<bool> cancelled_{false};
  std::chrono::steady_clock::time_point last_call_;
};

}  // namespace radbake
