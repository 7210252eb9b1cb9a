#pragma once
// How a slot's block is made: a factory the diagram calls with what it knows when it builds
// the slot (the block's name, the run's typed parameters, the features' size...), so a user's
// block fills a slot of the library's diagrams with no rewiring.

#include <concepts>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "cbbg/config/declared_keys.h"
#include "cbbg/framework/block.h"
#include "cbbg/parameters/parameters.h"
#include "cbbg/plant/plant_signals.h"

namespace cbbg::diagrams {

// What the diagram tells a slot's factory.
struct SlotRequest {
  std::string name;                          // the block's name: keep it (random streams use it)
  const parameters::Parameters& parameters;  // the run's (a user's section: parameters.own)
  int num_features = 0;                      // critic, actor: n, the features' size; else 0
  // critic, actor: false when the loop evaluates what was learnt: the block must act but
  // never change what it learns (blocks::Learner::learnt_parts).
  bool learns = true;
  int plant_state_size = 0;                     // sensors: the plant's output "state" size
  const plant::SignalIndex* signals = nullptr;  // sensors: where each signal sits in it

  // The block's own registered section (config::register_section), as its struct.
  template <class Params>
  Params section(std::string_view section_name) const {
    return config::read_section<Params>(parameters.own, section_name);
  }
};

// Makes the block of one slot. Called once per diagram built (so once per task, maybe in
// several threads at once). Either shape converts: a callable (name, parameters) for a slot
// that needs nothing more, or a callable (const SlotRequest&). It may return a
// std::unique_ptr. An empty factory leaves the slot to the parameters' own block.
class BlockFactory {
 public:
  using Named =
      std::function<std::shared_ptr<Block>(const std::string& name, const parameters::Parameters&)>;
  using Requested = std::function<std::shared_ptr<Block>(const SlotRequest&)>;

  BlockFactory() = default;
  BlockFactory(std::nullptr_t) {}  // NOLINT: empty, as std::function
  template <class F>
  requires std::is_invocable_r_v < std::shared_ptr<Block>,
  const F&, const SlotRequest& > BlockFactory(F factory)
      : requested_(std::move(factory)) {}  // NOLINT: any callable converts
  template <class F>
  requires(!std::is_invocable_v<const F&, const SlotRequest&> &&
           std::is_invocable_r_v<std::shared_ptr<Block>, const F&, const std::string&,
                                 const parameters::Parameters&>) BlockFactory(F factory)
      : named_(std::move(factory)) {}  // NOLINT: any callable converts

  explicit operator bool() const { return named_ || requested_; }
  std::shared_ptr<Block> operator()(const SlotRequest& request) const {
    return requested_ ? requested_(request) : named_(request.name, request.parameters);
  }
  std::shared_ptr<Block> operator()(const std::string& name,
                                    const parameters::Parameters& parameters) const {
    return (*this)(SlotRequest{name, parameters});
  }
  // The callable behind it, if it is a T (as std::function::target).
  template <class T>
  const T* target() const {
    return requested_ ? requested_.template target<T>() : named_.template target<T>();
  }

 private:
  Named named_;
  Requested requested_;
};

}  // namespace cbbg::diagrams
