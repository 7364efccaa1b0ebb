// Opening documents: what is refused, and how.
#include <gtest/gtest.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/xml/nesting.h"
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
