#include <gtest/gtest.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "test_support.h"

namespace airshape {
namespace {

/// A fuselage F, a wing W attached to it, a wing V on its own, and the airfoil W uses.
const std::string kModel = R"(
<fuselages><fuselage uID="F"><name>f</name><transformation><translation><x>0</x></translation></transformation></fuselage></fuselages>
<wings>
  <wing uID="W"><name>w</name><parentUID>F</parentUID><transformation><scaling><x>1</x></scaling></transformation>
    <sections><section uID="WS"><name>s</name><elements><element uID="WE"><name>e</name><airfoilUID>A</airfoilUID>
    </element></elements></section></sections></wing>
  <wing uID="V"><name>v</name><transformation><scaling><x>1</x></scaling></transformation></wing>
</wings>)";
const std::string kProfiles = R"(<profiles><wingAirfoils><wingAirfoil uID="A"><name>a</name>
  <pointList><x>1;0;1</x><y>0;0;0</y><z>0;0.1;0</z></pointList></wingAirfoil></wingAirfoils></profiles>)";

class ModelEditing : public ::testing::Test {
 protected:
  ModelEditing()
      : configuration(
            Configuration::fromString(test::cpacsDocument(kModel, kProfiles), "input.xml", test::bodyLocations())) {}

  /// Builds (or reuses) a stand-in object for each component, as a plugin would.
  void buildAll() {
    for (const char* uid : {"F", "W", "V"})
      configuration.cache().obtain<int>(std::string("geometry:") + uid, [] { return std::make_shared<const int>(1); });
  }
  std::size_t builds(const std::string& uid) {
    const auto& counts = configuration.cache().statistics().buildsByKey;
    const auto found = counts.find("geometry:" + uid);
    return found == counts.end() ? 0 : found->second;
  }

  Configuration configuration;
};

const std::string kWingScaling = "/cpacs/vehicles/aircraft/model/wings/wing[@uID='W']/transformation/scaling/x";

TEST_F(ModelEditing, ReadsAndWritesValuesByXPath) {
  EXPECT_EQ(configuration.value(kWingScaling), "1");
  EXPECT_EQ(configuration.value("/cpacs/vehicles/aircraft/model/wings/wing[2]/@uID"), "V");
  configuration.setValue(kWingScaling, "1.2");
  EXPECT_EQ(configuration.value(kWingScaling), "1.2");
  // The typed model follows the document.
  const auto& wing = configuration.cpacs().vehicles->aircraft->model[0].wings->wing[0];
  EXPECT_DOUBLE_EQ(wing.transformation->scaling->x.value(), 1.2);
}

TEST_F(ModelEditing, AnEditRebuildsOnlyWhatDependsOnIt) {
  buildAll();
  configuration.setValue(kWingScaling, "1.5");
  buildAll();
  EXPECT_EQ(builds("W"), 2u);  // the edited wing
  EXPECT_EQ(builds("F"), 1u);  // its parent is reused
  EXPECT_EQ(builds("V"), 1u);  // and so is the other wing

  configuration.setValue("/cpacs/vehicles/aircraft/model/fuselages/fuselage/transformation/translation/x", "2");
  buildAll();
  EXPECT_EQ(builds("F"), 2u);
  EXPECT_EQ(builds("W"), 3u);  // attached to the moved fuselage
  EXPECT_EQ(builds("V"), 1u);

  configuration.setValue("/cpacs/vehicles/profiles/wingAirfoils/wingAirfoil/pointList/z", "0;0.12;0");
  buildAll();
  EXPECT_EQ(builds("W"), 4u);  // uses the airfoil
  EXPECT_EQ(builds("F"), 2u);
  EXPECT_EQ(builds("V"), 1u);

  const CacheStatistics statistics = configuration.cache().statistics();
  EXPECT_EQ(statistics.built, 7u);
  EXPECT_EQ(statistics.invalidated, 4u);
  EXPECT_GE(statistics.reused, 5u);
}

TEST_F(ModelEditing, RefusedValuesLeaveTheDocumentAsItWas) {
  buildAll();
  try {
    configuration.setValue(kWingScaling, "wide");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::InvalidArgument);
    EXPECT_EQ(error.cpacsPath(), kWingScaling);
  }
  EXPECT_EQ(configuration.value(kWingScaling), "1");
  EXPECT_THROW(configuration.setValue("/cpacs/vehicles/aircraft/model/wings/wing[3]/name", "x"), Error);
  EXPECT_THROW(configuration.setValue("/cpacs/vehicles/aircraft/model/wings/wing[1]", "x"), Error);  // not a leaf
  // A wing made its own parent is a cycle: refused, and the wing stays under F.
  const std::string parent = "/cpacs/vehicles/aircraft/model/wings/wing[1]/parentUID";
  EXPECT_THROW(configuration.setValue(parent, "W"), Error);
  EXPECT_EQ(configuration.value(parent), "F");
  EXPECT_EQ(
      configuration.components().components()[static_cast<std::size_t>(configuration.components().find("W"))].parentUid,
      "F");
  buildAll();
  EXPECT_EQ(builds("W"), 1u);  // nothing was invalidated by the refused edits
}

TEST_F(ModelEditing, EditsOfTheTypedModelInvalidateToo) {
  buildAll();
  configuration.cpacs().vehicles->aircraft->model[0].wings->wing[1].transformation->scaling->x = 3.0;
  configuration.modelChanged();
  buildAll();
  EXPECT_EQ(builds("V"), 2u);
  EXPECT_EQ(builds("W"), 1u);
  EXPECT_EQ(configuration.value("/cpacs/vehicles/aircraft/model/wings/wing[2]/transformation/scaling/x"), "3");
}

TEST_F(ModelEditing, ElementsAreAddedAndRemoved) {
  buildAll();
  const std::string wings = "/cpacs/vehicles/aircraft/model/wings";
  configuration.remove(wings + "/wing[@uID='V']");
  EXPECT_LT(configuration.components().find("V"), 0);
  EXPECT_FALSE(configuration.uids().contains("V"));
  configuration.insertXml(wings, R"(<wing uID="T"><name>t</name><parentUID>F</parentUID><transformation/>
    <sections><section uID="TS"><name>s</name><elements><element uID="TE"><name>e</name><airfoilUID>A</airfoilUID>
    </element></elements></section></sections></wing>)",
                          1);
  EXPECT_EQ(configuration.value(wings + "/wing[1]/@uID"), "T");
  EXPECT_GE(configuration.components().find("T"), 0);
  buildAll();
  EXPECT_EQ(builds("W"), 1u);  // neither edit touched W or F
  EXPECT_EQ(builds("F"), 1u);
  EXPECT_EQ(builds("V"), 2u);  // gone, then asked for again: built anew

  // A repeated uID, a reference to nothing and broken XML are refused and change nothing.
  EXPECT_THROW(configuration.insertXml(wings, R"(<wing uID="W"><name>again</name></wing>)"), Error);
  EXPECT_THROW(configuration.remove("/cpacs/vehicles/profiles/wingAirfoils/wingAirfoil"), Error);  // W uses it
  EXPECT_THROW(configuration.insertXml(wings, "<wing>"), Error);
  EXPECT_EQ(configuration.value(wings + "/wing[2]/@uID"), "W");
  EXPECT_EQ(configuration.value("/cpacs/vehicles/profiles/wingAirfoils/wingAirfoil/@uID"), "A");
  EXPECT_THROW(configuration.value(wings + "/wing[3]"), Error);
}

}  // namespace
}  // namespace airshape
