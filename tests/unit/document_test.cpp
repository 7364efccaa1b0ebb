// Opening documents: what is refused, and how.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/xml/nesting.h"
#include "airshape/xml/read_ahead.h"
#include "test_support.h"

namespace airshape {
namespace {

ErrorCode openError(const std::string& text) {
  try {
    Configuration::fromString(text, "input.xml");
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("input.xml"), std::string::npos) << error.what();
    return error.code();
  }
  ADD_FAILURE() << "opening must fail";
  return ErrorCode::InvalidModel;
}

TEST(Opening, RefusesWhatIsNotCpacs3) {
  EXPECT_EQ(openError(""), ErrorCode::NotXml);
  EXPECT_EQ(openError("<cpacs><header>"), ErrorCode::NotXml);
  EXPECT_EQ(openError(std::string("\x7f"
                                  "ELF\x01\x02",
                                  6)),
            ErrorCode::NotXml);
  EXPECT_EQ(openError("<root/>"), ErrorCode::NotCpacs);
  EXPECT_EQ(openError("<cpacs><header><cpacsVersion>2.1.3</cpacsVersion></header></cpacs>"),
            ErrorCode::UnsupportedVersion);
  EXPECT_EQ(openError("<cpacs><header><name>x</name></header></cpacs>"), ErrorCode::UnsupportedVersion);
}

TEST(Opening, ReadsTheVersionFromEitherPlace) {
  EXPECT_EQ(Configuration::fromString(test::cpacsDocument("")).cpacsVersion(), "3.5");
  const auto old = Configuration::fromString("<cpacs><header><cpacsVersion>3.0</cpacsVersion></header></cpacs>");
  EXPECT_EQ(old.cpacsVersion(), "3.0");
}

TEST(Opening, MissingFileNamesTheFile) {
  try {
    Configuration::open("/no/such/file.xml");
    FAIL();
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::FileNotFound);
    EXPECT_EQ(std::string(error.what()), "/no/such/file.xml: no such file");
  }
}

/// Writes `text` to a file of the test's own in the temporary folder; returns its path.
std::string temporaryFile(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(ReadingAhead, TheOpenTakesTheDocumentReadAhead) {
  const std::string path = temporaryFile("airshape_read_ahead.xml", test::cpacsDocument(""));
  {
    const xml::ReadAhead readAhead(path);
    EXPECT_EQ(Configuration::open(path).cpacsVersion(), "3.5");
    EXPECT_FALSE(xml::takeReadAhead(path)) << "taken once: a second open reads the file again";
    EXPECT_EQ(Configuration::open(path).cpacsVersion(), "3.5");
  }
  std::filesystem::remove(path);
}

TEST(ReadingAhead, AnErrorReadingAheadIsTheOpensError) {
  const std::string path = temporaryFile("airshape_read_ahead_broken.xml", "<cpacs><header>");
  {
    const xml::ReadAhead readAhead(path);
    try {
      Configuration::open(path);
      FAIL();
    } catch (const Error& error) {
      EXPECT_EQ(error.code(), ErrorCode::NotXml);
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    }
  }
  const xml::ReadAhead missing("/no/such/file.xml");
  EXPECT_FALSE(xml::takeReadAhead("another.xml")) << "only the path read ahead is taken";
  EXPECT_THROW(xml::takeReadAhead("/no/such/file.xml"), Error);
  std::filesystem::remove(path);
}

TEST(ReadingAhead, AnUnusedReadAheadIsDroppedOnTheWayOut) {
  const std::string path = temporaryFile("airshape_read_ahead_unused.xml", test::cpacsDocument(""));
  { const xml::ReadAhead readAhead(path); }
  EXPECT_FALSE(xml::takeReadAhead(path));
  std::filesystem::remove(path);
}

/// A CPACS document with `depth` levels of <x> elements in its header, which the schema
/// keeps as elements it does not know; the innermost one holds a uID.
std::string nestedDocument(std::size_t depth) {
  std::string nesting;
  for (std::size_t i = 0; i < depth; ++i) nesting += "<x>";
  nesting += "<y uID=\"Deep\"/>";
  for (std::size_t i = 0; i < depth; ++i) nesting += "</x>";
  std::string document = test::cpacsDocument("");
  return document.replace(document.find("</header>"), 0, nesting);
}

TEST(Opening, NestingBeyondTheLimitIsRefusedNotACrash) {
  // 6,600 levels overflowed the stack in the uID registry's walk; every walk over a document is
  // now within kMaximumNesting, and deeper documents are refused with a line naming the file.
  try {
    Configuration::fromString(nestedDocument(6600), "deep.xml");
    FAIL() << "a document nested 6,600 levels deep must be refused";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::NotXml);
    EXPECT_NE(std::string(error.what()).find("deep.xml: elements are nested 6603 levels deep"), std::string::npos)
        << error.what();
  }
  const Configuration deepButAllowed = Configuration::fromString(nestedDocument(xml::kMaximumNesting - 10));
  EXPECT_TRUE(deepButAllowed.uids().contains("Deep"));
}

TEST(Opening, InsertedXmlMayNotNestBeyondTheLimit) {
  Configuration configuration = Configuration::fromString(nestedDocument(xml::kMaximumNesting - 10));
  std::string fragment;
  for (int i = 0; i < 20; ++i) fragment += "<z>";
  for (int i = 0; i < 20; ++i) fragment += "</z>";
  std::string deepest = "/cpacs/header";
  for (std::size_t i = 0; i < xml::kMaximumNesting - 10; ++i) deepest += "/x";
  try {
    configuration.insertXml(deepest, fragment);
    FAIL() << "the fragment would nest beyond the limit";
  } catch (const Error& error) {
    EXPECT_NE(error.message().find("levels deep"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace airshape
