// Physical-group names shared by the .msh writer and reader.
#include "msh_names.hpp"

#include <string>

namespace rockfdem::mesh {

std::string edge_tag_name(int tag) {
  switch (tag) {
    case kBottom:
      return "bottom";
    case kRight:
      return "right";
    case kTop:
      return "top";
    case kLeft:
      return "left";
    case kExcavation:
      return "excavation";
    case kLiningInner:
      return "lining_inner";
    case kRim:
      return "rim";
    case kLoadTop:
      return "load_top";
    case kLoadBottom:
      return "load_bottom";
    default:
      return "edge_" + std::to_string(tag);
  }
}

std::string zone_name(int zone) {
  switch (zone) {
    case kRock:
      return "rock";
    case kCore:
      return "core";
    case kLining:
      return "lining";
    default:
      return "zone_" + std::to_string(zone);
  }
}

namespace detail {

std::map<std::string, int> default_zone_groups() {
  std::map<std::string, int> out;
  for (Zone z : kZones) out[zone_name(z)] = z;
  return out;
}

}  // namespace detail
}  // namespace rockfdem::mesh
