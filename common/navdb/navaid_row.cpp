#include "common/navdb/navaid_row.hpp"

#include "common/navdb/dme_channel.hpp"
#include "common/navdb/nav_types.hpp"
#include "common/navdb/row_fields.hpp"
#include "common/units/units.hpp"

#include <cctype>

namespace fedsim::nav {

namespace {

// Bands and grids (ICAO Annex 10 Vol I 3.3.2.1, 3.4.2.1; Vol V 4.2).
constexpr std::uint32_t kVhfLowKhz = 108000;
constexpr std::uint32_t kVhfHighKhz = 117950;
constexpr std::uint32_t kVhfStepKhz = 50;
constexpr std::uint32_t kIlsBandTopKhz = 112000;  // below: VOR on even tenths, ILS on odd
constexpr double kNdbLowKhz = 190.0;
constexpr double kNdbHighKhz = 1750.0;

std::string khz_text(std::uint32_t khz) { return std::to_string(khz) + " kHz"; }

void check_vor_frequency(const csv::CsvRow& row, std::uint32_t khz) {
  if (khz < kVhfLowKhz || khz > kVhfHighKhz || khz % kVhfStepKhz != 0) {
    row.fail("column 'frequency_khz': " + khz_text(khz) +
             " is not a VOR frequency (108000-117950 kHz in 50 kHz steps)");
  }
  if (khz < kIlsBandTopKhz && (khz / 100) % 2 == 1) {
    row.fail("column 'frequency_khz': " + khz_text(khz) +
             " is an ILS localizer frequency (odd tenth of MHz below 112 MHz), not a VOR's");
  }
}

/// The DME channel of a station with DME: as given, else derived from the paired frequency.
DmeChannel dme_channel_of(const csv::CsvRow& row, NavaidType type, std::uint32_t frequency_khz) {
  const std::string& text = row.text("dme_channel");
  if (!text.empty()) {
    const auto channel = parse_dme_channel(text);
    if (!channel) row.fail("column 'dme_channel': '" + text + "' is not a DME channel (1X..126Y)");
    return *channel;
  }
  std::uint32_t paired_khz = frequency_khz;
  if (type == NavaidType::kNdbDme) {
    if (row.empty("dme_frequency_khz")) row.fail("column 'dme_channel': empty for an NDB-DME");
    paired_khz = whole_khz(row, "dme_frequency_khz", kVhfLowKhz, kVhfHighKhz);
  }
  const auto derived = dme_channel_for_vhf_khz(paired_khz);
  if (!derived) {
    row.fail("column 'dme_channel': empty, and " + khz_text(paired_khz) +
             " pairs with no DME channel");
  }
  return *derived;
}

/// Sets the DME of a station that has one and checks its channel against the frequency;
/// returns the station's stored frequency (0 for a TACAN/DME on an unpaired channel).
std::uint32_t set_dme(const csv::CsvRow& row, NavaidRow& out, std::uint32_t frequency_khz) {
  Navaid& n = out.navaid;
  const DmeChannel channel = dme_channel_of(row, n.type, frequency_khz);
  n.dme_channel = dme_channel_text(channel);
  const auto paired = paired_vhf_khz(channel);
  const bool frequency_is_vhf_pairing = n.type != NavaidType::kNdbDme;
  if (frequency_is_vhf_pairing) {
    if (paired && *paired != frequency_khz) {
      row.fail("column 'frequency_khz': " + khz_text(frequency_khz) + " but DME channel " +
               n.dme_channel + " pairs with " + khz_text(*paired) +
               " (ICAO Annex 10 Vol I Table A)");
    }
    if (!paired && has_vor(n.type)) {
      row.fail("column 'dme_channel': " + n.dme_channel +
               " has no VHF pairing, impossible for a VOR's DME");
    }
  }
  if (paired && !row.empty("dme_frequency_khz")) {
    const double given = row.number("dme_frequency_khz");
    if (given != static_cast<double>(*paired)) {
      out.warnings.push_back("column 'dme_frequency_khz': " + row.text("dme_frequency_khz") +
                             " disagrees with channel " + n.dme_channel + " (" +
                             khz_text(*paired) + "): the channel is kept");
    }
  }

  const bool has_lat = !row.empty("dme_latitude_deg");
  const bool has_lon = !row.empty("dme_longitude_deg");
  if (has_lat != has_lon) row.fail("column 'dme_latitude_deg'/'dme_longitude_deg': only one given");
  const auto dme_elevation_ft =
      optional_number_in(row, "dme_elevation_ft", kMinElevationFt, kMaxElevationFt);
  GeoPoint dme = n.position;  // co-located unless stated
  if (has_lat) {
    dme = point_from_degrees(required_number_in(row, "dme_latitude_deg", -90.0, 90.0),
                             required_number_in(row, "dme_longitude_deg", -180.0, 180.0),
                             n.position.elevation_m);
  }
  out.dme_elevation_known = n.elevation_known;
  if (dme_elevation_ft) {
    dme.elevation_m = *dme_elevation_ft * units::kFtToM;
    out.dme_elevation_known = true;
  }
  n.dme = dme;
  if (frequency_is_vhf_pairing && !paired) return 0;
  return frequency_khz;
}

std::uint32_t checked_frequency(const csv::CsvRow& row, NavaidType type) {
  if (is_ndb(type)) {
    const double khz = required_number_in(row, "frequency_khz", -1e9, 1e9);
    if (khz < kNdbLowKhz || khz > kNdbHighKhz) {
      row.fail("column 'frequency_khz': " + row.text("frequency_khz") +
               " kHz is outside the NDB band 190-1750 kHz");
    }
    return whole_khz(row, "frequency_khz", kNdbLowKhz, kNdbHighKhz);
  }
  const std::uint32_t khz = whole_khz(row, "frequency_khz", 0.0, 1e9);
  if (has_vor(type)) check_vor_frequency(row, khz);
  return khz;
}

void check_country(const csv::CsvRow& row, const std::string& country) {
  const bool two_letters = country.size() == 2 && std::isupper(static_cast<unsigned char>(country[0])) &&
                           std::isupper(static_cast<unsigned char>(country[1]));
  if (!two_letters) row.fail("column 'iso_country': '" + country + "' is not an ISO 3166 code");
}

}  // namespace

const std::vector<std::string>& navaid_columns() {
  static const std::vector<std::string> columns{
      "id", "ident", "name", "type", "frequency_khz", "latitude_deg", "longitude_deg",
      "elevation_ft", "iso_country", "dme_frequency_khz", "dme_channel", "dme_latitude_deg",
      "dme_longitude_deg", "dme_elevation_ft", "slaved_variation_deg", "magnetic_variation_deg",
      "usageType", "power", "associated_airport"};
  return columns;
}

NavaidRow parse_navaid_row(const csv::CsvRow& row) {
  NavaidRow out;
  Navaid& n = out.navaid;
  n.id = row.integer("id");
  if (n.id <= 0) row.fail("column 'id': " + row.text("id") + " is not a positive id");
  n.ident = required_text(row, "ident");
  n.name = row.text("name");
  const std::string& type_text = row.text("type");
  const auto type = parse_navaid_type(type_text);
  if (!type) {
    row.fail("column 'type': unknown type '" + type_text +
             "' (VOR, VOR-DME, VORTAC, DME, TACAN, NDB, NDB-DME)");
  }
  n.type = *type;
  const std::uint32_t frequency_khz = checked_frequency(row, n.type);

  const auto elevation_ft = optional_number_in(row, "elevation_ft", kMinElevationFt, kMaxElevationFt);
  n.elevation_known = elevation_ft.has_value();
  n.position = point_from_degrees(required_number_in(row, "latitude_deg", -90.0, 90.0),
                                  required_number_in(row, "longitude_deg", -180.0, 180.0),
                                  elevation_ft.value_or(0.0) * units::kFtToM);
  n.magnetic_variation_rad =
      required_number_in(row, "magnetic_variation_deg", -180.0, 180.0) * units::kDegToRad;
  const auto slaved = optional_number_in(row, "slaved_variation_deg", -180.0, 180.0);
  n.slaved_variation_known = slaved.has_value();
  n.slaved_variation_rad = slaved.value_or(0.0) * units::kDegToRad;

  const auto power = parse_power_class(row.text("power"));
  if (!power) row.fail("column 'power': unknown power class '" + row.text("power") + "'");
  n.power = *power;
  const auto usage = parse_usage_type(row.text("usageType"));
  if (!usage) row.fail("column 'usageType': unknown usage '" + row.text("usageType") + "'");
  n.usage = *usage;
  n.country = row.text("iso_country");
  check_country(row, n.country);
  n.airport = row.text("associated_airport");

  if (has_dme(n.type)) {
    n.frequency_khz = set_dme(row, out, frequency_khz);
  } else {
    if (!row.empty("dme_channel")) {
      row.fail("column 'dme_channel': " + row.text("dme_channel") + " given for a " + type_text +
               " (a station without DME)");
    }
    n.frequency_khz = frequency_khz;
  }
  return out;
}

}  // namespace fedsim::nav
