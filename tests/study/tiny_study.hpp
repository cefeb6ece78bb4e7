// The study texts the study and Slurm tests share: the tiny preset shortened so that a case takes a
// few seconds (a shallow pour, a short settling, 3 mm of travel), two cases that differ in sliding
// friction, and the element test shrunk to 200 spheres sheared to 5 % (about ten seconds a case on
// one thread) at tiny's mid-depth stress, ~10 kPa.
#pragma once

#include <string>

namespace trapdem::test {

// The scale `test` on the tiny preset with a shallow pour and a short settling; its `set` table is
// left open for more keys.
inline std::string tiny_scale(const std::string& description) {
  return "[scales.test]\n"
         "description = \"" + description + "\"\n"
         "preset = \"tiny\"\n"
         "[scales.test.set]\n"
         "pluviation.fill_height = 0.02\n"
         "settling.max_time = 0.04\n";
}

// Keys for the scale's `set`: 3 mm of travel with a snapshot every millimetre.
inline const std::string three_mm_of_travel =
    "trapdoor.travel = 0.003\n"
    "output.snapshot_displacements = [0.0, 0.001, 0.002, 0.003]\n";

// Keys for [report]: the element test of every case, shrunk. (The studies that use it set
// contact.restitution = 0.9, from when tiny's 0.5 left the dense specimen moving at its step limit;
// the servo settles it since its gain includes the dashpot: tests/experiment/element_command_test.cpp.)
inline const std::string small_element_test =
    "element_test = true\n"
    "[report.element]\n"
    "particles = 200\n"
    "confining = [1.0e4]\n"
    "max_axial_strain = 0.05\n"
    "critical_state_window = 0.02\n"
    "row_strain = 0.005\n";

// Two cases: smooth (mu 0.2) and rough (mu 0.6) grains.
inline const std::string smooth_and_rough_cases = R"([cases.smooth]
label = "Smooth"
[cases.smooth.set.contact]
static_friction = 0.2
kinetic_friction = 0.2
[cases.rough]
label = "Rough"
[cases.rough.set.contact]
static_friction = 0.6
kinetic_friction = 0.6
)";

}  // namespace trapdem::test
