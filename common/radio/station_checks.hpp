// Checks of the station records the receivers compute with (common/navdb/nav_records.hpp). A bad
// record is a data error, not per-frame noise: these throw std::invalid_argument naming the
// station and the field, e.g. "navaid 'SFO' (id 93531): position.lat_rad = nan (not finite or
// outside [-pi/2, pi/2])". The receivers call them on every record they are given; the adapter
// may call them when it fills its cache so that the error surfaces at load time.
#pragma once

#include "common/navdb/nav_records.hpp"

namespace fedsim::radio {

void check_navaid(const nav::Navaid& navaid);
void check_approach(const nav::IlsApproach& approach);

/// VOR, VOR-DME or VORTAC (a station with a VOR bearing signal).
bool has_vor(const nav::Navaid& navaid);
/// NDB or NDB-DME (a station an ADF points to).
bool has_ndb(const nav::Navaid& navaid);

}  // namespace fedsim::radio
