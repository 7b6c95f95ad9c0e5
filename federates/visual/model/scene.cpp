#include "visual/model/scene.hpp"

namespace fedsim::visual {

int Scene::find_end(const std::string& designator) const {
  for (std::size_t i = 0; i < runway_ends.size(); ++i) {
    if (runway_ends[i].designator == designator) return static_cast<int>(i);
  }
  return -1;
}

std::vector<LightPoint> Scene::lights_of(int runway_end, LightRole role) const {
  std::vector<LightPoint> out;
  for (const auto& l : lights) {
    if (l.runway_end == runway_end && l.role == role) out.push_back(l);
  }
  return out;
}

}  // namespace fedsim::visual
