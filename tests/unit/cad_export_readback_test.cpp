// Every CAD export (STEP, IGES, BREP) of the example airliner, read back as a user's CAD tool
// reads it: with OCCT's own readers in metres, the unit each file declares checked, and the
// volume of each solid integrated exactly (adaptively) and compared with the queried volumes.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>

#include "airshape/configuration.h"
#include "airshape/export/exporter.h"
#include "airshape/geometry/brep_measures.h"
#include "airshape/plugin/plugin_host.h"
#include "airshape/query/query_service.h"

namespace {

namespace fs = std::filesystem;
using namespace airshape;

/// The volume of every solid of a shape as read, integrated exactly (geometry::volumeOf: OCCT's
/// default is a fixed Gauss rule, off by up to 10 % on B-spline lofts, and even its adaptive
/// rule at 1e-9 is 7e-7 off on the example's nacelle), smallest first.
std::vector<double> solidVolumes(const TopoDS_Shape& shape) {
  std::vector<double> volumes;
  for (TopExp_Explorer solids(shape, TopAbs_SOLID); solids.More(); solids.Next())
    volumes.push_back(geometry::volumeOf(solids.Current()));
  std::sort(volumes.begin(), volumes.end());
  return volumes;
}

/// A STEP or IGES file read with OCCT's reader of that format in metres: the readers convert
/// what they read into the session unit, which a user of metre-based CPACS geometry sets (the
/// reader's constructor initialises its parameters, so it is set before and after it).
template <class Reader>
TopoDS_Shape readInMetres(const std::string& path) {
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  Reader reader;
  Interface_Static::SetCVal("xstep.cascade.unit", "M");
  EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone) << path;
  reader.TransferRoots();
  return reader.OneShape();
}

TopoDS_Shape readBrep(const std::string& path) {
  TopoDS_Shape shape;
  BRep_Builder builder;
  EXPECT_TRUE(BRepTools::Read(shape, path.c_str(), builder)) << path;
  return shape;
}

std::string contents(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The parameters of an IGES file's global section, Hollerith strings (5HHello) decoded.
std::vector<std::string> igesGlobalParameters(const std::string& path) {
  std::string global;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (line.size() >= 73 && line[72] == 'G') global += line.substr(0, 72);
  std::vector<std::string> parameters;
  std::string current;
  for (std::size_t i = 0; i < global.size(); ++i) {
    const char c = global[i];
    if (c == ',' || c == ';') {
      parameters.push_back(current);
      current.clear();
      if (c == ';') break;
    } else if (c == 'H' && !current.empty() && std::all_of(current.begin(), current.end(), ::isdigit)) {
      const std::size_t length = std::stoul(current);
      current = global.substr(i + 1, length);
      i += length;
    } else if (c != ' ') {
      current += c;
    }
  }
  return parameters;
}

class CadExportReadBack : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    configuration_ = std::make_unique<Configuration>(
        Configuration::open(std::string(AIRSHAPE_SOURCE_DIR) + "/examples/generic-airliner.xml",
                            plugin::processPlugins().componentLocations()));
    configuration_->useShapes(plugin::processPlugins().shapes());
    folder_ = fs::temp_directory_path() / ("airshape-readback-" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  static void TearDownTestSuite() {
    fs::remove_all(folder_);
    configuration_.reset();
  }

  /// One answer of the query service.
  static query::Json asked(const std::string& question) {
    return query::answer(*configuration_, plugin::processPlugins().queries(), question)["ok"];
  }

  /// The uIDs of the wings and fuselages (one solid each; the example's other components,
  /// nacelles and the like, are compounds of several).
  static std::vector<std::string> wingsAndFuselages() {
    std::vector<std::string> uids;
    for (const std::string kind : {"wing", "fuselage"}) {
      const long count = asked("{\"op\":\"" + kind + "_count\"}").get<long>();
      for (long index = 1; index <= count; ++index)
        uids.push_back(
            asked("{\"op\":\"" + kind + "_uid\",\"" + kind + "\":" + std::to_string(index) + "}").get<std::string>());
    }
    return uids;
  }

  /// The volumes the query service gives for every wing and fuselage, smallest first.
  static std::vector<double> queriedVolumes() {
    std::vector<double> volumes;
    for (const std::string& uid : wingsAndFuselages())
      volumes.push_back(asked("{\"op\":\"component_volume\",\"uid\":\"" + uid + "\"}").get<double>());
    std::sort(volumes.begin(), volumes.end());
    return volumes;
  }

  static std::string exported(const std::string& name, const std::vector<std::string>& uids = wingsAndFuselages()) {
    const std::string path = (folder_ / name).string();
    exporting::ExportOptions options;
    options.components = uids;
    exporting::exportConfiguration(*configuration_, path, options);
    return path;
  }

  static void expectVolumesAsQueried(const std::vector<double>& volumes) {
    const std::vector<double> expected = queriedVolumes();
    ASSERT_EQ(volumes.size(), expected.size());
    for (std::size_t i = 0; i < volumes.size(); ++i) EXPECT_NEAR(volumes[i], expected[i], 1e-6 * expected[i]);
  }

  static std::unique_ptr<Configuration> configuration_;
  static fs::path folder_;
};

std::unique_ptr<Configuration> CadExportReadBack::configuration_;
fs::path CadExportReadBack::folder_;

TEST_F(CadExportReadBack, StepDeclaresMetresAndHoldsTheQueriedVolumes) {
  const std::string path = exported("airliner.step");
  const std::string text = contents(path);
  EXPECT_NE(text.find("SI_UNIT($,.METRE.)"), std::string::npos);  // metres, no prefix
  EXPECT_EQ(text.find(".MILLI."), std::string::npos);
  expectVolumesAsQueried(solidVolumes(readInMetres<STEPControl_Reader>(path)));
}

TEST_F(CadExportReadBack, StepOfSolidsIsWrittenByOurWriterExactly) {
  // Wings and fuselages are solids of B-spline and plane faces: our own STEP writer writes
  // them (step_brep_writer.h), every number as the shortest text that reads back as the same
  // double, so OCCT's reader gives the queried volumes to the integration's accuracy.
  const std::string path = exported("airliner-own-writer.step");
  EXPECT_NE(contents(path).find("FILE_DESCRIPTION(('Airshape export')"), std::string::npos);
  const std::vector<double> volumes = solidVolumes(readInMetres<STEPControl_Reader>(path));
  const std::vector<double> expected = queriedVolumes();
  ASSERT_EQ(volumes.size(), expected.size());
  for (std::size_t i = 0; i < volumes.size(); ++i) EXPECT_NEAR(volumes[i], expected[i], 1e-9 * expected[i]);
}

TEST_F(CadExportReadBack, StepOfOurWriterKeepsConesAndSurfacesOfRevolution) {
  // The example's nacelle: surfaces of revolution and cones, one opening backwards (a negative
  // semi-angle, which STEP writes about the reversed axis), on left-handed placements.
  const std::string path = exported("nacelle.step", {"Engine_Left"});
  const std::string text = contents(path);
  EXPECT_NE(text.find("FILE_DESCRIPTION(('Airshape export')"), std::string::npos);
  EXPECT_NE(text.find("CONICAL_SURFACE("), std::string::npos);
  EXPECT_NE(text.find("SURFACE_OF_REVOLUTION("), std::string::npos);
  const std::vector<double> volumes = solidVolumes(readInMetres<STEPControl_Reader>(path));
  ASSERT_EQ(volumes.size(), 1u);
  const double expected = asked("{\"op\":\"component_volume\",\"uid\":\"Engine_Left\"}").get<double>();
  EXPECT_NEAR(volumes[0], expected, 1e-9 * expected);
}

TEST_F(CadExportReadBack, IgesDeclaresMetresAndHoldsTheQueriedVolumes) {
  const std::string path = exported("airliner.igs");
  const std::vector<std::string> global = igesGlobalParameters(path);
  ASSERT_GE(global.size(), 15u);
  EXPECT_EQ(global[13], "6");  // parameter 14, the unit flag: 6 is metres
  EXPECT_EQ(global[14], "M");  // parameter 15, the unit's name
  expectVolumesAsQueried(solidVolumes(readInMetres<IGESControl_Reader>(path)));
}

TEST_F(CadExportReadBack, BrepHoldsTheQueriedVolumes) {
  // OCCT's BREP has no unit: it holds the model's metres as they are.
  expectVolumesAsQueried(solidVolumes(readBrep(exported("airliner.brep"))));
}

}  // namespace
