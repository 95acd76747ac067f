// Partial-correlation kernel: GCC vector extensions (8 doubles per vector,
// lowered to AVX-512, AVX2 or SSE2 by the target clone) across lags.
//
// Operation count per lag and sample, exponential form: 7 products, 4 mean
// and 10 moment updates (2 each), 10 covariance entries, 2 × 19 for the two
// partial correlations, 6 for the ratios and 6 for the running maximum:
// about 95 floating-point operations, 40 of them fused multiply-adds.
#include "core/detector/PartialCorrelationKernel.h"

#include <cmath>

// Built with -O3 -ffp-contract=fast (see core/CMakeLists.txt) so a*b + c
// becomes one fused multiply-add where the CPU has it.
#define TACTISCOPE_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

// Every helper is forced inline: each clone must get its own copy compiled
// for its instruction set, never a call into the baseline version.
#define TACTISCOPE_INLINE [[gnu::always_inline]] inline

namespace tactiscope::core::detector {
namespace {

using Vec = double __attribute__((vector_size(kLaneWidth * sizeof(double))));
using Mask = long long __attribute__((vector_size(kLaneWidth * sizeof(long long))));
// The same vector at 8-byte alignment, for loads and stores anywhere in a
// double array. GCC gives vector types their element's alias set, so these
// accesses keep type-based alias analysis intact (memcpy would not).
using UnalignedVec = double __attribute__((vector_size(kLaneWidth * sizeof(double)), aligned(alignof(double))));

TACTISCOPE_INLINE Vec load(const double* p)
{
    return *reinterpret_cast<const UnalignedVec*>(p);
}

TACTISCOPE_INLINE void store(double* p, Vec v)
{
    *reinterpret_cast<UnalignedVec*>(p) = v;
}

TACTISCOPE_INLINE Vec splat(double x)
{
    return Vec{} + x;
}

TACTISCOPE_INLINE Vec absolute(Vec v)
{
    return v < 0.0 ? -v : v;
}

// Covariance matrix entries v_jk of u = [a, b, a(t−k), b(t−k)] for 8 lags.
struct Covariance {
    Vec v00, v01, v02, v03, v11, v12, v13, v22, v23, v33;
};

struct Ratios {
    Vec numAb, denAb, numBa, denBa;
};

// Partial correlations through Schur complements: for R_ab, the covariance
// of (b, a(t−k)) given Z = (a, b(t−k)) is Σ_XX − Σ_XZ Σ_ZZ⁻¹ Σ_ZX; scaled by
// det Σ_ZZ > 0 it needs no division, and the scale cancels in R. This equals
// −U₂₃/√(U₂₂U₃₃) of eq. 4 with U = V⁻¹; R_ba likewise with X = (a, b(t−k)).
TACTISCOPE_INLINE Ratios partialCorrelations(const Covariance& c)
{
    const Vec dz = c.v00 * c.v33 - c.v03 * c.v03;
    const Vec w1a = c.v33 * c.v01 - c.v03 * c.v13;
    const Vec w1b = c.v00 * c.v13 - c.v03 * c.v01;
    const Vec w2a = c.v33 * c.v02 - c.v03 * c.v23;
    const Vec w2b = c.v00 * c.v23 - c.v03 * c.v02;
    const Vec m11 = dz * c.v11 - (c.v01 * w1a + c.v13 * w1b);
    const Vec m22 = dz * c.v22 - (c.v02 * w2a + c.v23 * w2b);
    const Vec m12 = dz * c.v12 - (c.v01 * w2a + c.v13 * w2b);

    const Vec dy = c.v11 * c.v22 - c.v12 * c.v12;
    const Vec y0a = c.v22 * c.v01 - c.v12 * c.v02;
    const Vec y0b = c.v11 * c.v02 - c.v12 * c.v01;
    const Vec y3a = c.v22 * c.v13 - c.v12 * c.v23;
    const Vec y3b = c.v11 * c.v23 - c.v12 * c.v13;
    const Vec n00 = dy * c.v00 - (c.v01 * y0a + c.v02 * y0b);
    const Vec n33 = dy * c.v33 - (c.v13 * y3a + c.v23 * y3b);
    const Vec n03 = dy * c.v03 - (c.v01 * y3a + c.v02 * y3b);
    return {m12 * absolute(m12), m11 * m22, n03 * absolute(n03), n00 * n33};
}

// Covariance of lag group g from the stored moments. Exponential form:
// V = S − ūūᵀ. Sliding form over h samples (sums Σu, Σuuᵀ): h²·V + h²ε²I
// = h·Σuuᵀ − Σu Σuᵀ + h²ε²I, a positive multiple of the windowed V.
TACTISCOPE_INLINE Covariance covariance(const LagMoments& s, std::size_t g, std::uint32_t window, double epsilonSquared)
{
    const Vec m0 = load(&s.mean[0][g]);
    const Vec m1 = load(&s.mean[1][g]);
    const Vec m2 = load(&s.mean[2][g]);
    const Vec m3 = load(&s.mean[3][g]);
    const auto& S = s.moment;
    if (window == 0) {
        return {load(&S[S00][g]) - m0 * m0, load(&S[S01][g]) - m0 * m1, load(&S[S02][g]) - m0 * m2,
                load(&S[S03][g]) - m0 * m3, load(&S[S11][g]) - m1 * m1, load(&S[S12][g]) - m1 * m2,
                load(&S[S13][g]) - m1 * m3, load(&S[S22][g]) - m2 * m2, load(&S[S23][g]) - m2 * m3,
                load(&S[S33][g]) - m3 * m3};
    }
    const double h = window;
    const Vec ridge = load(&s.weight[g]) * (h * h * epsilonSquared);
    return {h * load(&S[S00][g]) - m0 * m0 + ridge, h * load(&S[S01][g]) - m0 * m1,
            h * load(&S[S02][g]) - m0 * m2,         h * load(&S[S03][g]) - m0 * m3,
            h * load(&S[S11][g]) - m1 * m1 + ridge, h * load(&S[S12][g]) - m1 * m2,
            h * load(&S[S13][g]) - m1 * m3,         h * load(&S[S22][g]) - m2 * m2 + ridge,
            h * load(&S[S23][g]) - m2 * m3,         h * load(&S[S33][g]) - m3 * m3 + ridge};
}

// Per-lane running maximum of num/den, by cross-multiplication (den > 0).
struct RunningMaximum {
    Vec num = splat(-2.0);  // below any partial correlation's −1
    Vec den = splat(1.0);
    Mask index = Mask{} - 1;

    TACTISCOPE_INLINE void offer(Vec candidateNum, Vec candidateDen, Mask candidateIndex)
    {
        const Mask better = candidateNum * den > num * candidateDen;
        num = better ? candidateNum : num;
        den = better ? candidateDen : den;
        index = better ? candidateIndex : index;
    }

    // The best lane; on a tie the smaller lag index wins.
    TACTISCOPE_INLINE LagMaximum reduce() const
    {
        LagMaximum best{num[0], den[0], static_cast<std::int32_t>(index[0])};
        for (std::size_t lane = 1; lane < kLaneWidth; ++lane) {
            const double lhs = num[lane] * best.den;
            const double rhs = best.num * den[lane];
            if (lhs > rhs || (lhs == rhs && index[lane] >= 0 && index[lane] < best.lagIndex)) {
                best = {num[lane], den[lane], static_cast<std::int32_t>(index[lane])};
            }
        }
        return best;
    }
};

constexpr Mask kFirstLanes = {0, 1, 2, 3, 4, 5, 6, 7};
static_assert(kLaneWidth == 8, "kFirstLanes lists one index per lane");

// One moment update for all lags of group g: s += w·(p − s) for the
// exponential form, s += w·(p − p_leaving) for sliding sums.
TACTISCOPE_INLINE void updateExponential(double* s, Vec w, Vec p)
{
    const Vec old = load(s);
    store(s, old + w * (p - old));
}

TACTISCOPE_INLINE void updateSliding(double* s, Vec w, Vec entering, Vec leaving)
{
    store(s, load(s) + w * (entering - leaving));
}

}  // namespace

TACTISCOPE_KERNEL_CLONES
void runPartialCorrelationKernel(const KernelInput& in, LagMoments& s, SampleMaxima* out)
{
    const std::size_t lanes = s.paddedCount;
    const std::uint32_t* lag = s.lag.data();
    const double eps2 = in.epsilonSquared;
    auto& S = s.moment;
    for (std::size_t j = 0; j < in.count; ++j) {
        const double* a = in.a + j;
        const double* b = in.b + j;
        for (std::size_t i = 0; i < lanes; ++i) {
            in.delayedA[i] = a[-static_cast<std::ptrdiff_t>(lag[i])];
            in.delayedB[i] = b[-static_cast<std::ptrdiff_t>(lag[i])];
        }
        const Vec x0 = splat(a[0]);
        const Vec x1 = splat(b[0]);
        RunningMaximum bestAb;
        RunningMaximum bestBa;
        Mask index = kFirstLanes;  // lag index of each lane in the current group

        if (in.window == 0) {
            const Vec x00 = splat(a[0] * a[0] + eps2);
            const Vec x01 = splat(a[0] * b[0]);
            const Vec x11 = splat(b[0] * b[0] + eps2);
            for (std::size_t g = 0; g < lanes; g += kLaneWidth) {
                const Vec w = load(&s.weight[g]);
                const Vec x2 = load(&in.delayedA[g]);
                const Vec x3 = load(&in.delayedB[g]);
                updateExponential(&s.mean[0][g], w, x0);
                updateExponential(&s.mean[1][g], w, x1);
                updateExponential(&s.mean[2][g], w, x2);
                updateExponential(&s.mean[3][g], w, x3);
                updateExponential(&S[S00][g], w, x00);
                updateExponential(&S[S01][g], w, x01);
                updateExponential(&S[S02][g], w, x0 * x2);
                updateExponential(&S[S03][g], w, x0 * x3);
                updateExponential(&S[S11][g], w, x11);
                updateExponential(&S[S12][g], w, x1 * x2);
                updateExponential(&S[S13][g], w, x1 * x3);
                updateExponential(&S[S22][g], w, x2 * x2 + eps2);
                updateExponential(&S[S23][g], w, x2 * x3);
                updateExponential(&S[S33][g], w, x3 * x3 + eps2);
                const Ratios r = partialCorrelations(covariance(s, g, 0, eps2));
                bestAb.offer(r.numAb, r.denAb, index);
                bestBa.offer(r.numBa, r.denBa, index);
                index += static_cast<long long>(kLaneWidth);
            }
        } else {
            const double* ao = a - in.window;
            const double* bo = b - in.window;
            for (std::size_t i = 0; i < lanes; ++i) {
                in.leavingA[i] = ao[-static_cast<std::ptrdiff_t>(lag[i])];
                in.leavingB[i] = bo[-static_cast<std::ptrdiff_t>(lag[i])];
            }
            const Vec y0 = splat(ao[0]);
            const Vec y1 = splat(bo[0]);
            for (std::size_t g = 0; g < lanes; g += kLaneWidth) {
                const Vec w = load(&s.weight[g]);
                const Vec x2 = load(&in.delayedA[g]);
                const Vec x3 = load(&in.delayedB[g]);
                const Vec y2 = load(&in.leavingA[g]);
                const Vec y3 = load(&in.leavingB[g]);
                updateSliding(&s.mean[0][g], w, x0, y0);
                updateSliding(&s.mean[1][g], w, x1, y1);
                updateSliding(&s.mean[2][g], w, x2, y2);
                updateSliding(&s.mean[3][g], w, x3, y3);
                updateSliding(&S[S00][g], w, x0 * x0, y0 * y0);
                updateSliding(&S[S01][g], w, x0 * x1, y0 * y1);
                updateSliding(&S[S02][g], w, x0 * x2, y0 * y2);
                updateSliding(&S[S03][g], w, x0 * x3, y0 * y3);
                updateSliding(&S[S11][g], w, x1 * x1, y1 * y1);
                updateSliding(&S[S12][g], w, x1 * x2, y1 * y2);
                updateSliding(&S[S13][g], w, x1 * x3, y1 * y3);
                updateSliding(&S[S22][g], w, x2 * x2, y2 * y2);
                updateSliding(&S[S23][g], w, x2 * x3, y2 * y3);
                updateSliding(&S[S33][g], w, x3 * x3, y3 * y3);
                const Ratios r = partialCorrelations(covariance(s, g, in.window, eps2));
                bestAb.offer(r.numAb, r.denAb, index);
                bestBa.offer(r.numBa, r.denBa, index);
                index += static_cast<long long>(kLaneWidth);
            }
        }
        out[j] = {bestAb.reduce(), bestBa.reduce()};
    }
}

void correlationsFromMoments(const LagMoments& s, std::uint32_t window, double epsilonSquared, double* rab, double* rba)
{
    const auto ratio = [](double num, double den) {
        return den > 0.0 ? std::copysign(std::sqrt(std::abs(num) / den), num) : 0.0;
    };
    for (std::size_t g = 0; g < s.paddedCount; g += kLaneWidth) {
        const Ratios r = partialCorrelations(covariance(s, g, window, epsilonSquared));
        for (std::size_t lane = 0; lane < kLaneWidth && g + lane < s.lagCount; ++lane) {
            rab[g + lane] = ratio(r.numAb[lane], r.denAb[lane]);
            rba[g + lane] = ratio(r.numBa[lane], r.denBa[lane]);
        }
    }
}

}  // namespace tactiscope::core::detector
