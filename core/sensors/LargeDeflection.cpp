// LargeDeflection: the elastica by shooting, and the force of a given
// model error by bisection.
#include "core/sensors/LargeDeflection.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::sensors {
namespace {

constexpr int kSteps = 2000;  // along the arc: the midpoint rule's error is far below the errors asked
constexpr int kShootingRounds = 200;

struct Shape {
    double x_m = 0.0;
    double y_m = 0.0;
};

// The beam's shape for a guess of the tip's x: its tip.
Shape integrate(const BendingStiffness& stiffness, double length_m, double force_n, double tipX_m)
{
    const double ds = length_m / kSteps;
    double theta = 0.0, x = 0.0, y = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double s = (i + 0.5) * ds;
        // Half a step on x to the midpoint, so the moment arm is the midpoint's.
        const double xMid = x + 0.5 * ds * std::cos(theta);
        const double thetaMid = theta + 0.5 * ds * force_n * (tipX_m - xMid) / stiffness(s);
        theta += ds * force_n * (tipX_m - xMid) / stiffness(s);
        x += ds * std::cos(thetaMid);
        y += ds * std::sin(thetaMid);
    }
    return {x, y};
}

}  // namespace

TipDeflection tipDeflection(const BendingStiffness& stiffness, double length_m, double force_n)
{
    if (!(std::isfinite(length_m) && length_m > 0.0) || !(std::isfinite(force_n) && force_n > 0.0))
        throw std::invalid_argument("tip deflection: the length and the force must be positive");
    TipDeflection result;
    const double ds = length_m / kSteps;
    double theta = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double s = (i + 0.5) * ds;
        const double slope = theta + 0.5 * ds * force_n * (length_m - s) / stiffness(s);
        theta += ds * force_n * (length_m - s) / stiffness(s);
        result.linear_m += ds * slope;
    }
    // The tip's x: the shape's own, found again from each shape (it
    // converges for any deflection the linear model is anywhere near).
    double tipX = length_m;
    Shape shape;
    for (int round = 0; round < kShootingRounds; ++round) {
        shape = integrate(stiffness, length_m, force_n, tipX);
        if (std::abs(shape.x_m - tipX) < 1e-12 * length_m) break;
        tipX = shape.x_m;
    }
    result.exact_m = shape.y_m;
    return result;
}

BendingStiffness bendingStiffness(const CapacitiveBeam& beam)
{
    const auto& b = beam.geometry().beam;
    const double a1 = beam.segment1().bendingStiffnessPerWidth_n_m;
    const double a2 = beam.segment2().bendingStiffnessPerWidth_n_m;
    return [=](double s) {
        return s < b.sheetLengthRatio * b.length_m ? a1 * b.rootWidth_m * (b.length_m - s) / b.length_m
                                                   : a2 * (1.0 - b.sheetLengthRatio) * b.rootWidth_m;
    };
}

double forceAtModelError(const BendingStiffness& stiffness, double length_m, double error)
{
    if (!(error > 0.0 && error < 0.5)) throw std::invalid_argument("model error: between 0 and 0.5");
    // The linear deflection per newton sets the scale: search from a
    // hundredth to half the length's worth of linear deflection.
    const double perNewton_m = tipDeflection(stiffness, length_m, 1.0).linear_m;
    double low = 0.01 * length_m / perNewton_m, high = 0.5 * length_m / perNewton_m;
    for (int i = 0; i < 40; ++i) {
        const double middle = 0.5 * (low + high);
        (tipDeflection(stiffness, length_m, middle).modelError() < error ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

}  // namespace tactiscope::core::sensors
