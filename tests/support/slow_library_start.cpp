// A shared library that takes 2 s to start, preloaded into radbake by a test
// (Interrupt.ASignalWhileTheLibrariesStartEndsWithTheCancelledLine) to stretch the moment
// radbake's own libraries take to start (about 0.2 s) until a signal can be sent into it.
// It makes the file RADBAKE_TEST_LIBRARY_BEGAN names as it begins, so that the test signals
// within those 2 s however slowly the machine loaded radbake up to here.
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

__attribute__((constructor)) static void start_slowly() {
  const char* began = getenv("RADBAKE_TEST_LIBRARY_BEGAN");
  if (began && *began) {
    const int fd = open(began, O_CREAT | O_WRONLY, 0644);
    if (fd >= 0) close(fd);
  }
  usleep(2000000);
}
