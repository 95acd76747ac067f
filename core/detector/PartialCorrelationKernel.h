// The detector's hot loop: for a run of samples, update the moments of every
// lag and find, per sample, the lag with the largest R_ab and the one with the
// largest R_ba (eqs 4–5). Compiled for several instruction sets (AVX-512,
// AVX2+FMA, baseline x86-64) and dispatched at run time, so one portable
// binary uses the best the CPU has.
//
// R is returned as a ratio: R² = |num|/den with the sign of num. Comparing
// ratios by cross-multiplication avoids a division and a square root per lag;
// the caller takes one square root per sample for the winner.
#pragma once

#include "core/detector/LagMoments.h"

#include <cstddef>
#include <cstdint>

namespace tactiscope::core::detector {

struct LagMaximum {
    double num = 0.0;  // sign(R)·R²·den
    double den = 0.0;  // > 0 for a valid lag
    std::int32_t lagIndex = -1;
};

struct SampleMaxima {
    LagMaximum ab;
    LagMaximum ba;
};

struct KernelInput {
    // a[j], b[j] is sample j of the run; a[j − k] must be readable for every
    // lane's lag k (LagMoments::largestLaneLag()) plus the window.
    const double* a = nullptr;
    const double* b = nullptr;
    std::size_t count = 0;
    double epsilonSquared = 0.0;
    std::uint32_t window = 0;  // 0: exponential form
    // Working memory of kernelScratchSize() doubles.
    double* scratch = nullptr;
};

std::size_t kernelScratchSize(const LagMoments& moments, std::uint32_t window);

// Advances `moments` by input.count samples and writes one SampleMaxima per sample.
void runPartialCorrelationKernel(const KernelInput& input, LagMoments& moments, SampleMaxima* out);

// R_ab and R_ba of every lag from the current moments (not the hot path:
// for inspection, plots and tests). Outputs have lagCount entries.
void correlationsFromMoments(const LagMoments& moments, std::uint32_t window, double epsilonSquared, double* rab,
                             double* rba);

}  // namespace tactiscope::core::detector
