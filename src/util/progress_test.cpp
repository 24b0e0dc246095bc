#include "ris/util/progress.h"

#include <gtest/gtest.h>

namespace ris {
namespace {

TEST(ProgressBar, LineShowsFractionRateAndTimeRemaining) {
  const std::string line =
      ProgressBar::format_line("simulate", 250, 1000, " cells", 2.0, "geometry", 20);
  // A quarter done in 2 s: 125 cells/s, 750 left -> 6 s.
  EXPECT_NE(line.find("[#####...............]"), std::string::npos) << line;
  EXPECT_NE(line.find(" 25%"), std::string::npos) << line;
  EXPECT_NE(line.find("125 cells/s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 6 s"), std::string::npos) << line;
  EXPECT_NE(line.find("geometry"), std::string::npos) << line;
  // A unit named without its space reads the same; a count under 1000 has
  // a space before its unit ("0 cells", not "0cells").
  const std::string bare = ProgressBar::format_line("simulate", 0, 1000, "cells", 1.0, "", 20);
  EXPECT_NE(bare.find("  0 cells  0 cells/s"), std::string::npos) << bare;
  const std::string big =
      ProgressBar::format_line("simulate", 1400000, 4000000, "cells", 2.0, "", 20);
  EXPECT_NE(big.find("1.4 Mcells  700 kcells/s"), std::string::npos) << big;
}

// A run counted in percent (ris simulate's in-memory stages): one
// percentage, the time taken and left, no "30%  30%  277%/s" (issue 38).
TEST(ProgressBar, PercentLineHasOnePercentageAndNoRate) {
  const std::string line =
      ProgressBar::format_line("simulate", 30, 100, "%", 6.0, "backscatter", 10);
  EXPECT_NE(line.find("[###.......]  30%"), std::string::npos) << line;
  EXPECT_EQ(line.find("30%", line.find("30%") + 1), std::string::npos) << line;
  EXPECT_EQ(line.find("/s"), std::string::npos) << line;
  // 30 % in 6 s: 5 % a second, 70 % left -> 14 s.
  EXPECT_NE(line.find("6 s elapsed"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 14 s"), std::string::npos) << line;
  EXPECT_NE(line.find("backscatter"), std::string::npos) << line;
}

TEST(ProgressBar, QuietDrawsNothingALogGetsPlainLines) {
  ::testing::internal::CaptureStderr();
  ProgressBar quiet("x", 10, "", true);
  EXPECT_FALSE(quiet.enabled());
  quiet.advance(5);
  quiet.set_stage("stage");
  quiet.finish();
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  // ctest runs with stderr redirected: not a terminal, so plain lines (one
  // per stage change), never a carriage return.
  if (stderr_is_terminal()) GTEST_SKIP() << "stderr is a terminal";
  ::testing::internal::CaptureStderr();
  ProgressBar piped("x", 10, "rows", false);
  EXPECT_TRUE(piped.enabled());
  piped.advance(5);
  piped.set_stage("writing");
  piped.finish();
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(log.find("ris x: ["), std::string::npos) << log;
  EXPECT_NE(log.find("50%"), std::string::npos) << log;
  EXPECT_NE(log.find("writing\n"), std::string::npos) << log;
  EXPECT_EQ(log.find('\r'), std::string::npos) << log;
}

}  // namespace
}  // namespace ris
