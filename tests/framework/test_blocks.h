#pragma once
// Small blocks whose behaviour is known in closed form, for the framework's tests.

#include <cmath>
#include <string>
#include <utility>

#include "cbbg/framework/block.h"
#include "cbbg/framework/block_context.h"

namespace cbbg::testing {

// y = x, x' = u: integrates its input (simulator-integrated).
class Integrator final : public Block {
 public:
  Integrator(std::string name, double initial_value = 0.0) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_continuous_state(Vector::Constant(1, initial_value),
                             [&u](const BlockContext& context, VectorRef derivatives) {
                               derivatives = context.input(u);
                             });
    declare_output_port(
        "y", 1, [](const BlockContext& context, VectorRef y) { y = context.continuous_state(); },
        {});
  }
};

// y = x, x' = rate * x (no inputs).
class Exponential final : public Block {
 public:
  Exponential(std::string name, double rate, double initial_value) : Block(std::move(name)) {
    declare_continuous_state(Vector::Constant(1, initial_value),
                             [rate](const BlockContext& context, VectorRef derivatives) {
                               derivatives = rate * context.continuous_state();
                             });
    declare_output_port(
        "y", 1, [](const BlockContext& context, VectorRef y) { y = context.continuous_state(); },
        {});
  }
};

// y = x, x' = x^2: leaves every finite value in finite time.
class BlowUp final : public Block {
 public:
  explicit BlowUp(std::string name) : Block(std::move(name)) {
    declare_continuous_state(Vector::Ones(1), [](const BlockContext& context, VectorRef d) {
      d = context.continuous_state().array().square().matrix();
    });
  }
};

// Counts its periodic updates; y = count. Terminates when the count reaches `stop_at`
// (never when stop_at <= 0).
class Counter final : public Block {
 public:
  Counter(std::string name, double period, double offset = 0.0, int stop_at = 0)
      : Block(std::move(name)) {
    declare_discrete_state("state", Vector::Zero(1), StateLifetime::kPersistent);
    declare_output_port(
        "y", 1, [](const BlockContext& context, VectorRef y) { y = context.discrete_state(); }, {});
    declare_periodic_update(period, offset, [stop_at](BlockContext&, VectorRef next) {
      next[0] += 1.0;
      return stop_at > 0 && next[0] >= stop_at ? EventStatus::terminate("count reached")
                                               : EventStatus::succeeded();
    });
  }
};

// Next state = input + 1 at each update; y = state. Two of them wired crosswise show whether
// simultaneous updates read the values from before the instant.
class IncrementInput final : public Block {
 public:
  IncrementInput(std::string name, double period) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_discrete_state("state", Vector::Zero(1), StateLifetime::kPersistent);
    declare_output_port(
        "y", 1, [](const BlockContext& context, VectorRef y) { y = context.discrete_state(); }, {});
    declare_periodic_update(period, 0.0, [&u](BlockContext& context, VectorRef next) {
      next = context.input(u).array() + 1.0;
      return EventStatus::succeeded();
    });
  }
};

// y = u0 + u1.
class Adder final : public Block {
 public:
  Adder(std::string name, int size) : Block(std::move(name)) {
    const InputPort& a = declare_input_port("a", size);
    const InputPort& b = declare_input_port("b", size);
    declare_output_port("y", size,
                        [&a, &b](const BlockContext& context, VectorRef y) {
                          y = context.input(a) + context.input(b);
                        },
                        {&a, &b});
  }
};

// Advances x' = u itself, exactly (inputs held); y = x. Records how often it was advanced.
class SelfIntegrator final : public Block {
 public:
  explicit SelfIntegrator(std::string name) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 1);
    declare_self_integrated_state(Vector::Zero(1), [&u](BlockContext& context, double end_time) {
      context.mutable_continuous_state()[0] += context.input(u)[0] * (end_time - context.time());
    });
    declare_output_port(
        "y", 1, [](const BlockContext& context, VectorRef y) { y = context.continuous_state(); },
        {});
  }
};

}  // namespace cbbg::testing
