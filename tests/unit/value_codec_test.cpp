#include "airshape/schema/value_codec.h"

#include <cmath>

#include <gtest/gtest.h>

#include "airshape/schema/generated/cpacs_model.h"

namespace airshape::schema {

TEST(ValueCodec, DoubleParsesXmlSchemaNumbersAndRejectsText) {
  double value = 0;
  EXPECT_FALSE(DoubleCodec::parse(" 1.5e3 ", value));
  EXPECT_EQ(value, 1500.0);
  EXPECT_FALSE(DoubleCodec::parse("+2", value));
  EXPECT_EQ(value, 2.0);
  EXPECT_FALSE(DoubleCodec::parse("NaN", value));
  EXPECT_TRUE(std::isnan(value));
  value = 7;
  EXPECT_TRUE(DoubleCodec::parse("1.0 m", value));
  EXPECT_TRUE(DoubleCodec::parse("", value));
  EXPECT_EQ(value, 7.0) << "a failed parse leaves the value alone";
}

TEST(ValueCodec, DoubleFormatRoundTripsExactly) {
  for (double x : {0.1, 1.0 / 3.0, -2.5e-300, 123456789.125}) {
    double back = 0;
    ASSERT_FALSE(DoubleCodec::parse(DoubleCodec::format(x), back));
    EXPECT_EQ(back, x);
  }
}

TEST(ValueCodec, IntegerAndBoolean) {
  long long integer = 0;
  EXPECT_FALSE(IntegerCodec::parse("42", integer));
  EXPECT_EQ(integer, 42);
  EXPECT_TRUE(IntegerCodec::parse("4.2", integer));
  EXPECT_EQ(integer, 42) << "a failed parse leaves the value";
  EXPECT_FALSE(IntegerCodec::parse(" 1.000000 ", integer)) << "an integral decimal, as some editors write";
  EXPECT_EQ(integer, 1);
  EXPECT_FALSE(IntegerCodec::parse("-3.0e0", integer));
  EXPECT_EQ(integer, -3);
  EXPECT_TRUE(IntegerCodec::parse("1.5", integer));
  EXPECT_TRUE(IntegerCodec::parse("1e300", integer)) << "beyond any integer";
  EXPECT_TRUE(IntegerCodec::parse("NaN", integer));
  EXPECT_EQ(integer, -3);
  bool flag = false;
  EXPECT_FALSE(BooleanCodec::parse("1", flag));
  EXPECT_TRUE(flag);
  EXPECT_TRUE(BooleanCodec::parse("yes", flag));
}

TEST(ValueCodec, DoubleVectorSplitsAtSemicolons) {
  std::vector<double> values;
  EXPECT_FALSE(DoubleVectorCodec::parse("0;0.5; 1", values));
  EXPECT_EQ(values, (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_FALSE(DoubleVectorCodec::parse("1;2;", values)) << "a trailing separator is tolerated";
  EXPECT_EQ(values.size(), 2u);
  const ParseError error = DoubleVectorCodec::parse("1;x;3", values);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("'x'"), std::string::npos);
  EXPECT_EQ(DoubleVectorCodec::format({1.0, 2.5}), "1;2.5");
}

TEST(ValueCodec, EnumerationsUseTheSchemaTexts) {
  SymmetryXyXzYzType symmetry{};
  EXPECT_FALSE(EnumCodec<SymmetryXyXzYzType>::parse("x-z-plane", symmetry));
  EXPECT_EQ(symmetry, SymmetryXyXzYzType::XZPlane);
  EXPECT_STREQ(toString(symmetry), "x-z-plane");
  const ParseError error = EnumCodec<SymmetryXyXzYzType>::parse("xz", symmetry);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("one of none, inherit"), std::string::npos);
}

}  // namespace airshape::schema
