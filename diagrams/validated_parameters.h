#pragma once
// The typed parameter tree of a run, checked whole before anything is built or run: every
// value against its declaration, every block's own invariants beyond its declared ranges
// (strictly increasing RBF centres, a rigid body's inertias for the Simbody plant, a
// stabilising LQR gain) and the rules across sections
// (parameters::Parameters::check_across_sections). This is the edge of a run: below it, blocks,
// diagrams and protocols take the typed tree and look no key up.

#include <string>

#include "cbbg/config/config.h"
#include "cbbg/parameters/parameters.h"

namespace cbbg::diagrams {

// The tree of `config`. Throws config::ConfigError with the block's or the rule's one-line
// message.
parameters::Parameters validated_parameters(const config::Config& config);

// `parameters` with the settings of one entry of a list of settings (config::Kind::kSettings,
// "key=value; key=value"), validated as a run's are: a condition of transfer.conditions.
// Throws config::ConfigError, its message starting with `source` for a value its key refuses.
parameters::Parameters validated_with_settings(const parameters::Parameters& parameters,
                                               const std::string& entry, const std::string& source);

// Whether the settings of `entry` change any value of `parameters` (a condition that sets the
// values the run has changes nothing).
bool settings_change(const parameters::Parameters& parameters, const std::string& entry);

// The same checks of a tree built or changed in C++ (an evaluation's changed robot).
void validate_parameters(const parameters::Parameters& parameters);

}  // namespace cbbg::diagrams
