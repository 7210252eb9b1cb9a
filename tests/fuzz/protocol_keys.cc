// The built-in protocols' keys, as the cbbg command registers them with the protocols (their
// params structs' headers alone: the protocols' code stays out of the fuzz build), so the
// fuzzed config is the command's whole config.

#include "cbbg/config/declared_keys.h"
#include "cbbg/experiments/exp2_params.h"
#include "cbbg/experiments/exp3_params.h"
#include "cbbg/experiments/transfer_params.h"
#include "cbbg/parameters/parameters.h"  // the tree first: the keys below are placed in it

namespace cbbg::fuzz {
namespace {

template <class Params>
void register_like_its_protocol() {
  config::register_keys(config::declared_keys(Params{}, Params::kSection), Params::kKeysAfter);
}

bool register_protocol_keys() {
  using namespace cbbg::experiments;
  register_like_its_protocol<Exp2Params>();
  register_like_its_protocol<Exp3Params>();
  register_like_its_protocol<TransferParams>();
  return true;
}

[[maybe_unused]] const bool kProtocolKeysRegistered = register_protocol_keys();

}  // namespace
}  // namespace cbbg::fuzz
