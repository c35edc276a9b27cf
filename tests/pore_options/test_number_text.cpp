// The strict decimal reader every style's keywords use (plugin_common/number_text.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "lbm/input_error.h"
#include "plugin_common/number_text.h"

using lbm_pore::read_decimal;
using lbm_pore::read_decimal_integer;

TEST(NumberText, PlainDecimalsReadAsStrtodReadsThem) {
  for (const char* text :
       {"1", "-2.5", "+3", ".5", "5.", "1e-3", "2.5E+04", "0", "-0", "0.142857", "1e300"})
    EXPECT_EQ(read_decimal(text).value(), std::strtod(text, nullptr)) << text;
}

TEST(NumberText, HexInfNanBlanksAndTrailingWordsAreRefused) {
  for (const char* text : {"0x10", "0X1p3", "inf",   "-inf",   "nan", "NAN", "infinity", " 1",
                           "1 ",   "1,5",   "1e",    "e5",     ".",   "-",   "",         "1e5x",
                           "--1",  "1.2.3", "1e400", "1e-400", "0x",  "+.e1"})
    EXPECT_FALSE(read_decimal(text).has_value()) << "'" << text << "'";
}

TEST(NumberText, IntegersAreDigitsOnlyAndFitAnInt) {
  EXPECT_EQ(read_decimal_integer("100").value(), 100);
  EXPECT_EQ(read_decimal_integer("-7").value(), -7);
  EXPECT_EQ(read_decimal_integer("+7").value(), 7);
  for (const char* text :
       {"0x10", "1e2", "1.0", "", "+", " 3", "3 ", "99999999999", "-99999999999"})
    EXPECT_FALSE(read_decimal_integer(text).has_value()) << "'" << text << "'";
}

TEST(NumberText, RangeErrorsNameCommandKeywordRangeAndText) {
  try {
    lbm_pore::number_in_range("fix wall/voxel", "mu", "0x10", 0.0, true, 1e300);
    FAIL();
  } catch (const lbm::InputError& e) {
    EXPECT_STREQ(e.what(), "fix wall/voxel: mu must be a number >= 0 (got '0x10')");
  }
  try {
    lbm_pore::integer_in_range("fix wall/voxel", "width", "1e3", 1, 1 << 20);
    FAIL();
  } catch (const lbm::InputError& e) {
    EXPECT_STREQ(e.what(), "fix wall/voxel: width must be an integer in [1, 1048576] (got '1e3')");
  }
  EXPECT_EQ(lbm_pore::interval_text(0.0, false, HUGE_VAL), "(0, inf]");
  EXPECT_EQ(lbm_pore::interval_text(1.0, true, 10.0), "[1, 10]");
}
