#include "cli/interrupts.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>
#include <thread>

#include "base/errors.h"
#include "io/run/output_folder.h"

namespace radbake {
namespace {

sigset_t watched;
std::atomic<int> signal_number{0};
// Guards the two below; the watcher keeps it until _exit, so the main thread cannot destroy the
// folder while it is being abandoned.
std::mutex folder_mutex;
StagedFolder* folder_to_abandon = nullptr;
bool output_in_place = false;  // the bake committed its output: too late to cancel, let it finish

void write_stderr(const char* text) {
  ssize_t ignored = write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

void watch() {
  int sig = 0;
  if (sigwait(&watched, &sig) != 0) return;
  signal_number = sig;
  const timespec grace{1, 0};
  sigtimedwait(&watched, nullptr, &grace);  // the grace second, cut short by a second signal
  std::lock_guard<std::mutex> lock(folder_mutex);
  if (output_in_place || (folder_to_abandon && !folder_to_abandon->abandon())) return;
  write_stderr("\nradbake: cancelled; nothing was written\n");
  _exit(128 + sig);
}

void block_watched_signals() {
  sigemptyset(&watched);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&watched, sig);
  pthread_sigmask(SIG_BLOCK, &watched, nullptr);
}

// The signals are blocked before any shared library's constructor runs (an executable's
// .preinit_array runs first): radbake's 272 libraries take about 0.2 s to initialise, and a
// signal then ended radbake by its default action, with no word said. Held pending, it is taken
// by the watcher once main starts it.
void block_before_libraries_start(int, char**, char**) { block_watched_signals(); }
__attribute__((section(".preinit_array"), used)) void (*const block_early)(int, char**, char**) =
    &block_before_libraries_start;

}  // namespace

void watch_interrupts() {
  block_watched_signals();
  std::thread(watch).detach();
}

bool interrupted() { return signal_number != 0; }

void stop_if_interrupted() {
  if (interrupted()) throw Cancelled();
}

int interrupted_exit_status() { return signal_number ? 128 + signal_number : 1; }

AbandonOnInterrupt::AbandonOnInterrupt(StagedFolder& folder) : folder_(folder) {
  std::lock_guard<std::mutex> lock(folder_mutex);
  folder_to_abandon = &folder;
}

AbandonOnInterrupt::~AbandonOnInterrupt() {
  std::lock_guard<std::mutex> lock(folder_mutex);
  output_in_place = folder_.committed();
  folder_to_abandon = nullptr;
}

}  // namespace radbake
