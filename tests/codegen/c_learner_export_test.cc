// The learner exporter (codegen/c_learner_export.h) with blocks of a user's own: a block's
// state and periodic update, its per-trial reset, a draw from its generator, the update that
// ends a trial, compiled as C99 and run against the C++ simulator tick for tick; and what it
// refuses, in one line naming the block.

#include "cbbg/codegen/c_learner_export.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/random.h"
#include "cbbg/framework/simulator.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::codegen {
namespace {

using ::testing::HasSubstr;

constexpr double kPeriod = 0.01;

// A leaky level fed by u: level <- 0.5 level + u + noise (per trial), total <- total + u
// (kept), y = level; the noise a uniform draw at every tick, and the trial ends when the
// level passes `limit`.
class Leak final : public Block, public EmitsC {
 public:
  Leak(std::string name, double limit, bool emits_update = true)
      : Block(std::move(name)), limit_(limit), emits_update_(emits_update) {
    const InputPort& u = declare_input_port("u", 1);
    level_ = declare_discrete_state("level", Vector::Zero(1), StateLifetime::kPerTrial);
    total_ = declare_discrete_state("total", Vector::Zero(1), StateLifetime::kPersistent);
    noise_ = declare_discrete_state("noise", Vector::Zero(1), StateLifetime::kPerTrial);
    declare_output_port(
        "y", 1,
        [this](const BlockContext& c, VectorRef y) { y[0] = level_.of(c.discrete_state())[0]; },
        {});
    declare_initialization_update([this](BlockContext& c, VectorRef next) {
      noise_.of(next)[0] = draw_uniform(c.random_generator());
      return EventStatus::succeeded();
    });
    declare_periodic_update(kPeriod, 0.0, [this, &u](BlockContext& c, VectorRef next) {
      const auto state = c.discrete_state();
      const double level = 0.5 * level_.of(state)[0] + c.input(u)[0] + noise_.of(state)[0];
      level_.of(next)[0] = level;
      total_.of(next)[0] = total_.of(state)[0] + c.input(u)[0];
      noise_.of(next)[0] = draw_uniform(c.random_generator());
      return level > limit_ ? EventStatus::terminate("over the limit") : EventStatus::succeeded();
    });
  }
  CCalculation c_calculation(int, const Context&) const override {
    return {{}, "  out[0] = @level[0];\n"};
  }
  CCalculation c_update(int update, const Context& context) const override {
    if (!emits_update_) return EmitsC::c_update(update, context);
    return {{c_number("limit", limit_)},
            "  const real level = (real)0.5 * @level[0] + in0[0] + @noise[0];\n"
            "  @@level[0] = level;\n  @@total[0] = @total[0] + in0[0];\n"
            "  @@noise[0] = CBBG_UNIFORM(rng);\n  if (level > $limit) return 1;\n",
            true};
  }
  CCalculation c_initialization(int, const Context&) const override {
    return {{}, "  @@noise[0] = CBBG_UNIFORM(rng);\n", true};
  }

 private:
  double limit_;
  bool emits_update_;
  StatePart level_, total_, noise_;
};

// x -> leak -> y, with x the learner's argument.
struct LeakLoop {
  std::unique_ptr<Diagram> diagram;
  const Leak* leak = nullptr;
  const OutputPort* x = nullptr;
};

LeakLoop leak_loop(double x, bool emits_update = true) {
  DiagramBuilder builder("user");
  auto& source = builder.emplace<ConstantSource>("x", Vector::Constant(1, x));
  auto& leak = builder.emplace<Leak>("leak", 3.0, emits_update);
  builder.connect(source, "y", leak, "u");
  LeakLoop loop;
  loop.leak = &leak;
  loop.x = &source.output_port("y");
  loop.diagram = builder.build();
  return loop;
}

CLearnerOptions given_x(const LeakLoop& loop) {
  CLearnerOptions options;
  options.name = "leak";
  options.period = kPeriod;
  options.given[loop.x] = "x";
  return options;
}

TEST(CLearnerExport, WritesTheStateAsAStructTheCallerOwns) {
  const LeakLoop loop = leak_loop(1.0);
  const auto context = loop.diagram->create_context(3);
  const CSources c =
      export_learner_c(*loop.diagram, loop.leak->output_port("y"), *context, given_x(loop));
  EXPECT_THAT(c.header, HasSubstr("typedef struct {\n  leak_real level[1];\n  leak_real total[1];"
                                  "\n  leak_real noise[1];\n} leak_leak_state;"));
  EXPECT_THAT(c.header, HasSubstr("  leak_leak_state leak;\n  leak_random leak_random;\n"));
  EXPECT_THAT(c.header, HasSubstr("int leak_step(leak_state *learner, const leak_real "
                                  "x[LEAK_X_SIZE], leak_real *action);"));
  EXPECT_THAT(c.header, HasSubstr("#define LEAK_PERIOD 0.01\n"));
  EXPECT_THAT(c.source, HasSubstr("next->level[0] = level;"));
  EXPECT_THAT(c.source, ::testing::Not(HasSubstr("stdio")));
}

// Three trials of the C++ simulator with x = 1: the level rises past 3 and ends each one.
TEST(CLearnerExport, TheCodeLearnsAndEndsTrialsAsTheSimulatorDoes) {
  const cbbg::testing::ScratchDirectory scratch;
  const LeakLoop loop = leak_loop(1.0);
  Simulator simulator(*loop.diagram, {}, 3);
  const CSources c = export_learner_c(*loop.diagram, loop.leak->output_port("y"),
                                      simulator.context(), given_x(loop));
  std::string expected;
  SignalLog& log = simulator.add_log(loop.leak->output_port("y"), kPeriod);
  for (int trial = 0; trial < 3; ++trial) {
    log.clear();
    simulator.context().reset_trial_state();
    simulator.initialize();
    const SimulationStatus status = simulator.advance_to(1.0);
    ASSERT_TRUE(status.terminated);
    for (int k = 0; k < log.num_samples(); ++k) {
      char line[64];
      std::snprintf(line, sizeof line, "%.17g %d\n", log.sample(k)[0],
                    k + 1 == log.num_samples() ? 1 : 0);
      expected += line;
    }
    expected += "trial\n";
  }
  char total[64];
  std::snprintf(total, sizeof total, "%.17g\n", simulator.context().discrete_state(*loop.leak)[1]);
  expected += total;

  std::ofstream(scratch.path() / "leak.h") << c.header;
  std::ofstream(scratch.path() / "leak.c") << c.source;
  std::ofstream(scratch.path() / "main.c")
      << "#include <stdio.h>\n#include \"leak.h\"\nint main(void) {\n"
         "  static leak_state learner;\n  const leak_real x[1] = {1.0};\n  int trial;\n"
         "  leak_init(&learner);\n  for (trial = 0; trial < 3; ++trial) {\n"
         "    leak_real y;\n    int ended = 0;\n    leak_start_trial(&learner);\n"
         "    while (!ended) {\n      ended = leak_step(&learner, x, &y);\n"
         "      printf(\"%.17g %d\\n\", y, ended);\n    }\n    printf(\"trial\\n\");\n  }\n"
         "  printf(\"%.17g\\n\", learner.leak.total[0]);\n  return 0;\n}\n";
  const std::string command = "cd " + scratch.path().string() +
                              " && gcc -std=c99 -Wall -Wextra -Werror -pedantic main.c leak.c -lm "
                              "-o leak && ./leak > out.txt";
  ASSERT_EQ(std::system(command.c_str()), 0) << c.source;
  std::ifstream out(scratch.path() / "out.txt");
  const std::string got((std::istreambuf_iterator<char>(out)), std::istreambuf_iterator<char>());
  EXPECT_EQ(got, expected);
}

TEST(CLearnerExport, ABlockThatCannotWriteItsUpdateIsRefusedByName) {
  const LeakLoop loop = leak_loop(1.0, false);
  const auto context = loop.diagram->create_context();
  try {
    export_learner_c(*loop.diagram, loop.leak->output_port("y"), *context, given_x(loop));
    FAIL() << "a block without its update's C was exported";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "block 'user/leak' cannot write its update as C: it does not implement "
                 "codegen::EmitsC::c_update");
  }
}

TEST(CLearnerExport, UpdatesAtAnotherTickThanTheLearnersAreRefused) {
  const LeakLoop loop = leak_loop(1.0);
  const auto context = loop.diagram->create_context();
  CLearnerOptions options = given_x(loop);
  options.period = 0.02;
  try {
    export_learner_c(*loop.diagram, loop.leak->output_port("y"), *context, options);
    FAIL() << "an update at another period was exported";
  } catch (const std::invalid_argument& error) {
    EXPECT_THAT(error.what(), HasSubstr("block 'user/leak' updates at another period"));
  }
}

}  // namespace
}  // namespace cbbg::codegen
