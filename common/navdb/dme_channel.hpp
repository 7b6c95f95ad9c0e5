// DME/TACAN channels and their VHF pairing, ICAO Annex 10 Volume I, 3.5.3.3.4 and Table A
// ("DME/VHF frequency pairing"): channels 17X-59Y pair with 108.00-112.25 MHz and 70X-126Y with
// 112.30-117.95 MHz in 50 kHz steps (X on the .x0 frequency, Y on .x5); channels 1-16 and 60-69
// have no VHF frequency (military TACAN; some databases list pseudo-frequencies 133.30-135.95
// MHz for them).
//
// Text form as in OurAirports: three digits and the mode, "084X".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fedsim::nav {

struct DmeChannel {
  int number = 0;   // 1..126
  char mode = 'X';  // 'X' or 'Y'
  bool operator==(const DmeChannel&) const = default;
};

/// "84X", "084X", "084x" -> {84, 'X'}; nullopt for anything else (number outside 1..126).
std::optional<DmeChannel> parse_dme_channel(std::string_view text);
/// {84, 'X'} -> "084X".
std::string dme_channel_text(const DmeChannel& channel);
/// The paired VHF frequency [kHz], or nullopt for the unpaired channels 1-16 and 60-69.
std::optional<std::uint32_t> paired_vhf_khz(const DmeChannel& channel);
/// The channel paired with a VHF frequency [kHz] (108000..117950 on the 50 kHz grid), or
/// nullopt for any other frequency.
std::optional<DmeChannel> dme_channel_for_vhf_khz(std::uint32_t frequency_khz);

}  // namespace fedsim::nav
