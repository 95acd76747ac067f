// The detector's hot loop: for a run of samples, update the moments of every
// lag and find, per sample, the lag with the largest R_ab and the one with the
// largest R_ba (eqs 4–5). Compiled for three instruction sets (AVX-512,
// AVX2+FMA, baseline x86-64); the best one the CPU supports is used, so one
// portable binary runs everywhere at the speed the machine allows.
//
// Lags are ranked by sign(R)·R², which orders them like R without a square
// root per lag; only each sample's winner gets its square root.
#pragma once

#include "core/detector/LagMoments.h"

#include <cstddef>
#include <cstdint>

namespace tactiscope::core::detector {

// The largest R of one direction over the lags at one sample.
struct LagMaximum {
    double r = 0.0;  // the partial correlation; 0 when no lag is valid
    std::int32_t lagIndex = -1;
};

struct SampleMaxima {
    LagMaximum ab;
    LagMaximum ba;
};

// R from sign(R)·R² (in [−1, 1]); 0 for anything else (a degenerate lag).
double signedRoot(double signedSquare);

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

// The instruction sets the kernel is built for, in increasing order.
enum class KernelVariant { Baseline, Avx2, Avx512 };

// The fastest variant this CPU runs (checked once).
KernelVariant bestKernelVariant();
bool kernelVariantSupported(KernelVariant variant);
const char* toString(KernelVariant variant);

// Advances `moments` by input.count samples and writes one SampleMaxima per
// sample. `variant` must be supported by the CPU. All variants compute the
// same values up to floating-point rounding (fused multiply-adds differ).
void runPartialCorrelationKernel(KernelVariant variant, const KernelInput& input, LagMoments& moments,
                                 SampleMaxima* out);

// R_ab and R_ba of every lag from the current moments (not the hot path:
// for inspection, plots and tests). Outputs have lagCount entries.
void correlationsFromMoments(const LagMoments& moments, std::uint32_t window, double epsilonSquared, double* rab,
                             double* rba);

}  // namespace tactiscope::core::detector
