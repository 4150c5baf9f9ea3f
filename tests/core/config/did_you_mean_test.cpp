// Tests of typo suggestions.
#include "core/config/did_you_mean.hpp"

#include <gtest/gtest.h>

namespace corrmp {

TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(edit_distance("width", "width"), 0);
  EXPECT_EQ(edit_distance("widht", "width"), 2);
  EXPECT_EQ(edit_distance("", "abc"), 3);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
}

TEST(DidYouMean, SuggestsTheClosestPlausibleCandidate) {
  EXPECT_EQ(did_you_mean("widht", {"depth", "width", "lr"}), " (did you mean 'width'?)");
  EXPECT_EQ(did_you_mean("zzzzzz", {"depth", "width"}), "");
  EXPECT_EQ(closest_match("corridor_psh", {"corridor_push", "rope_knot"}), "corridor_push");
}

}  // namespace corrmp
