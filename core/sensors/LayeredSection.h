// Bending of a beam made of bonded layers (composite, "multimorph" beam): the
// neutral axis and the bending stiffness per unit width of a stack of layers
// given bottom to top (z increasing), each with thickness and Young's
// modulus. With h⁽¹⁾ = z_i − z_{i−1}, h⁽²⁾ = (z_i² − z_{i−1}²)/2 and
// h⁽³⁾ = (z_i³ − z_{i−1}³)/3:
//   z_N = Σ E·h⁽²⁾ / Σ E·h⁽¹⁾                                  (seed 002, eq. 6)
//   A   = Σ E·h⁽³⁾ − (Σ E·h⁽²⁾)² / Σ E·h⁽¹⁾   [N·m per m of width]
// The paper's eqs 10 and 15 print the bracket of A wrongly (the squared sum
// divided, not subtracted); the form above is the transformed-section
// result and reduces to E·h³/12 for one layer.
#pragma once

#include <span>

namespace tactiscope::core::sensors {

struct Layer {
    double thickness_m = 0.0;
    double youngsModulus_pa = 0.0;
};

struct SectionProperties {
    double bendingStiffnessPerWidth_n_m = 0.0;  // A
    double neutralAxis_m = 0.0;                 // z_N, from the bottom of the stack
    double height_m = 0.0;                      // total thickness
};

// Throws std::invalid_argument for an empty stack or a non-positive layer.
SectionProperties sectionProperties(std::span<const Layer> bottomToTop);

}  // namespace tactiscope::core::sensors
