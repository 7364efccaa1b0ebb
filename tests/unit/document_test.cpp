// Opening documents: what is refused, and how.
#include <gtest/gtest.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
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

}  // namespace
}  // namespace airshape
