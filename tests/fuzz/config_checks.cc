#include "tests/fuzz/config_checks.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace cbbg::fuzz {
namespace {

[[noreturn]] void fail(const std::string& why, const config::Config& config) {
  std::fprintf(stderr, "config check failed: %s\nthe config as to_yaml() writes it:\n%s\n",
               why.c_str(), config.to_yaml().c_str());
  std::abort();
}

}  // namespace

void require_defaults(const config::Config& config) {
  if (!(config == config::Config())) fail("a refused input changed the config", config);
}

void require_round_trip(const config::Config& config) {
  config::Config reloaded;
  try {
    reloaded.merge_yaml(config.to_yaml(), "to_yaml()");
  } catch (const config::ConfigError& error) {
    fail(std::string("to_yaml() does not load back: ") + error.what(), config);
  }
  if (!(reloaded == config)) fail("to_yaml() loads back to a different config", config);
}

}  // namespace cbbg::fuzz
