// Two kinds of failure: bad input and a disk that takes no more are the user's (a clear message,
// exit status 2); anything else is ours (exit status 1). Invariants inside the core are asserts, not exceptions.
#pragma once

#include <stdexcept>
#include <string>

namespace radbake {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A stage made a NaN or an infinity from input that passed validation: our bug, never written out.
struct NonFiniteValue : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// User text (a path, a URI, a name, tinygltf's message that may hold a whole data URI) as an error
// line quotes it: control characters shown as '?', so the message stays one line, and anything
// longer than `max` bytes cut in the middle, so a 100 MB URI cannot flood a terminal or a log.
inline std::string clipped(const std::string& text, size_t max = 100) {
  std::string out = text;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (out.size() <= max) return out;
  // Cut on UTF-8 character boundaries (never before a continuation byte).
  auto boundary = [&](size_t at) {
    while (at > 0 && (static_cast<unsigned char>(out[at]) & 0xc0) == 0x80) --at;
    return at;
  };
  const size_t head = boundary(max * 2 / 3), tail = boundary(out.size() - (max - max * 2 / 3 - 3));
  return out.substr(0, head) + "..." + out.substr(tail);
}

// An output that could not be written: the user's disk (full, read-only, no permission), exit
// status 2 like bad input. The message names the file and why, in radbake's words; a file's
// `path` and `reason` are kept apart so the message can name it where the user will look for it
// (OUT/..., not the staging folder it was being written in).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
  OutputError(const std::string& file, const std::string& why)
      : std::runtime_error("cannot write " + clipped(file) + ": " + why), path(file), reason(why) {}
  std::string path, reason;  // empty unless one file's writing failed
};

// Thrown when a bake has done what it was asked to (--stop-after, a slice of the gather) and its
// checkpoint holds it: what() names the last stage done.
struct StoppedEarly : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown out of a stage when the progress callback asks to stop.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace radbake
