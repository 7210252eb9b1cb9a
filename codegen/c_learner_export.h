#pragma once
// The C99 of a whole online learner (`cbbg export --learner`): every block from the signals
// it is given to its action, with the state and the updates of each that has them (the
// critic's and the actor's learning, the exploration's draws, the omega counter, the
// reward's memory, the failure that ends a trial), so that a robot goes on learning as the
// simulator's loop would, tick for tick. Each block writes its own outputs and updates
// (c_calculation.h's EmitsC); the exporter orders them and owns nothing between calls:
//
//   typedef struct { ... } NAME_state;        /* the learner's state, the caller's memory */
//   void NAME_init(NAME_state *learner);    /* as exported: learnt weights, generators */
//   void NAME_seed(NAME_state *learner, uint64_t seed);  /* generators as a run of seed */
//   void NAME_start_trial(NAME_state *learner);  /* per-trial state reset, initializations */
//   int NAME_step(NAME_state *learner, const NAME_real GIVEN[GIVEN_SIZE], ...,
//                 NAME_real *action);         /* one tick; 1 when the trial ends */
//
// No heap, no stdio, no global mutable state; <math.h>'s exp, sqrt, log, cos and fabs, and
// <stdint.h>. The generators are std::mt19937_64's (c_random.h).

#include <map>
#include <string>
#include <vector>

#include "cbbg/codegen/c_export.h"

namespace cbbg::codegen {

struct CLearnerOptions {
  std::string name = "cbbg_learner";  // the files' and identifiers' prefix: a C identifier
  Scalar scalar = Scalar::kDouble;
  std::vector<std::string> provenance;  // lines of the head comments
  // The tick NAME_step runs at: every update of the learner must run at it, from time 0.
  double period = 0.01;
  // Outputs the learner takes as arguments of these names (the measured signals).
  std::map<const OutputPort*, std::string> given;
  // Outputs besides the action whose blocks the learner carries (the failure detector's,
  // whose update ends a trial, though the action may not read it).
  std::vector<const OutputPort*> watched;
};

// The C of the learner whose action is `action` (size 1, of a leaf block inside `root`),
// with the state, parameters and generators of `context`, a context of `root`. Throws
// std::invalid_argument naming a block that cannot write an output or an update as C, or
// whose updates run at another period, and for a name that is no C identifier.
CSources export_learner_c(const Diagram& root, const OutputPort& action, const Context& context,
                          const CLearnerOptions& options);

}  // namespace cbbg::codegen
