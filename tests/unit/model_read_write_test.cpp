// Reading a document into the generated model, validating it, and writing edits back.
#include <algorithm>

#include <gtest/gtest.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "test_support.h"

namespace airshape {
namespace {

/// The wings the typed model holds in the aircraft models.
std::vector<schema::WingType*> wingsOf(const Configuration& configuration) {
  std::vector<schema::WingType*> wings;
  for (auto& model : configuration.cpacs().vehicles->aircraft->model)
    if (model.wings)
      for (auto& wing : model.wings->wing) wings.push_back(&wing);
  return wings;
}

bool hasProblem(const Problems& problems, const std::string& xpath, const std::string& text) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const Problem& p) { return p.xpath == xpath && p.message.find(text) != std::string::npos; });
}

TEST(ModelReading, TypedValuesAreRead) {
  const auto configuration = Configuration::fromString(
      test::cpacsDocument("<wings>" + test::wingXml("W", "", " symmetry=\"x-z-plane\"") + "</wings>"));
  const auto wings = wingsOf(configuration);
  ASSERT_EQ(wings.size(), 1u);
  EXPECT_EQ(wings[0]->uID, "W");
  ASSERT_TRUE(wings[0]->symmetry.has_value());
  EXPECT_EQ(*wings[0]->symmetry, schema::SymmetryXyXzYzType::XZPlane);
  EXPECT_EQ(wings[0]->sections->section.size(), 2u);
  EXPECT_DOUBLE_EQ(*wings[0]->transformation->scaling->y, 1.0);
  EXPECT_EQ(wings[0]->sections->section[1].xpath,
            "/cpacs/vehicles/aircraft/model[1]/wings/wing[1]/sections/section[2]");
  EXPECT_TRUE(configuration.schemaProblems().empty()) << configuration.schemaProblems().front().describe();
}

TEST(ModelReading, EverySchemaViolationIsReportedWithItsXPath) {
  const std::string wing =
      "<wing uID=\"W\" symmetry=\"sideways\"><description>d</description>"
      "<transformation><scaling><x>one</x></scaling></transformation>"
      "<sections><section uID=\"S\"><name>s</name><transformation/><elements/></section></sections>"
      "<segments><segment uID=\"G\"><name>g</name><fromElementUID>S</fromElementUID>"
      "<toElementUID>S</toElementUID></segment></segments><bogus/></wing>";
  const auto configuration = Configuration::fromString(test::cpacsDocument("<wings>" + wing + "</wings>"));
  const Problems& problems = configuration.schemaProblems();
  const std::string w = "/cpacs/vehicles/aircraft/model[1]/wings/wing[1]";
  EXPECT_TRUE(hasProblem(problems, w, "missing required element 'name'"));
  EXPECT_TRUE(hasProblem(problems, w + "/@symmetry", "'sideways' is not one of"));
  EXPECT_TRUE(hasProblem(problems, w + "/transformation/scaling/x", "'one' is not a number"));
  EXPECT_TRUE(hasProblem(problems, w + "/sections", "element 'section' occurs once, at least 2 needed"));
  EXPECT_TRUE(hasProblem(problems, w + "/sections/section[1]/elements", "missing required element 'element'"));
  EXPECT_TRUE(hasProblem(problems, w + "/bogus", "not allowed in wingType"));
}

TEST(ModelReading, ChoicesAllowExactlyOneAlternative) {
  const std::string profiles =
      "<profiles><wingAirfoils><wingAirfoil uID=\"A\"><name>a</name></wingAirfoil>"
      "<wingAirfoil uID=\"B\"><name>b</name><pointList><x>0</x><y>0</y><z>0</z></pointList>"
      "<cst2D><upperN1>0.5</upperN1></cst2D></wingAirfoil></wingAirfoils></profiles>";
  const auto configuration = Configuration::fromString(test::cpacsDocument("", profiles));
  const Problems& problems = configuration.schemaProblems();
  const std::string airfoils = "/cpacs/vehicles/profiles/wingAirfoils/wingAirfoil";
  EXPECT_TRUE(hasProblem(problems, airfoils + "[1]", "needs one of"));
  EXPECT_TRUE(hasProblem(problems, airfoils + "[2]", "exclude each other"));
}

TEST(ModelWriting, AnUneditedModelLeavesTheDocumentAsItWas) {
  auto configuration = Configuration::fromString(test::cpacsDocument("<wings>" + test::wingXml("W") + "</wings>"));
  const std::string before = configuration.document().toString();
  configuration.writeModel();
  EXPECT_EQ(configuration.document().toString(), before);
}

TEST(ModelWriting, EditsReachTheDocumentInSchemaOrder) {
  auto configuration = Configuration::fromString(test::cpacsDocument("<wings>" + test::wingXml("W") + "</wings>"));
  schema::WingType& wing = *wingsOf(configuration)[0];
  wing.name = "Renamed";
  wing.description = "added";
  wing.transformation->scaling->x = 2.5;
  wing.sections->section.erase(1);
  configuration.writeModel();
  const std::string after = configuration.document().toString();
  EXPECT_NE(after.find("<name>Renamed</name><description>added</description>"), std::string::npos) << after;
  EXPECT_NE(after.find("<x>2.5</x>"), std::string::npos);
  EXPECT_EQ(after.find("uID=\"W_S2\""), std::string::npos) << "the removed section is gone";
  EXPECT_NE(after.find("uID=\"W_S1\""), std::string::npos);
}

TEST(ModelWriting, TextTheModelCannotHoldStaysAsWritten) {
  auto configuration = Configuration::fromString(test::cpacsDocument(
      "<wings>" + test::wingXml("W") + "</wings><reference><area></area><length>n/a</length></reference>"));
  const std::string before = configuration.document().toString();
  configuration.writeModel();
  EXPECT_EQ(configuration.document().toString(), before);
}

TEST(ModelWriting, RepeatedUidsAreLeftOutOfTheModelButSaved) {
  auto configuration =
      Configuration::fromString(test::cpacsDocument("<wings>" + test::wingXml("W") + test::wingXml("W") + "</wings>"));
  EXPECT_EQ(wingsOf(configuration).size(), 1u);
  EXPECT_FALSE(configuration.warnings().empty());
  const std::string before = configuration.document().toString();
  configuration.writeModel();
  EXPECT_EQ(configuration.document().toString(), before);
}

TEST(Saving, WritesAtomicallyAndReportsAMissingFolder) {
  auto configuration = Configuration::fromString(test::cpacsDocument(""));
  try {
    configuration.save("/nonexistent-folder/out.xml");
    FAIL() << "saving into a missing folder must fail";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::WriteFailed);
    EXPECT_NE(std::string(error.what()).find("/nonexistent-folder/out.xml"), std::string::npos);
  }
}

}  // namespace
}  // namespace airshape
