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
}

TEST(ProgressBar, QuietOrNotATerminalDrawsNothing) {
  ::testing::internal::CaptureStderr();
  ProgressBar quiet("x", 10, "", true);
  EXPECT_FALSE(quiet.enabled());
  quiet.advance(5);
  quiet.set_stage("stage");
  quiet.finish();
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  // ctest runs with stderr redirected: not a terminal.
  ProgressBar piped("x", 10, "", false);
  EXPECT_EQ(piped.enabled(), stderr_is_terminal());
}

}  // namespace
}  // namespace ris
