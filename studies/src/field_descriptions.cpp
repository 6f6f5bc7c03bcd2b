#include "field_descriptions.hpp"

#include <map>

namespace wearscale::studies {

std::string contact_field_description(const std::string& dataset) {
  static const std::map<std::string, std::string> known = {
      {"/surface/height", "height h(x, y) of the rigid rough surface the elastic half-space meets (both surfaces' "
                          "gap at zero load, Johnson's equivalent surface)"},
      {"/fields/pressure", "normal contact pressure p_N(x, y), compressive positive"},
      {"/fields/traction_x", "tangential traction p_x(x, y) on the surface"},
      {"/fields/traction_y", "tangential traction p_y(x, y) on the surface"},
      {"/fields/stick_slip", "contact state: 0 open, 1 stick, 2 slip"},
      {"/fields/gap", "normal gap g(x, y) between the surfaces, 0 in contact"},
      {"/fields/slip_x", "slip (relative tangential displacement) along x"},
      {"/fields/slip_y", "slip (relative tangential displacement) along y"},
      {"/fields/displacement", "normal displacement u_z(x, y) of the elastic surface"},
      {"/fields/displacement_x", "tangential displacement u_x(x, y) of the elastic surface"},
      {"/fields/displacement_y", "tangential displacement u_y(x, y) of the elastic surface"},
      {"/fields/contact", "1 where the surfaces touch (p_N > 0), else 0"},
      {"/stress/surface/sigma_I", "largest principal stress at the surface (tension positive)"},
      {"/stress/surface/sigma_III", "smallest principal stress at the surface (tension positive)"},
      {"/stress/surface/tau_max", "maximum shear stress at the surface, (sigma_I - sigma_III)/2"},
  };
  if (const auto it = known.find(dataset); it != known.end()) return it->second;
  // "/stress/depth_<k>/<what>": the same quantity at the group's `depth` below the surface.
  if (dataset.starts_with("/stress/depth_")) {
    const auto leaf = dataset.substr(dataset.rfind('/') + 1);
    if (const auto it = known.find("/stress/surface/" + leaf); it != known.end()) {
      std::string text = it->second;
      const auto at = text.find(" at the surface");
      if (at != std::string::npos) text.replace(at, 15, " at the group's depth below the surface");
      return text;
    }
  }
  return "";
}

}  // namespace wearscale::studies
