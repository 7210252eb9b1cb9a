#pragma once
// What must hold after every fuzz input, whatever Config made of it. A failed check prints
// why and aborts, which libFuzzer reports as a crash and saves the input.

#include "cbbg/config/config.h"

namespace cbbg::fuzz {

// A refused input changes nothing: `config` still holds the built-in defaults.
void require_defaults(const config::Config& config);

// An accepted input leaves a tree whose to_yaml() loads back to an equal Config (config.h's
// promise for to_yaml).
void require_round_trip(const config::Config& config);

}  // namespace cbbg::fuzz
