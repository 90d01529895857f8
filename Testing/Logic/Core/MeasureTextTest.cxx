// How messages print a measure: fixed decimals for what a mesh measures, compact beyond.
#include "Core/MeasureText.h"

#include <gtest/gtest.h>

#include <limits>

namespace slicemesh
{
namespace
{

TEST(MeasureText, FixedDecimalsForOrdinaryValues)
{
  EXPECT_EQ(measureText(25.0, 1), "25.0");
  EXPECT_EQ(measureText(65447.66, 1), "65447.7");
  EXPECT_EQ(measureText(1000000.0, 1), "1000000.0");
  EXPECT_EQ(measureText(592.0, 0), "592");
  EXPECT_EQ(measureText(0.0, 2), "0.00");
  EXPECT_EQ(measureText(-12.345, 2), "-12.35");
}

TEST(MeasureText, ThreeSignificantDigitsWhereTheDecimalsWouldShowZero)
{
  EXPECT_EQ(measureText(0.0001234, 1), "0.000123");
  EXPECT_EQ(measureText(0.004, 2), "0.004");
}

TEST(MeasureText, AnExponentForValuesBeyondWhatFixedDigitsCanHold)
{
  // A contour file's coordinate of 1e300 printed three hundred digits in a message.
  EXPECT_EQ(measureText(1e300, 1), "1e+300");
  EXPECT_EQ(measureText(-5.669251963571548e284, 1), "-5.66925e+284");
  EXPECT_EQ(measureText(1.4e296, 1), "1.4e+296");
  EXPECT_EQ(measureText(1e15, 0), "1e+15");
  EXPECT_EQ(measureText(999999999999999.0, 0), "999999999999999");
  EXPECT_EQ(measureText(std::numeric_limits<double>::max(), 3), "1.79769e+308");
}

} // namespace
} // namespace slicemesh
