#include "common/navdb/dme_channel.hpp"

#include <cstdio>

namespace fedsim::nav {

namespace {
// Annex 10 Vol I Table A: the two paired blocks of channels, their first channel's X frequency.
constexpr int kLowBlockFirst = 17;    // 17X = 108.00 MHz
constexpr int kLowBlockLast = 59;     // 59Y = 112.25 MHz
constexpr int kHighBlockFirst = 70;   // 70X = 112.30 MHz
constexpr int kHighBlockLast = 126;   // 126Y = 117.95 MHz
constexpr std::uint32_t kLowBlockBaseKhz = 108000;
constexpr std::uint32_t kHighBlockBaseKhz = 112300;
constexpr std::uint32_t kChannelStepKhz = 100;  // between successive channel numbers
constexpr std::uint32_t kYOffsetKhz = 50;       // Y channels: +50 kHz
}  // namespace

std::optional<DmeChannel> parse_dme_channel(std::string_view text) {
  if (text.size() < 2 || text.size() > 4) return std::nullopt;
  const char mode = text.back();
  DmeChannel channel;
  if (mode == 'X' || mode == 'x') {
    channel.mode = 'X';
  } else if (mode == 'Y' || mode == 'y') {
    channel.mode = 'Y';
  } else {
    return std::nullopt;
  }
  int number = 0;
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
    number = number * 10 + (text[i] - '0');
  }
  if (number < 1 || number > 126) return std::nullopt;
  channel.number = number;
  return channel;
}

std::string dme_channel_text(const DmeChannel& channel) {
  char text[8];
  std::snprintf(text, sizeof text, "%03d%c", channel.number, channel.mode);
  return text;
}

std::optional<std::uint32_t> paired_vhf_khz(const DmeChannel& channel) {
  const std::uint32_t y = channel.mode == 'Y' ? kYOffsetKhz : 0;
  const auto n = static_cast<std::uint32_t>(channel.number);
  if (channel.number >= kLowBlockFirst && channel.number <= kLowBlockLast) {
    return kLowBlockBaseKhz + (n - kLowBlockFirst) * kChannelStepKhz + y;
  }
  if (channel.number >= kHighBlockFirst && channel.number <= kHighBlockLast) {
    return kHighBlockBaseKhz + (n - kHighBlockFirst) * kChannelStepKhz + y;
  }
  return std::nullopt;
}

std::optional<DmeChannel> dme_channel_for_vhf_khz(std::uint32_t frequency_khz) {
  if (frequency_khz % kYOffsetKhz != 0) return std::nullopt;
  const char mode = (frequency_khz % kChannelStepKhz) == 0 ? 'X' : 'Y';
  const std::uint32_t x_khz = frequency_khz - (mode == 'Y' ? kYOffsetKhz : 0);
  const std::uint32_t low_last_khz =
      kLowBlockBaseKhz + (kLowBlockLast - kLowBlockFirst) * kChannelStepKhz;
  const std::uint32_t high_last_khz =
      kHighBlockBaseKhz + (kHighBlockLast - kHighBlockFirst) * kChannelStepKhz;
  if (x_khz >= kLowBlockBaseKhz && x_khz <= low_last_khz) {
    return DmeChannel{kLowBlockFirst + static_cast<int>((x_khz - kLowBlockBaseKhz) / kChannelStepKhz),
                      mode};
  }
  if (x_khz >= kHighBlockBaseKhz && x_khz <= high_last_khz) {
    return DmeChannel{
        kHighBlockFirst + static_cast<int>((x_khz - kHighBlockBaseKhz) / kChannelStepKhz), mode};
  }
  return std::nullopt;
}

}  // namespace fedsim::nav
