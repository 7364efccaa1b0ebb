#include "airshape/query/query_service.h"

#include <sstream>

#include <gtest/gtest.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/query/arguments.h"
#include "test_support.h"

namespace airshape::query {
namespace {

class QueryServiceTest : public ::testing::Test {
 protected:
  QueryServiceTest() : configuration(Configuration::fromString(test::cpacsDocument(""))) {
    registry.add({"echo_wing", "test", "wing -> index", [](Configuration&, const Json& q) -> Json {
                    return selectByIndexOrUid(q, "wing", {"W1", "W2"}, "wing");
                  }});
    registry.add({"eta", "test", "eta -> eta",
                  [](Configuration&, const Json& q) -> Json { return fractionArgument(q, "eta"); }});
  }
  Configuration configuration;
  QueryRegistry registry;
};

TEST_F(QueryServiceTest, AnswersOkOrError) {
  EXPECT_EQ(answer(configuration, registry, R"({"op":"echo_wing","wing":2})"), Json({{"ok", 1}}));
  EXPECT_EQ(answer(configuration, registry, R"({"op":"echo_wing","wing":"W1"})"), Json({{"ok", 0}}));
  EXPECT_EQ(answer(configuration, registry, R"({"op":"echo_wing","wing":3})")["error"],
            "wing index 3 is out of range (there are 2 wings)");
  EXPECT_EQ(answer(configuration, registry, R"({"op":"echo_wing","wing":"X"})")["error"], "no wing with uID 'X'");
  EXPECT_EQ(answer(configuration, registry, R"({"op":"echo_wing"})")["error"], "missing argument 'wing'");
  EXPECT_EQ(answer(configuration, registry, R"({"op":"eta","eta":1.5})")["error"], "eta = 1.5 is outside [0, 1]");
  EXPECT_EQ(answer(configuration, registry, R"({"op":"nope"})")["error"], "unknown op 'nope'");
  EXPECT_EQ(answer(configuration, registry, "not json")["error"], "the line is not valid JSON");
  EXPECT_EQ(answer(configuration, registry, "[1]")["error"], "a query must be a JSON object");
  EXPECT_EQ(answer(configuration, registry, R"({"op":"eta","eta":1e400})")["error"],
            "the line holds a number too large for a double");  // was an internal error
}

TEST_F(QueryServiceTest, OneAnswerLinePerQueryLine) {
  std::istringstream in("{\"op\":\"eta\",\"eta\":0.5}\n\n{\"op\":\"x\"}\n");
  std::ostringstream out;
  serveQueries(configuration, registry, in, out);
  EXPECT_EQ(out.str(), "{\"ok\":0.5}\n{\"error\":\"unknown op 'x'\"}\n");
}

TEST_F(QueryServiceTest, AnOpNameIsOwnedOnce) { EXPECT_THROW(registry.add({"eta", "other", "", nullptr}), Error); }

}  // namespace
}  // namespace airshape::query
