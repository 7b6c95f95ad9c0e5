// The navigation display (seed 5.8.4's compass card grown into the EFIS ND), in the Boeing
// ND's ROSE form: a full compass rose, heading up, centred on the aircraft, with the HSI on it
// (the selected course pointer, the course deviation bar on its dot scale, the TO/FROM
// pointer), the two bearing pointers (VOR green, ADF cyan; 1 single-line, 2 double-line), the
// track line, the selected-heading bug, and the navaids within range drawn at their bearing and
// distance (the overlay MAP CTR mode draws; VOR hexagon, DME square, VOR-DME both, NDB ring of
// dots, airport circle). Readouts: heading on top, GS/TAS top left, the course station's ident
// and DME distance top right, the bearing pointers' sources at the bottom corners.
//
// Design units: a 1000 x 1000 square (y down) fitted to the picture's shorter side and centred;
// the rose's outer ring is range_nm from the aircraft, the dashed inner ring half that. Course
// deviation 70 units per dot.
#pragma once

#include "common/symbology/canvas.hpp"
#include "displays/model/display_inputs.hpp"

namespace fedsim::displays {

struct NdLayout {
  double px_per_unit = 1.0;
  symbology::Vec2 origin_px = symbology::Vec2::Zero();
  symbology::Vec2 rose_centre_px = symbology::Vec2::Zero();  // the aircraft
  double rose_radius_px = 0.0;         // range_nm from the aircraft
  double deviation_dot_px = 0.0;
  symbology::Rect course_flag_px;  // where the VOR / LOC flag is drawn

  symbology::Vec2 to_px(const symbology::Vec2& design) const { return origin_px + px_per_unit * design; }
};

NdLayout nd_layout(int width_px, int height_px);

/// Draws the ND into `canvas` (reset to the picture's size first); inputs validated.
void draw_nd(symbology::Canvas& canvas, const NdInputs& in);

}  // namespace fedsim::displays
