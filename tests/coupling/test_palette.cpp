// The categorical colours of the figures: Okabe & Ito's palette and its tints.
#include <gtest/gtest.h>

#include <stdexcept>

#include "wearscale/coupling/palette.hpp"

namespace oi = wearscale::coupling::okabe_ito;

TEST(Palette, TintMixesWithWhiteChannelByChannel) {
  EXPECT_EQ(oi::tint(oi::sky_blue, 1.0), "#56B4E9");
  EXPECT_EQ(oi::tint(oi::sky_blue, 0.0), "#FFFFFF");
  // 255 - 0.5 (255 - c): 0x56 = 86 -> 170.5 -> 171 (AB), 0xB4 = 180 -> 217.5 -> 218 (DA), 0xE9 = 233 -> 244
  EXPECT_EQ(oi::tint(oi::sky_blue, 0.5), "#ABDAF4");
  EXPECT_EQ(oi::tint("#009e73", 0.5), "#80CFB9") << "lower-case digits read as well";
}

TEST(Palette, TintRefusesWhatIsNotAColourOrAFraction) {
  EXPECT_THROW(oi::tint("56B4E9", 0.5), std::invalid_argument);
  EXPECT_THROW(oi::tint("#56B4G9", 0.5), std::invalid_argument);
  EXPECT_THROW(oi::tint(oi::orange, 1.5), std::invalid_argument);
  EXPECT_THROW(oi::tint(oi::orange, -0.1), std::invalid_argument);
}
