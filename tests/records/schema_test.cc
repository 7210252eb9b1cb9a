// A protocol's results schema: what check_schema refuses, in one line naming the protocol.

#include "cbbg/records/schema.h"

#include <stdexcept>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cbbg::records {
namespace {

using ::testing::ThrowsMessage;

TEST(ResultsSchema, TheDefaultIsExp1sAndItsHeadlineTheFailuresBeforeSuccess) {
  const ResultsSchema schema;
  EXPECT_NO_THROW(check_schema(schema, "mine"));
  EXPECT_EQ(schema.headline_name(), "failures_before_success");
  EXPECT_TRUE(schema.evaluates);
  EXPECT_TRUE(schema.pairs_failures);
  EXPECT_EQ(schema.figure("anything"), nullptr);
}

TEST(ResultsSchema, RefusesWhatCannotBeWrittenNamingTheProtocol) {
  EXPECT_THAT([] { check_schema({.trial_columns = {{"two words"}}}, "mine"); },
              ThrowsMessage<std::invalid_argument>(
                  "protocol 'mine': trial column 'two words' is not a word of letters, digits "
                  "and '_'"));
  EXPECT_THAT(
      [] {
        check_schema({.trial_columns = {{"a"}, {"a"}}}, "mine");
      },
      ThrowsMessage<std::invalid_argument>("protocol 'mine': two trial columns named 'a'"));
  EXPECT_THAT([] { check_schema({.figures = {{.name = "a\nb"}}}, "mine"); },
              ThrowsMessage<std::invalid_argument>(
                  "protocol 'mine': a figure's name must be a line of text"));
  EXPECT_THAT(
      [] {
        check_schema({.figures = {{.name = "x"}, {.name = "x"}}}, "mine");
      },
      ThrowsMessage<std::invalid_argument>("protocol 'mine': two figures named 'x'"));
  EXPECT_THAT([] { check_schema({.figures = {{.name = "succeeded"}}}, "mine"); },
              ThrowsMessage<std::invalid_argument>(
                  "protocol 'mine': 'succeeded' is every run's own figure; give the protocol's "
                  "another name"));
  EXPECT_THAT([] { check_schema({.headline = "x"}, "mine"); },
              ThrowsMessage<std::invalid_argument>(
                  "protocol 'mine': the headline 'x' is none of its figures"));
  EXPECT_THAT([] { check_schema({.plots = {"radar"}}, "mine"); },
              ThrowsMessage<std::invalid_argument>(
                  "protocol 'mine': no drawing is named 'radar' (pitch, failures, skill, "
                  "annealing, evaluation, figures)"));
}

TEST(ResultsSchema, AFigureIsFoundByName) {
  const ResultsSchema schema{.figures = {{.name = "a@b=1, c", .paired = true}}, .headline = ""};
  ASSERT_NE(schema.figure("a@b=1, c"), nullptr);
  EXPECT_TRUE(schema.figure("a@b=1, c")->paired);
  EXPECT_NO_THROW(check_schema(schema, "mine"));  // a comma is text like any other
}

}  // namespace
}  // namespace cbbg::records
