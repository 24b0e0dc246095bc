// Did-you-mean suggestions (ris/util/spelling.h): the distance's closed
// values, and which slips are suggested and which are not.
#include "ris/util/spelling.h"

#include <gtest/gtest.h>

namespace ris {
namespace {

TEST(Spelling, EditDistanceCountsEachEditOnce) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);  // Levenshtein's classic
  EXPECT_EQ(edit_distance("polarization", "polarisation"), 1u);
  EXPECT_EQ(edit_distance("ca", "ac"), 1u);  // a swap of neighbours
  EXPECT_EQ(edit_distance("abcd", "acbd"), 1u);
  EXPECT_EQ(edit_distance("Right", "right"), 0u);  // case is not a slip
  EXPECT_EQ(edit_distance("simulat", "simulate"), 1u);
}

TEST(Spelling, OnlyNearAndUniqueNamesAreSuggested) {
  const std::vector<std::string> keys{"polarisation", "frequency", "pulse_width"};
  EXPECT_EQ(nearest_name("polarization", keys), "polarisation");
  EXPECT_EQ(nearest_name("frequncy", keys), "frequency");
  EXPECT_EQ(nearest_name("altitude", keys), std::nullopt);         // nothing near
  EXPECT_EQ(nearest_name("frequency", keys), std::nullopt);        // the word itself
  EXPECT_EQ(nearest_name("bat", {"cat", "hat"}), std::nullopt);    // a tie
  EXPECT_EQ(nearest_name("colour", {"color", "colon"}), "color");  // 1 against 2
  EXPECT_EQ(nearest_name("ab", {"xy"}), std::nullopt);             // 2 edits in 2 letters
  EXPECT_EQ(did_you_mean("simulat", {"simulate", "study"}), " (did you mean \"simulate\"?)");
  EXPECT_EQ(did_you_mean("zzz", {"simulate"}), "");
}

}  // namespace
}  // namespace ris
