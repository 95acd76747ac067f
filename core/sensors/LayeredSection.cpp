// Neutral axis and bending stiffness of a layer stack.
#include "core/sensors/LayeredSection.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::sensors {

SectionProperties sectionProperties(std::span<const Layer> layers)
{
    if (layers.empty()) throw std::invalid_argument("a section needs at least one layer");
    double z = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (const Layer& layer : layers) {
        if (!(std::isfinite(layer.thickness_m) && layer.thickness_m > 0.0 && std::isfinite(layer.youngsModulus_pa) &&
              layer.youngsModulus_pa > 0.0))
            throw std::invalid_argument("layers need positive thickness and Young's modulus");
        const double z0 = z, z1 = z + layer.thickness_m;
        const double E = layer.youngsModulus_pa;
        s1 += E * (z1 - z0);
        s2 += E * (z1 * z1 - z0 * z0) / 2.0;
        s3 += E * (z1 * z1 * z1 - z0 * z0 * z0) / 3.0;
        z = z1;
    }
    return {s3 - s2 * s2 / s1, s2 / s1, z};
}

}  // namespace tactiscope::core::sensors
