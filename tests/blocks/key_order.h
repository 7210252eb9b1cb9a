#pragma once
// The keys a params struct declares, in the order its describe() declares them: where a new
// key sits is part of the config's contract (docs/parameters.md lists them in this order).

#include <string>
#include <string_view>
#include <vector>

namespace cbbg::testing {

class KeyOrder {
 public:
  template <typename... Rest>
  void number(std::string_view key, Rest&&...) {
    keys_.emplace_back(key);
  }
  template <typename... Rest>
  void integer(std::string_view key, Rest&&...) {
    keys_.emplace_back(key);
  }
  template <typename... Rest>
  void numbers(std::string_view key, Rest&&...) {
    keys_.emplace_back(key);
  }
  template <typename... Rest>
  void choice(std::string_view key, Rest&&...) {
    keys_.emplace_back(key);
  }
  template <typename... Rest>
  void text(std::string_view key, Rest&&...) {
    keys_.emplace_back(key);
  }

  const std::vector<std::string>& keys() const { return keys_; }

 private:
  std::vector<std::string> keys_;
};

// The keys of `Params`, in declaration order.
template <typename Params>
std::vector<std::string> declared_keys() {
  Params params;
  KeyOrder order;
  params.describe(order);
  return order.keys();
}

}  // namespace cbbg::testing
