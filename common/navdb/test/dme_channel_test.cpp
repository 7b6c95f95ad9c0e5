// DME/VHF pairing against ICAO Annex 10 Vol I Table A and published station data.
#include "common/navdb/dme_channel.hpp"

#include <gtest/gtest.h>

namespace fedsim::nav {
namespace {

std::uint32_t paired(const char* text) {
  const auto channel = parse_dme_channel(text);
  EXPECT_TRUE(channel.has_value()) << text;
  const auto khz = channel ? paired_vhf_khz(*channel) : std::nullopt;
  return khz.value_or(0);
}

TEST(DmeChannel, PairingFollowsAnnex10TableA) {
  // Table A: first and last channels of both paired blocks, X and Y.
  EXPECT_EQ(paired("017X"), 108000u);
  EXPECT_EQ(paired("017Y"), 108050u);
  EXPECT_EQ(paired("018X"), 108100u);  // the first ILS localizer frequency
  EXPECT_EQ(paired("056Y"), 111950u);  // the last
  EXPECT_EQ(paired("059Y"), 112250u);
  EXPECT_EQ(paired("070X"), 112300u);
  EXPECT_EQ(paired("126Y"), 117950u);
  // Published stations (FAA Chart Supplement): SFO VOR-DME 115.8 ch 105X, OAK VORTAC 116.8 ch
  // 115X, LIT VORTAC 113.9 ch 86X.
  EXPECT_EQ(paired("105X"), 115800u);
  EXPECT_EQ(paired("115X"), 116800u);
  EXPECT_EQ(paired("86X"), 113900u);
}

TEST(DmeChannel, MilitaryChannelsHaveNoVhfPairing) {
  for (const char* text : {"001X", "016Y", "060X", "069Y", "012X"}) {
    const auto channel = parse_dme_channel(text);
    ASSERT_TRUE(channel) << text;
    EXPECT_FALSE(paired_vhf_khz(*channel).has_value()) << text;
  }
}

TEST(DmeChannel, EveryPairedFrequencyRoundTrips) {
  int paired_count = 0;
  for (std::uint32_t khz = 107950; khz <= 118000; khz += 50) {
    const auto channel = dme_channel_for_vhf_khz(khz);
    if (khz < 108000 || khz > 117950 || (khz > 112250 && khz < 112300)) {
      EXPECT_FALSE(channel) << khz;
      continue;
    }
    ASSERT_TRUE(channel) << khz;
    EXPECT_EQ(paired_vhf_khz(*channel), khz);
    ++paired_count;
  }
  EXPECT_EQ(paired_count, 2 * (59 - 17 + 1) + 2 * (126 - 70 + 1));  // 200 paired channels
  EXPECT_FALSE(dme_channel_for_vhf_khz(115825).has_value());         // off the 50 kHz grid
}

TEST(DmeChannel, ParsesOurAirportsTextAndRejectsOtherText) {
  EXPECT_EQ(parse_dme_channel("084X"), (DmeChannel{84, 'X'}));
  EXPECT_EQ(parse_dme_channel("7y"), (DmeChannel{7, 'Y'}));
  EXPECT_EQ(dme_channel_text(DmeChannel{7, 'Y'}), "007Y");
  for (const char* bad : {"", "X", "000X", "127X", "084Z", "08 4X", "-12X", "12345X"}) {
    EXPECT_FALSE(parse_dme_channel(bad).has_value()) << bad;
  }
}

}  // namespace
}  // namespace fedsim::nav
