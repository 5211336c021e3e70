// Two kinds of failure: bad input is the user's (a clear message, exit status 2); anything else
// is ours (exit status 1). Invariants inside the core are asserts, not exceptions.
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

// Thrown out of a stage when the progress callback asks to stop.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

}  // namespace radbake
