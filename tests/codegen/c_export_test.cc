// The C exporter (codegen/) with blocks of a user's own: what it writes of a diagram's output,
// how it orders the blocks and names their constants, that the code compiles as C99 and
// computes what the C++ does, and what it refuses, in one line naming the block.

#include "cbbg/codegen/c_export.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cbbg/framework/block_context.h"
#include "cbbg/framework/diagram_builder.h"
#include "cbbg/framework/primitives/constant_source.h"
#include "cbbg/framework/primitives/gain.h"
#include "tests/support/scratch_directory.h"

namespace cbbg::codegen {
namespace {

using ::testing::HasSubstr;

// y = k u[0] + u[1]: a user's block that writes its calculation as C.
class Blend final : public Block, public EmitsC {
 public:
  Blend(std::string name, double k) : Block(std::move(name)), k_(k) {
    const InputPort& u = declare_input_port("u", 2);
    declare_output_port("y", 1,
                        [this, &u](const BlockContext& c, VectorRef y) {
                          y[0] = k_ * c.input(u)[0] + c.input(u)[1];
                        },
                        {&u});
  }
  CCalculation c_calculation(int, const Context&) const override {
    return {{{"k", {k_}, false}}, "  out[0] = $k * in0[0] + in0[1];\n"};
  }

 private:
  double k_;
};

// y = (u0 * u0, u1 + 1): another, feeding the first.
class Shape final : public Block, public EmitsC {
 public:
  explicit Shape(std::string name) : Block(std::move(name)) {
    const InputPort& u = declare_input_port("u", 2);
    declare_output_port("y", 2,
                        [&u](const BlockContext& c, VectorRef y) {
                          y[0] = c.input(u)[0] * c.input(u)[0];
                          y[1] = c.input(u)[1] + 1.0;
                        },
                        {&u});
  }
  CCalculation c_calculation(int, const Context&) const override {
    return {{{"one", {1.0}, true}}, "  out[0] = in0[0] * in0[0];\n  out[1] = in0[1] + $one[0];\n"};
  }
};

// u -> shape -> blend -> y, u exported as "signals".
std::unique_ptr<Diagram> two_blocks() {
  DiagramBuilder builder("user");
  auto& shape = builder.emplace<Shape>("shape");
  auto& blend = builder.emplace<Blend>("blend", 0.25);
  builder.connect(shape, "y", blend, "u");
  builder.export_input(shape.input_port("u"), "signals");
  builder.export_output(blend.output_port("y"), "y");
  return builder.build();
}

TEST(CExport, WritesEachBlockOnceInTheOrderTheOutputNeedsThem) {
  const auto diagram = two_blocks();
  const auto context = diagram->create_context();
  CExportOptions options;
  options.name = "mine";
  options.provenance = {"a test's"};
  const CSources c =
      export_c(*diagram, diagram->block("blend").output_port("y"), *context, options);
  EXPECT_THAT(c.header, HasSubstr("#define MINE_EXPORT_VERSION 1\n#define MINE_SIGNALS_SIZE 2\n"));
  EXPECT_THAT(c.header, HasSubstr("typedef double mine_real;"));
  EXPECT_THAT(c.header,
              HasSubstr("mine_real mine_step(const mine_real signals[MINE_SIGNALS_SIZE]);"));
  EXPECT_THAT(c.header, HasSubstr(" * a test's\n"));
  EXPECT_THAT(c.source, HasSubstr("static const real mine_s0_one[1] = {\n    1.0\n};\n"));
  EXPECT_THAT(c.source, HasSubstr("static const real mine_s1_k = 0.25;\n"));
  EXPECT_THAT(c.source,
              HasSubstr("  mine_s0(signals, s0);\n  mine_s1(s0, s1);\n  return s1[0];\n"));
  EXPECT_THAT(c.source, ::testing::Not(HasSubstr("stdio")));
}

TEST(CExport, TheCodeCompilesAsC99AndComputesWhatTheDiagramDoes) {
  const cbbg::testing::ScratchDirectory scratch;
  const auto diagram = two_blocks();
  auto context = diagram->create_context();
  CExportOptions options;
  options.name = "mine";
  const CSources c =
      export_c(*diagram, diagram->block("blend").output_port("y"), *context, options);
  std::ofstream(scratch.path() / "mine.h") << c.header;
  std::ofstream(scratch.path() / "mine.c") << c.source;
  std::ofstream(scratch.path() / "main.c")
      << "#include <stdio.h>\n#include \"mine.h\"\nint main(void) {\n"
         "  const mine_real u[2] = {3.0, -0.5};\n  printf(\"%.17g\\n\", mine_step(u));\n"
         "  return 0;\n}\n";
  const std::string command = "cd " + scratch.path().string() +
                              " && gcc -std=c99 -Wall -Wextra -Werror -pedantic main.c mine.c -lm "
                              "-o mine && ./mine > out.txt";
  ASSERT_EQ(std::system(command.c_str()), 0) << c.source;
  context->fix_input(diagram->input_port("signals"), (Vector(2) << 3.0, -0.5).finished());
  const double expected = diagram->eval_output(*context, diagram->output_port("y"))[0];
  double got = 0.0;
  std::ifstream(scratch.path() / "out.txt") >> got;
  EXPECT_EQ(got, expected);  // 0.25 * 9 + 0.5
}

// What the export is told to read otherwise: an output held at a value, another read as a
// third; and a ConstantSource, written as its constant.
TEST(CExport, HeldOutputsOutputsReadAsOthersAndConstantSourcesAreConstants) {
  DiagramBuilder builder("user");
  auto& constant = builder.emplace<ConstantSource>("constant", (Vector(2) << 1.5, 2.5).finished());
  auto& shape = builder.emplace<Shape>("shape");
  auto& blend = builder.emplace<Blend>("blend", 0.25);
  builder.connect(constant, "y", shape, "u");
  builder.connect(shape, "y", blend, "u");
  const auto diagram = builder.build();
  const auto context = diagram->create_context();
  const CSources alone = export_c(*diagram, blend.output_port("y"), *context, {});
  EXPECT_THAT(alone.source,
              HasSubstr("static const real cbbg_policy_constant0[2] = {\n    1.5, 2.5\n};"));
  EXPECT_THAT(alone.header, HasSubstr("cbbg_policy_step(void);"));
  CExportOptions held;
  held.held[&shape.output_port("y")] = 7.0;
  const CSources with_held = export_c(*diagram, blend.output_port("y"), *context, held);
  EXPECT_THAT(with_held.source, HasSubstr("cbbg_policy_s0(cbbg_policy_held0, s0);"));
  EXPECT_THAT(with_held.source, ::testing::Not(HasSubstr("block 'user/shape'")));
  CExportOptions read_as;
  read_as.read_as[&shape.output_port("y")] = &constant.output_port("y");
  const CSources with_read_as = export_c(*diagram, blend.output_port("y"), *context, read_as);
  EXPECT_THAT(with_read_as.source, HasSubstr("cbbg_policy_s0(cbbg_policy_constant0, s0);"));
}

TEST(CExport, ABlockThatCannotBeWrittenAsCIsRefusedByName) {
  DiagramBuilder builder("user");
  auto& gain = builder.emplace<Gain>("gain", 2.0, 2);
  auto& blend = builder.emplace<Blend>("blend", 0.25);
  builder.connect(gain, "y", blend, "u");
  builder.export_input(gain.input_port("u"), "signals");
  const auto diagram = builder.build();
  const auto context = diagram->create_context();
  EXPECT_THAT([&] { export_c(*diagram, blend.output_port("y"), *context, {}); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "block 'user/gain' cannot be written as C: it does not implement "
                  "codegen::EmitsC (the output 'y' of the export needs it)"));
}

TEST(CExport, RefusesANameThatIsNoCIdentifierAndAnOutputOfManyValues) {
  const auto diagram = two_blocks();
  const auto context = diagram->create_context();
  CExportOptions options;
  options.name = "2fast";
  EXPECT_THAT(
      [&] { export_c(*diagram, diagram->block("blend").output_port("y"), *context, options); },
      ::testing::ThrowsMessage<std::invalid_argument>(HasSubstr("'2fast' is no C identifier")));
  EXPECT_THAT([&] { export_c(*diagram, diagram->block("shape").output_port("y"), *context, {}); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  "output 'user/shape.y' has 2 values; the export writes one action"));
}

TEST(CLiteral, KeepsEveryDigitADoubleOrAFloatNeeds) {
  EXPECT_EQ(c_literal(0.1, Scalar::kDouble), "0.10000000000000001");
  EXPECT_EQ(c_literal(2.0, Scalar::kDouble), "2.0");
  EXPECT_EQ(c_literal(-1.0 / 3.0, Scalar::kDouble), "-0.33333333333333331");
  EXPECT_EQ(c_literal(1e-300, Scalar::kDouble), "1e-300");
  EXPECT_EQ(c_literal(0.1, Scalar::kFloat), "0.100000001f");
  EXPECT_EQ(c_literal(2.0, Scalar::kFloat), "2.0f");
  EXPECT_THROW(c_literal(std::nan(""), Scalar::kDouble), std::invalid_argument);
}

}  // namespace
}  // namespace cbbg::codegen
