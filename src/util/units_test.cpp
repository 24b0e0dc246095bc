#include "ris/util/units.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace ris {
namespace {

TEST(Units, LengthWithUnits) {
  EXPECT_DOUBLE_EQ(parse_quantity("20 ft", Quantity::length), 6.096);
  EXPECT_DOUBLE_EQ(parse_quantity("1.5 km", Quantity::length), 1500.0);
  EXPECT_DOUBLE_EQ(parse_quantity("  7  ", Quantity::length), 7.0);
}

TEST(Units, AnglesDefaultToDegrees) {
  EXPECT_NEAR(parse_quantity("90", Quantity::angle), kPi / 2, 1e-15);
  EXPECT_NEAR(parse_quantity("6.8e-4 rad", Quantity::angle), 6.8e-4, 1e-18);
}

TEST(Units, FrequencyAndTime) {
  EXPECT_DOUBLE_EQ(parse_quantity("8.6 GHz", Quantity::frequency), 8.6e9);
  EXPECT_NEAR(parse_quantity("0.163 us", Quantity::time), 1.63e-7, 1e-20);
}

TEST(Units, UnknownUnitIsAnErrorListingAccepted) {
  try {
    parse_quantity("20 furlongs", Quantity::length);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("furlongs"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("ft"), std::string::npos);
  }
  EXPECT_THROW(parse_quantity("GHz", Quantity::frequency), std::invalid_argument);
  EXPECT_THROW(parse_quantity("3 GHz", Quantity::length), std::invalid_argument);
}

}  // namespace
}  // namespace ris
