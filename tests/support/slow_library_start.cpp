// A shared library that takes 2 s to start, preloaded into radbake by a test
// (Interrupt.ASignalWhileTheLibrariesStartEndsWithTheCancelledLine) to stretch the moment
// radbake's own libraries take to start (about 0.2 s) until a signal can be sent into it.
#include <unistd.h>

__attribute__((constructor)) static void start_slowly() { usleep(2000000); }
