#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "airshape/error.h"
#include "airshape/output_file.h"

namespace fs = std::filesystem;

namespace {

/// A fresh empty folder for one test.
fs::path freshFolder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / ("airshape-output-file-" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string contentOf(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST(SafeOutput, WritesTheFileAndItsSideFiles) {
  const fs::path folder = freshFolder("side");
  const fs::path target = folder / "model.gltf";
  airshape::writeFileSafely(target.string(), [](const std::string& temporary) {
    EXPECT_EQ(fs::path(temporary).filename(), "model.gltf");  // writers derive side files from it
    writeText(temporary, "json");
    writeText((fs::path(temporary).parent_path() / "model.bin").string(), "buffer");
  });
  EXPECT_EQ(contentOf(target), "json");
  EXPECT_EQ(contentOf(folder / "model.bin"), "buffer");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 2);  // no temporary left
}

TEST(SafeOutput, AFailingWriterLeavesTheOldFileAndNoTemporary) {
  const fs::path folder = freshFolder("failing");
  const fs::path target = folder / "model.step";
  writeText(target.string(), "old");
  EXPECT_THROW(airshape::writeFileSafely(target.string(),
                                         [](const std::string& temporary) {
                                           writeText(temporary, "half");
                                           throw std::runtime_error("disk full");
                                         }),
               std::runtime_error);
  EXPECT_EQ(contentOf(target), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);
}

TEST(SafeOutput, AWriterThatWritesNothingIsAnError) {
  const fs::path folder = freshFolder("nothing");
  try {
    airshape::writeFileSafely((folder / "x.stl").string(), [](const std::string&) {});
    FAIL() << "no error";
  } catch (const airshape::Error& error) {
    EXPECT_EQ(error.code(), airshape::ErrorCode::WriteFailed);
    EXPECT_EQ(error.file(), (folder / "x.stl").string());
  }
  EXPECT_TRUE(fs::is_empty(folder));
}

TEST(SafeOutput, AMissingFolderIsNamed) {
  const fs::path folder = freshFolder("missing");
  try {
    airshape::writeTextFileSafely((folder / "no" / "x.xml").string(), "text");
    FAIL() << "no error";
  } catch (const airshape::Error& error) {
    EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("x.xml"), std::string::npos) << error.what();
  }
}
