// SIGINT, SIGTERM and SIGHUP end radbake within about a second, in any stage, and leave nothing
// behind; the exit status is 128 + the signal's number, as shells report a process a signal ended
// (130 for Ctrl-C, 143 for SIGTERM).
//
// The signals are blocked in every thread and taken by one watcher thread (sigwait), so no
// handler interrupts the code at an arbitrary point: the watcher sets the flag that the progress
// callbacks poll, and the main thread unwinds through StagedFolder's destructor, which removes
// the staging folder. Some work cannot poll (tinygltf parsing a large file, OpenEXR writing a
// page); when the main thread has not ended the process a second after the signal, or at a
// second signal, the watcher removes the staging folder itself (StagedFolder::abandon) and ends
// the process with _exit.
#pragma once

namespace radbake {

class StagedFolder;

// Starts the watcher. Call first in main. The signals are blocked from before main (threads
// inherit the mask), so one sent while radbake starts waits for the watcher.
void watch_interrupts();

bool interrupted();
void stop_if_interrupted();  // throws Cancelled once a signal arrived
int interrupted_exit_status();

// While it lives, the watcher abandons `folder` if it has to end the process itself.
class AbandonOnInterrupt {
 public:
  explicit AbandonOnInterrupt(StagedFolder& folder);
  ~AbandonOnInterrupt();
  AbandonOnInterrupt(const AbandonOnInterrupt&) = delete;
  AbandonOnInterrupt& operator=(const AbandonOnInterrupt&) = delete;

 private:
  StagedFolder& folder_;
};

}  // namespace radbake
