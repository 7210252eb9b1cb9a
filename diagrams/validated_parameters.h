#pragma once
// The typed parameter tree of a run, checked whole before anything is built or run: every
// value against its declaration, every block's own invariants beyond its declared ranges
// (strictly increasing RBF centres, a rigid body's inertias for the Simbody plant, a
// stabilising LQR gain) and the rules across sections
// (config::Parameters::check_across_sections). This is the edge of a run: below it, blocks,
// diagrams and protocols take the typed tree and look no key up.

#include "cbbg/config/config.h"
#include "cbbg/config/parameters.h"

namespace cbbg::diagrams {

// The tree of `config`. Throws config::ConfigError with the block's or the rule's one-line
// message.
config::Parameters validated_parameters(const config::Config& config);

// The same checks of a tree built or changed in C++ (an evaluation's changed robot).
void validate_parameters(const config::Parameters& parameters);

}  // namespace cbbg::diagrams
