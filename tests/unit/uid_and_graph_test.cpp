#include <algorithm>

#include <gtest/gtest.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/symmetry.h"
#include "test_support.h"

namespace airshape {
namespace {

std::string fuselage(const std::string& uid, const std::string& parent = "") {
  const std::string parentElement = parent.empty() ? "" : "<parentUID>" + parent + "</parentUID>";
  return "<fuselage uID=\"" + uid + "\" symmetry=\"x-y-plane\"><name>f</name>" + parentElement +
         "<transformation/><sections/><segments/></fuselage>";
}

TEST(Uids, DuplicatesAndDanglingReferencesAreReportedWithXPaths) {
  const std::string wings = "<wings>" + test::wingXml("W") + "</wings>";
  const std::string doc = test::cpacsDocument(wings + "<fuselages>" + fuselage("W_Seg") + "</fuselages>");
  const auto configuration = Configuration::fromString(doc, "input.xml", test::bodyLocations());
  const Problems& problems = configuration.uids().problems();
  const auto has = [&](const std::string& text) {
    return std::any_of(problems.begin(), problems.end(),
                       [&](const Problem& p) { return p.describe().find(text) != std::string::npos; });
  };
  EXPECT_TRUE(has("duplicate uID 'W_Seg'"));
  EXPECT_TRUE(
      has("/cpacs/vehicles/aircraft/model/fuselages/fuselage: duplicate uID 'W_Seg' (first defined at "
          "/cpacs/vehicles/aircraft/model/wings/wing/segments/segment"));
  EXPECT_TRUE(has("airfoilUID: uIDref 'A' points to no element")) << "the wing's airfoil A is not defined";
}

TEST(ComponentGraph, ParentsComeBeforeChildren) {
  const std::string doc = test::cpacsDocument("<fuselages>" + fuselage("F") + "</fuselages><wings>" +
                                              test::wingXml("Tail", "Main") + test::wingXml("Main", "F") + "</wings>");
  const auto configuration = Configuration::fromString(doc, "input.xml", test::bodyLocations());
  const auto& graph = configuration.components();
  std::vector<std::string> order;
  for (std::size_t index : graph.buildOrder())
    if (!graph.components()[index].part) order.push_back(graph.components()[index].uid);
  EXPECT_EQ(order, (std::vector<std::string>{"F", "Main", "Tail"}));
  // The parts: the model first (attached to nothing), each segment below its wing.
  EXPECT_EQ(graph.components()[graph.buildOrder().front()].typeName, "plane");
  const graph::Component& segment = graph.components()[static_cast<std::size_t>(graph.find("Tail_Seg"))];
  EXPECT_TRUE(segment.part);
  EXPECT_EQ(segment.typeName, "wing_segment");
  EXPECT_EQ(segment.parentUid, "Tail");
  EXPECT_EQ(graph.depth(static_cast<std::size_t>(graph.find("Tail"))), 2u);
  EXPECT_EQ(model::resolvedSymmetry(configuration, "Tail"), "x-y") << "inherited from the fuselage through Main";
}

TEST(ComponentGraph, ACycleIsAnErrorNamingItsUids) {
  const std::string doc =
      test::cpacsDocument("<wings>" + test::wingXml("A", "B") + test::wingXml("B", "A") + "</wings>");
  try {
    Configuration::fromString(doc, "cycle.xml", test::bodyLocations());
    FAIL() << "a parentUID cycle must be refused";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.code(), ErrorCode::InvalidModel);
    EXPECT_NE(message.find("cycle.xml"), std::string::npos);
    EXPECT_NE(message.find("A -> B"), std::string::npos) << message;
  }
}

TEST(ComponentGraph, AParentThatIsNoComponentIsAWarning) {
  const auto configuration = Configuration::fromString(
      test::cpacsDocument("<wings>" + test::wingXml("W", "Nowhere") + "</wings>"), "input.xml", test::bodyLocations());
  ASSERT_EQ(configuration.components().components().size(), 3u);  // the model, the wing, its segment
  EXPECT_EQ(configuration.components().components()[1].parentUid, "");
  const Problems& warnings = configuration.warnings();
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const Problem& p) {
    return p.message.find("parentUID 'Nowhere' names no geometric component") != std::string::npos;
  }));
}

}  // namespace
}  // namespace airshape
