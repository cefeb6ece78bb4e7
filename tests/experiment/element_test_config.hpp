#pragma once
// The run configuration the element tests read (fast and slow): 2 mm beads on the presets' spring
// (k_n = 1e6 N/m, k_t = k_n / 2, e = 0.9), friction mu (static and kinetic), rolling resistance
// mu_r (constant torque, or none when 0), and a short pour (a run configuration needs one; the
// element test ignores it). The [element] table is left open for the test's own keys: its first
// key goes on line 19.
#include <string>

#include <fmt/format.h>

namespace trapdem {

inline std::string element_test_config(const std::string& name, double mu, double mu_r) {
  return fmt::format(
      "name = \"{0}\"\n"
      "[particles]\n"
      "density = 2500.0\n"
      "size = \"uniform\"\n"
      "min_diameter = 0.0019\n"
      "max_diameter = 0.0021\n"
      "[contact]\n"
      "normal_stiffness = 1.0e6\n"
      "tangential_stiffness = 5.0e5\n"
      "restitution = 0.9\n"
      "static_friction = {1}\n"
      "kinetic_friction = {1}\n"
      "rolling_friction = {2}\n"
      "rolling_model = \"{3}\"\n"
      "[pluviation]\n"
      "count = 1000\n"
      "[element]\n",
      name, mu, mu_r, mu_r > 0.0 ? "constant_torque" : "none");
}

}  // namespace trapdem
