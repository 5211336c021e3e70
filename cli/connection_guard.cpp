#include "cli/connection_guard.h"

#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

namespace {

thread_local int last_accepted_socket = -1;

}  // namespace

// cpp-httplib 0.11 hands its task queue a closure over the socket it accepted, never the socket,
// so radbake's one caller of accept (httplib's listening loop, which enqueues each connection
// right after accepting it, on the same thread) is interposed to learn it.
extern "C" int accept(int listening, sockaddr* address, socklen_t* length) {
  last_accepted_socket = ::accept4(listening, address, length, 0);
  return last_accepted_socket;
}

// Debian's cpp-httplib 0.11 is a shared library that listens with a backlog of 5. 200 clients
// connecting at once, while the accepting thread waited for one of two busy cores, overflowed it:
// the kernel dropped the handshakes past it, and their clients were reset some 100 s later, never
// answered. Its one call to listen is interposed, as accept is, and asks for the system's maximum.
extern "C" int listen(int socket, int backlog) {
  return int(::syscall(SYS_listen, socket, std::max(backlog, SOMAXCONN)));
}

namespace radbake {

using Clock = std::chrono::steady_clock;

struct ConnectionGuard::State {
  struct Job {
    std::function<void()> serve;  // httplib's: serves the connection, then closes its socket
    int socket = -1;              // our duplicate, which outlives httplib's for shutdown() to reach
    int port = -1;                // the peer's, as requests name their connection
  };
  struct Served {
    int socket = -1;
    bool answering = false;
    Clock::time_point waiting_since;
  };

  ConnectionLimits limits;
  std::mutex mutex;
  std::condition_variable jobs_changed;  // the workers' alone
  // The deadline thread's tick and its stop. It once waited on jobs_changed too, and a job's
  // notify_one could wake it instead of a worker: the connection then waited for the next one (an
  // install test's only request hung with all 128 workers idle).
  std::condition_variable deadline_tick;
  std::deque<Job> jobs;
  std::map<int, Served> served;  // by peer port
  bool stopping = false;
  std::vector<std::thread> threads;

  void start() {
    for (size_t k = 0; k < limits.served_at_once; ++k) threads.emplace_back([this] { work(); });
    threads.emplace_back([this] { enforce_deadlines(); });
  }

  void enqueue(std::function<void()> serve) {
    Job job{std::move(serve), -1, -1};
    if (last_accepted_socket >= 0) {
      job.socket = ::fcntl(last_accepted_socket, F_DUPFD_CLOEXEC, 0);
      sockaddr_storage peer{};
      socklen_t size = sizeof peer;
      if (::getpeername(last_accepted_socket, reinterpret_cast<sockaddr*>(&peer), &size) == 0)
        job.port = peer.ss_family == AF_INET ? ntohs(reinterpret_cast<sockaddr_in*>(&peer)->sin_port) : -1;
      last_accepted_socket = -1;
    }
    std::unique_lock<std::mutex> lock(mutex);
    if (jobs.size() >= limits.waiting || stopping) {
      lock.unlock();
      refuse(std::move(job));
      return;
    }
    jobs.push_back(std::move(job));
    jobs_changed.notify_one();
  }

  // Ends a connection unanswered: httplib's reader sees it closed at once and closes its socket.
  static void refuse(Job job) {
    if (job.socket >= 0) ::shutdown(job.socket, SHUT_RDWR);
    job.serve();
    if (job.socket >= 0) ::close(job.socket);
  }

  void work() {
    for (;;) {
      Job job;
      {
        std::unique_lock<std::mutex> lock(mutex);
        jobs_changed.wait(lock, [this] { return stopping || !jobs.empty(); });
        if (jobs.empty()) return;
        job = std::move(jobs.front());
        jobs.pop_front();
        if (stopping) {
          lock.unlock();
          refuse(std::move(job));
          continue;
        }
        if (job.port >= 0) served[job.port] = Served{job.socket, false, Clock::now()};
      }
      job.serve();
      std::lock_guard<std::mutex> lock(mutex);
      served.erase(job.port);
      if (job.socket >= 0) ::close(job.socket);
    }
  }

  void enforce_deadlines() {
    std::unique_lock<std::mutex> lock(mutex);
    while (!stopping) {
      deadline_tick.wait_for(lock, std::chrono::milliseconds(100));
      const Clock::time_point now = Clock::now();
      for (auto& [port, connection] : served)
        if (!connection.answering && now - connection.waiting_since > limits.header_deadline) {
          ::shutdown(connection.socket, SHUT_RDWR);
          connection.waiting_since = Clock::time_point::max() - limits.header_deadline;
        }
    }
  }

  void request_started(int port) {
    std::lock_guard<std::mutex> lock(mutex);
    const auto connection = served.find(port);
    if (connection != served.end()) connection->second.answering = true;
  }

  void request_answered(int port) {
    std::lock_guard<std::mutex> lock(mutex);
    const auto connection = served.find(port);
    if (connection == served.end()) return;
    connection->second.answering = false;
    connection->second.waiting_since = Clock::now();
  }

  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
      for (auto& [port, connection] : served) ::shutdown(connection.socket, SHUT_RDWR);
    }
    jobs_changed.notify_all();
    deadline_tick.notify_all();
    for (std::thread& thread : threads) thread.join();
    threads.clear();
  }
};

namespace {

class GuardedQueue : public httplib::TaskQueue {
 public:
  explicit GuardedQueue(std::shared_ptr<ConnectionGuard::State> state) : state_(std::move(state)) { state_->start(); }
  void enqueue(std::function<void()> serve) override { state_->enqueue(std::move(serve)); }
  void shutdown() override { state_->stop(); }

 private:
  std::shared_ptr<ConnectionGuard::State> state_;
};

}  // namespace

ConnectionGuard::ConnectionGuard(ConnectionLimits limits) : state_(std::make_shared<State>()) {
  state_->limits = limits;
}

void ConnectionGuard::guard(httplib::Server& server) {
  std::shared_ptr<State> state = state_;
  server.new_task_queue = [state] { return new GuardedQueue(state); };
  server.set_pre_routing_handler([state](const httplib::Request& request, httplib::Response&) {
    state->request_started(request.remote_port);
    return httplib::Server::HandlerResponse::Unhandled;
  });
  server.set_logger([state](const httplib::Request& request, const httplib::Response&) {
    state->request_answered(request.remote_port);
  });
}

}  // namespace radbake
