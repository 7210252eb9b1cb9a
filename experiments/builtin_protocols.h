#pragma once
// The library's protocols, each declared in its own file as a user's is (protocols.h), in the
// order `cbbg list` shows them. protocols.cc registers them before any of the user's.

#include "cbbg/experiments/protocols.h"

namespace cbbg::experiments {

Protocol exp1_protocol();      // exp1.cc
Protocol exp2_protocol();      // exp2.cc
Protocol exp3_protocol();      // exp3.cc
Protocol evaluate_protocol();  // evaluate.cc
Protocol transfer_protocol();  // transfer.cc
Protocol realtime_protocol();  // realtime.cc

}  // namespace cbbg::experiments
