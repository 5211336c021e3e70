// What keeps `radbake view`'s server answering whoever else connects: a fixed number of
// connections served at once (each on its own worker, so a slow one holds only itself), a bounded
// number waiting for a worker (more are closed at once), and a deadline for each request's header,
// counted from when the connection was taken or its last answer went out. cpp-httplib 0.11 times
// out each read alone: a client that sends a header line every 2 s held a worker for ever, and 40
// of them held them all.
#pragma once

#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <memory>

namespace radbake {

struct ConnectionLimits {
  size_t served_at_once = 128;
  // Beyond these, a new connection is closed unanswered. Each holds two descriptors (httplib's
  // socket and the guard's duplicate), which the usual limit of 1,024 bounds.
  size_t waiting = 256;
  // A header on 127.0.0.1 takes microseconds; a browser's idle connection is closed by httplib's
  // keep-alive timeout (5 s) before this.
  std::chrono::milliseconds header_deadline{8000};
};

class ConnectionGuard {
 public:
  explicit ConnectionGuard(ConnectionLimits limits);

  // Sets the server's task queue, and the hooks that tell a request's header from its answer.
  void guard(httplib::Server& server);

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace radbake
