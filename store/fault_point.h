#pragma once
// A test hook for crash safety: the process stops dead (as a kill would stop it) at a named
// step of a commit, so a test can check that --resume finishes from there. Off unless the
// environment variable CBBG_FAULT_AT names the step, optionally with the occurrence:
//   CBBG_FAULT_AT=commit:publish      the first time the step is reached
//   CBBG_FAULT_AT=task:record@3       the third time
// The process then exits at once with kFaultExitCode, writing and flushing nothing more.

namespace cbbg::store {

inline constexpr int kFaultExitCode = 86;

// The steps, in the order a run reaches them (for tests that visit every one).
inline constexpr const char* kFaultPoints[] = {"task:steps",     "task:weights",  "task:record",
                                               "commit:results", "commit:marker", "commit:publish",
                                               "commit:clean",   "commit:unmark"};

// Exits the process with kFaultExitCode when CBBG_FAULT_AT names `step` (and this is its
// named occurrence). Thread-safe.
void fault_point(const char* step);

}  // namespace cbbg::store
