// Partial-correlation kernel: GCC vector extensions (8 doubles per vector,
// lowered to AVX-512, AVX2 or SSE2 by the target clone) across lags.
//
// Loop order: samples are taken in blocks of kBlock; within a block each group
// of 8 lags runs through all the block's samples with its 14 state vectors in
// registers, writing the ratios of R_ab and R_ba; a second pass takes the
// maximum over groups per sample. Delayed samples come from a reversed copy
// of the block's history, so a group's 8 delayed values are one load when the
// lags are contiguous (the paper's 2…150 ms at 2 ms are).
//
// Exponential form in Welford style. With w = 1 − r and d = u − ū(t−Δt),
// eqs 8–10 give ū ← ū + w·d and V ← r·V + w·r·d·dᵀ + w·ε²·I exactly. The
// state keeps V̂ = V/(w·r), so V̂ ← r·V̂ + d·dᵀ + (ε²/r)·I: two operations per
// entry and no S − ūūᵀ. R is the same for any positive multiple of V.
//
// Floating-point operations per lag and sample on the multiply/FMA pipes
// (exponential form): mean 4, covariance 20, partial correlations 2 × 19,
// ratios 4, maximum 4: 70, plus 4 subtractions and a few blends.
#include "core/detector/PartialCorrelationKernel.h"

#include <algorithm>
#include <cmath>

// Built with -O3 -ffp-contract=fast (see core/CMakeLists.txt) so a*b + c
// becomes one fused multiply-add where the CPU has it.
#define TACTISCOPE_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
// Every helper is forced inline: each clone must get its own copy compiled
// for its instruction set, never a call into the baseline version.
#define TACTISCOPE_INLINE [[gnu::always_inline]] inline

namespace tactiscope::core::detector {
namespace {

// Samples per block: long enough to amortise loading a group's state, short
// enough that the block's ratios (kBlock × lags × 4 doubles) stay in L1.
constexpr std::size_t kBlock = 16;

using Vec = double __attribute__((vector_size(kLaneWidth * sizeof(double))));
using Mask = long long __attribute__((vector_size(kLaneWidth * sizeof(long long))));
// The same vector at 8-byte alignment, for loads and stores anywhere in a
// double array. GCC gives vector types their element's alias set, so these
// accesses keep type-based alias analysis intact (memcpy would not).
using UnalignedVec = double __attribute__((vector_size(kLaneWidth * sizeof(double)), aligned(alignof(double))));

constexpr Mask kFirstLanes = {0, 1, 2, 3, 4, 5, 6, 7};
static_assert(kLaneWidth == 8, "kFirstLanes lists one index per lane");

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

// |v| by clearing the sign bit: one AND, no compare into a mask register.
TACTISCOPE_INLINE Vec absolute(Vec v)
{
    return reinterpret_cast<Vec>(reinterpret_cast<Mask>(v) & (Mask{} + 0x7fffffffffffffffLL));
}

// Covariance matrix entries v_jk of u = [a, b, a(t−k), b(t−k)] for 8 lags,
// up to a positive factor per lane.
struct Covariance {
    Vec v00, v01, v02, v03, v11, v12, v13, v22, v23, v33;
};

// Partial correlations through Schur complements: for R_ab, the covariance
// of (b, a(t−k)) given Z = (a, b(t−k)) is Σ_XX − Σ_XZ Σ_ZZ⁻¹ Σ_ZX; scaled by
// det Σ_ZZ > 0 it needs no division, and the scale cancels in R. This equals
// −U₂₃/√(U₂₂U₃₃) of eq. 4 with U = V⁻¹; R_ba likewise with X = (a, b(t−k)).
// Each R is returned as num = sign(R)·c², den = c_xx·c_yy: R² = |num|/den.
struct Ratios {
    Vec numAb, denAb, numBa, denBa;
};

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

// Per sample, the per-lane best ratio num/den seen so far and its lag index.
// Ratios compare by cross-multiplication (den > 0): no division.
struct SampleBest {
    double numAb[kLaneWidth], denAb[kLaneWidth], numBa[kLaneWidth], denBa[kLaneWidth];
    long long indexAb[kLaneWidth], indexBa[kLaneWidth];
};

TACTISCOPE_INLINE void startBest(SampleBest& best)
{
    store(best.numAb, splat(-2.0));  // below any partial correlation's −1
    store(best.numBa, splat(-2.0));
    store(best.denAb, splat(1.0));
    store(best.denBa, splat(1.0));
    std::fill(std::begin(best.indexAb), std::end(best.indexAb), -1);
    std::fill(std::begin(best.indexBa), std::end(best.indexBa), -1);
}

TACTISCOPE_INLINE Mask loadMask(const long long* p)
{
    return reinterpret_cast<Mask>(load(reinterpret_cast<const double*>(p)));
}

TACTISCOPE_INLINE void offer(double* num, double* den, long long* index, Vec candidateNum, Vec candidateDen,
                             Mask candidateIndex)
{
    const Vec bestNum = load(num);
    const Vec bestDen = load(den);
    const Mask better = candidateNum * bestDen > bestNum * candidateDen;
    store(num, better ? candidateNum : bestNum);
    store(den, better ? candidateDen : bestDen);
    store(reinterpret_cast<double*>(index), reinterpret_cast<Vec>(better ? candidateIndex : loadMask(index)));
}

// The best of the 8 lanes: one division turns each lane's ratio into
// sign(R)·R², a shuffle tree finds the largest, and on a tie the smaller lag
// index wins.
TACTISCOPE_INLINE LagMaximum reduceBest(const double* num, const double* den, const long long* index)
{
    const Vec n = load(num);
    const Vec d = load(den);
    const Vec q = n / d;
    Vec m = q;
    m = m > __builtin_shuffle(m, Mask{4, 5, 6, 7, 0, 1, 2, 3}) ? m : __builtin_shuffle(m, Mask{4, 5, 6, 7, 0, 1, 2, 3});
    m = m > __builtin_shuffle(m, Mask{2, 3, 0, 1, 6, 7, 4, 5}) ? m : __builtin_shuffle(m, Mask{2, 3, 0, 1, 6, 7, 4, 5});
    m = m > __builtin_shuffle(m, Mask{1, 0, 3, 2, 5, 4, 7, 6}) ? m : __builtin_shuffle(m, Mask{1, 0, 3, 2, 5, 4, 7, 6});
    std::size_t bestLane = kLaneWidth;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) {
        if (q[lane] == m[0] && (bestLane == kLaneWidth || index[lane] < index[bestLane])) bestLane = lane;
    }
    return {num[bestLane], den[bestLane], static_cast<std::int32_t>(index[bestLane])};
}

// Offers one group's ratios for one sample. In the group that holds padding
// lanes (weight 0) those become 0/0, which the strict comparison never prefers.
template <bool HasPadding>
TACTISCOPE_INLINE void offerGroup(SampleBest& best, Ratios r, Mask index, Mask padding)
{
    if constexpr (HasPadding) {
        r.numAb = padding ? Vec{} : r.numAb;
        r.denAb = padding ? Vec{} : r.denAb;
        r.numBa = padding ? Vec{} : r.numBa;
        r.denBa = padding ? Vec{} : r.denBa;
    }
    offer(best.numAb, best.denAb, best.indexAb, r.numAb, r.denAb, index);
    offer(best.numBa, best.denBa, best.indexBa, r.numBa, r.denBa, index);
}

// The 8 samples x(t − k) of lanes g … g+7 for the sample at `origin` of a
// reversed series (reversed[origin + k] = x(t − k)).
TACTISCOPE_INLINE Vec delayed(const double* reversed, std::size_t origin, const std::uint32_t* lag, bool contiguous)
{
    if (contiguous) return load(reversed + origin + lag[0]);
    Vec v;
    for (std::size_t lane = 0; lane < kLaneWidth; ++lane) v[lane] = reversed[origin + lag[lane]];
    return v;
}

// Scratch layout: reversed a, reversed b, then the block's per-sample best.
struct Scratch {
    std::size_t reversedLength;
    double* reversedA;
    double* reversedB;
    SampleBest* best;  // one per sample of the block

    Scratch(double* base, const LagMoments& s, std::uint32_t window)
        : reversedLength(kBlock + s.largestLaneLag() + window + 1),
          reversedA(base),
          reversedB(base + reversedLength),
          best(reinterpret_cast<SampleBest*>(base + 2 * reversedLength))
    {
    }
};

static_assert(sizeof(SampleBest) % sizeof(double) == 0 && alignof(SampleBest) <= alignof(double));

// Exponential form for one group of lags over the block's n samples.
template <bool HasPadding>
TACTISCOPE_INLINE void exponentialGroup(LagMoments& s, std::size_t g, const Scratch& scratch, std::size_t n,
                                        double epsilonSquared, Mask index, Mask padding)
{
    const Vec w = load(&s.weight[g]);
    const Vec r = load(&s.forgetting[g]);
    const Vec ridge = epsilonSquared / r;
    Vec m0 = load(&s.mean[0][g]), m1 = load(&s.mean[1][g]), m2 = load(&s.mean[2][g]), m3 = load(&s.mean[3][g]);
    auto& S = s.moment;
    Covariance c{load(&S[S00][g]), load(&S[S01][g]), load(&S[S02][g]), load(&S[S03][g]), load(&S[S11][g]),
                 load(&S[S12][g]), load(&S[S13][g]), load(&S[S22][g]), load(&S[S23][g]), load(&S[S33][g])};
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t origin = n - 1 - j;
        const Vec d0 = scratch.reversedA[origin] - m0;
        const Vec d1 = scratch.reversedB[origin] - m1;
        const Vec d2 = delayed(scratch.reversedA, origin, &s.lag[g], s.contiguous) - m2;
        const Vec d3 = delayed(scratch.reversedB, origin, &s.lag[g], s.contiguous) - m3;
        m0 += w * d0;
        m1 += w * d1;
        m2 += w * d2;
        m3 += w * d3;
        c.v00 = r * c.v00 + (d0 * d0 + ridge);
        c.v01 = r * c.v01 + d0 * d1;
        c.v02 = r * c.v02 + d0 * d2;
        c.v03 = r * c.v03 + d0 * d3;
        c.v11 = r * c.v11 + (d1 * d1 + ridge);
        c.v12 = r * c.v12 + d1 * d2;
        c.v13 = r * c.v13 + d1 * d3;
        c.v22 = r * c.v22 + (d2 * d2 + ridge);
        c.v23 = r * c.v23 + d2 * d3;
        c.v33 = r * c.v33 + (d3 * d3 + ridge);
        offerGroup<HasPadding>(scratch.best[j], partialCorrelations(c), index, padding);
    }
    store(&s.mean[0][g], m0);
    store(&s.mean[1][g], m1);
    store(&s.mean[2][g], m2);
    store(&s.mean[3][g], m3);
    store(&S[S00][g], c.v00);
    store(&S[S01][g], c.v01);
    store(&S[S02][g], c.v02);
    store(&S[S03][g], c.v03);
    store(&S[S11][g], c.v11);
    store(&S[S12][g], c.v12);
    store(&S[S13][g], c.v13);
    store(&S[S22][g], c.v22);
    store(&S[S23][g], c.v23);
    store(&S[S33][g], c.v33);
}

// Sliding-window form for one group: window sums of u and uuᵀ, then
// h²·V = h·Σuuᵀ − Σu·Σuᵀ (+ h²ε²·I), a positive multiple of the window's V.
template <bool HasPadding>
TACTISCOPE_INLINE void slidingGroup(LagMoments& s, std::size_t g, const Scratch& scratch, std::size_t n,
                                    std::uint32_t window, double epsilonSquared, Mask index, Mask padding)
{
    const Vec w = load(&s.weight[g]);
    const double h = window;
    const Vec ridge = w * (h * h * epsilonSquared);
    Vec m[4] = {load(&s.mean[0][g]), load(&s.mean[1][g]), load(&s.mean[2][g]), load(&s.mean[3][g])};
    Vec q[kMomentCount];
    for (std::size_t i = 0; i < kMomentCount; ++i) q[i] = load(&s.moment[i][g]);
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t origin = n - 1 - j;
        const std::size_t leaving = origin + window;
        const Vec x0 = w * scratch.reversedA[origin];
        const Vec x1 = w * scratch.reversedB[origin];
        const Vec x2 = w * delayed(scratch.reversedA, origin, &s.lag[g], s.contiguous);
        const Vec x3 = w * delayed(scratch.reversedB, origin, &s.lag[g], s.contiguous);
        const Vec y0 = w * scratch.reversedA[leaving];
        const Vec y1 = w * scratch.reversedB[leaving];
        const Vec y2 = w * delayed(scratch.reversedA, leaving, &s.lag[g], s.contiguous);
        const Vec y3 = w * delayed(scratch.reversedB, leaving, &s.lag[g], s.contiguous);
        m[0] += x0 - y0;
        m[1] += x1 - y1;
        m[2] += x2 - y2;
        m[3] += x3 - y3;
        q[S00] += x0 * x0 - y0 * y0;
        q[S01] += x0 * x1 - y0 * y1;
        q[S02] += x0 * x2 - y0 * y2;
        q[S03] += x0 * x3 - y0 * y3;
        q[S11] += x1 * x1 - y1 * y1;
        q[S12] += x1 * x2 - y1 * y2;
        q[S13] += x1 * x3 - y1 * y3;
        q[S22] += x2 * x2 - y2 * y2;
        q[S23] += x2 * x3 - y2 * y3;
        q[S33] += x3 * x3 - y3 * y3;
        const Covariance c{h * q[S00] - m[0] * m[0] + ridge, h * q[S01] - m[0] * m[1],         h * q[S02] - m[0] * m[2],
                           h * q[S03] - m[0] * m[3],         h * q[S11] - m[1] * m[1] + ridge, h * q[S12] - m[1] * m[2],
                           h * q[S13] - m[1] * m[3],         h * q[S22] - m[2] * m[2] + ridge, h * q[S23] - m[2] * m[3],
                           h * q[S33] - m[3] * m[3] + ridge};
        offerGroup<HasPadding>(scratch.best[j], partialCorrelations(c), index, padding);
    }
    for (std::size_t i = 0; i < 4; ++i) store(&s.mean[i][g], m[i]);
    for (std::size_t i = 0; i < kMomentCount; ++i) store(&s.moment[i][g], q[i]);
}

}  // namespace

std::size_t kernelScratchSize(const LagMoments& moments, std::uint32_t window)
{
    const std::size_t reversedLength = kBlock + moments.largestLaneLag() + window + 1;
    return 2 * reversedLength + kBlock * sizeof(SampleBest) / sizeof(double);
}

TACTISCOPE_KERNEL_CLONES
void runPartialCorrelationKernel(const KernelInput& in, LagMoments& s, SampleMaxima* out)
{
    const Scratch scratch(in.scratch, s, in.window);
    const std::size_t P = s.paddedCount;
    for (std::size_t j0 = 0; j0 < in.count; j0 += kBlock) {
        const std::size_t n = std::min(kBlock, in.count - j0);
        // reversed[q] = x(j0 + n − 1 − q): sample j of the block, delayed by
        // k, is reversed[n − 1 − j + k].
        const std::size_t span = n + s.largestLaneLag() + in.window;
        const double* lastA = in.a + j0 + n - 1;
        const double* lastB = in.b + j0 + n - 1;
        for (std::size_t q = 0; q < span; ++q) {
            scratch.reversedA[q] = lastA[-static_cast<std::ptrdiff_t>(q)];
            scratch.reversedB[q] = lastB[-static_cast<std::ptrdiff_t>(q)];
        }
        for (std::size_t j = 0; j < n; ++j) startBest(scratch.best[j]);
        Mask index = kFirstLanes;  // lag index of each lane of the group
        for (std::size_t g = 0; g < P; g += kLaneWidth, index += static_cast<long long>(kLaneWidth)) {
            const Mask padding = load(&s.weight[g]) == 0.0;
            const bool hasPadding = g + kLaneWidth > s.lagCount;
            if (in.window == 0) {
                if (hasPadding)
                    exponentialGroup<true>(s, g, scratch, n, in.epsilonSquared, index, padding);
                else
                    exponentialGroup<false>(s, g, scratch, n, in.epsilonSquared, index, padding);
            } else {
                if (hasPadding)
                    slidingGroup<true>(s, g, scratch, n, in.window, in.epsilonSquared, index, padding);
                else
                    slidingGroup<false>(s, g, scratch, n, in.window, in.epsilonSquared, index, padding);
            }
        }
        for (std::size_t j = 0; j < n; ++j) {
            const SampleBest& best = scratch.best[j];
            out[j0 + j] = {reduceBest(best.numAb, best.denAb, best.indexAb),
                           reduceBest(best.numBa, best.denBa, best.indexBa)};
        }
    }
}

void correlationsFromMoments(const LagMoments& s, std::uint32_t window, double epsilonSquared, double* rab, double* rba)
{
    const auto correlation = [](double num, double den) {
        return den > 0.0 ? std::copysign(std::sqrt(std::abs(num) / den), num) : 0.0;
    };
    for (std::size_t g = 0; g < s.paddedCount; g += kLaneWidth) {
        Covariance c;
        const auto& S = s.moment;
        if (window == 0) {
            c = {load(&S[S00][g]), load(&S[S01][g]), load(&S[S02][g]), load(&S[S03][g]), load(&S[S11][g]),
                 load(&S[S12][g]), load(&S[S13][g]), load(&S[S22][g]), load(&S[S23][g]), load(&S[S33][g])};
        } else {
            const double h = window;
            const Vec ridge = load(&s.weight[g]) * (h * h * epsilonSquared);
            Vec m[4];
            for (std::size_t i = 0; i < 4; ++i) m[i] = load(&s.mean[i][g]);
            const auto entry = [&](std::size_t index, std::size_t j, std::size_t k) {
                return h * load(&S[index][g]) - m[j] * m[k] + (j == k ? ridge : Vec{});
            };
            c = {entry(S00, 0, 0), entry(S01, 0, 1), entry(S02, 0, 2), entry(S03, 0, 3), entry(S11, 1, 1),
                 entry(S12, 1, 2), entry(S13, 1, 3), entry(S22, 2, 2), entry(S23, 2, 3), entry(S33, 3, 3)};
        }
        const Ratios r = partialCorrelations(c);
        for (std::size_t lane = 0; lane < kLaneWidth && g + lane < s.lagCount; ++lane) {
            rab[g + lane] = correlation(r.numAb[lane], r.denAb[lane]);
            rba[g + lane] = correlation(r.numBa[lane], r.denBa[lane]);
        }
    }
}

}  // namespace tactiscope::core::detector
