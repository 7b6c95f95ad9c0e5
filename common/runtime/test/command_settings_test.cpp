#include "common/runtime/command_settings.hpp"

#include <gtest/gtest.h>

namespace fedsim::runtime {
namespace {

msg::SimCommand failure(const std::string& target, bool active, std::uint32_t seq) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_FAILURE);
  c.target(target);
  c.issuer("fedsim-command");
  c.sequence_number(seq);
  c.failure().active(active);
  return c;
}

msg::SimCommand weather(double wind_mps, std::uint32_t seq) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_WEATHER);
  c.issuer("fedsim-command");
  c.sequence_number(seq);
  c.weather().wind_speed_mps(wind_mps);
  return c;
}

msg::SimCommand of_kind(msg::CommandKind kind) {
  msg::SimCommand c;
  c.kind(kind);
  return c;
}

TEST(CommandSettings, SettingsAreStateAndEventsAreNot) {
  EXPECT_TRUE(is_setting(of_kind(msg::COMMAND_WEATHER)));
  EXPECT_TRUE(is_setting(of_kind(msg::COMMAND_FAILURE)));
  EXPECT_TRUE(is_setting(of_kind(msg::COMMAND_RADIO_TUNING)));
  EXPECT_TRUE(is_setting(of_kind(msg::COMMAND_TIME_OF_DAY)));
  EXPECT_FALSE(is_setting(of_kind(msg::COMMAND_REPOSITION)));
  EXPECT_FALSE(is_setting(of_kind(msg::COMMAND_SNAPSHOT)));
  EXPECT_FALSE(is_setting(of_kind(msg::COMMAND_SHUTDOWN)));
  EXPECT_FALSE(is_setting(of_kind(msg::COMMAND_RUN_STATE)));
}

TEST(CommandSettings, HolderKeepsTheLatestSettingOfEachKindAndTarget) {
  SettingHolder holder;
  EXPECT_TRUE(holder.offer(weather(5, 1)));
  EXPECT_TRUE(holder.offer(failure("engine1", true, 2)));
  EXPECT_TRUE(holder.offer(failure("engine2", true, 3)));
  EXPECT_TRUE(holder.offer(weather(12, 4)));            // replaces the first weather
  EXPECT_TRUE(holder.offer(failure("engine1", false, 5)));  // engine1 restored
  EXPECT_FALSE(holder.offer(of_kind(msg::COMMAND_REPOSITION)));
  EXPECT_FALSE(holder.offer(of_kind(msg::COMMAND_SNAPSHOT)));
  const auto held = holder.held();
  ASSERT_EQ(held.size(), 3u);
  int weathers = 0;
  for (const auto& c : held) {
    if (c.kind() == msg::COMMAND_WEATHER) {
      ++weathers;
      EXPECT_EQ(c.weather().wind_speed_mps(), 12);
    }
    if (c.kind() == msg::COMMAND_FAILURE && c.target().to_string() == "engine1") {
      EXPECT_FALSE(c.failure().active());
      EXPECT_EQ(c.sequence_number(), 5u);  // the original sequence number, unchanged
    }
  }
  EXPECT_EQ(weathers, 1);
}

TEST(CommandSettings, HolderDoesNotRepublishWhatItHolds) {
  SettingHolder holder;
  ASSERT_TRUE(holder.offer(weather(5, 1)));
  EXPECT_FALSE(holder.offer(weather(5, 1)));  // its own copy coming back: no loop
  EXPECT_TRUE(holder.offer(weather(5, 2)));   // a new command with the same payload is news
}

TEST(CommandSettings, FilterDropsARedeliveredSettingOnly) {
  RedeliveryFilter filter;
  EXPECT_TRUE(filter.first_delivery(weather(5, 1)));
  EXPECT_FALSE(filter.first_delivery(weather(5, 1)));  // the holder's copy
  EXPECT_EQ(filter.dropped(), 1u);
  EXPECT_TRUE(filter.first_delivery(failure("engine1", true, 7)));
  EXPECT_TRUE(filter.first_delivery(failure("engine1", false, 7)));  // restore: payload differs
  EXPECT_TRUE(filter.first_delivery(failure("engine1", true, 7)));   // and fail again: applied
  EXPECT_FALSE(filter.first_delivery(failure("engine1", true, 7)));
  // Events always pass: an equal reposition issued twice repositions twice.
  EXPECT_TRUE(filter.first_delivery(of_kind(msg::COMMAND_REPOSITION)));
  EXPECT_TRUE(filter.first_delivery(of_kind(msg::COMMAND_REPOSITION)));
  EXPECT_EQ(filter.dropped(), 2u);
}

}  // namespace
}  // namespace fedsim::runtime
