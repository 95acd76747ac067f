// The order in which a defect crossed the two cantilevers, as every text
// of the command line and the reports writes it.
#pragma once

namespace tactiscope::core::detector {

// direction > 0: "A then B"; < 0: "B then A"; 0: "no defect".
constexpr const char* defectOrderText(int direction)
{
    return direction > 0 ? "A then B" : direction < 0 ? "B then A" : "no defect";
}

}  // namespace tactiscope::core::detector
