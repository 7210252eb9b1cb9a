#pragma once
// The typed parameter tree of a config, checked whole before anything is built or run: every
// block's own invariants beyond its declared ranges (strictly increasing RBF centres, a rigid
// body's inertias for the Simbody plant, a stabilising LQR gain) and the rules across
// sections (config::Parameters::check_across_sections).

#include "config/config.h"
#include "config/parameters.h"

namespace cbbg::diagrams {

// Throws config::ConfigError with the block's or the rule's one-line message.
config::Parameters validated_parameters(const config::Config& config);

}  // namespace cbbg::diagrams
