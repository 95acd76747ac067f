// Partial-correlation kernel: GCC vector extensions across lags, compiled
// three times (AVX-512, AVX2+FMA, baseline SSE2) with group widths 8, 4 and 2.
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
// Every helper is forced inline: each entry point must get its own copy
// compiled for its instruction set, never a call into the baseline version.
#define TACTISCOPE_INLINE [[gnu::always_inline]] inline

namespace tactiscope::core::detector {
namespace {

// Samples per block: long enough to amortise loading a group's state, short
// enough that the block's per-sample maxima stay in L1.
constexpr std::size_t kBlock = 24;

// Vector types of N doubles and their lane masks. The group width follows the
// register file: 8 lanes with AVX-512's 32 registers, 4 with AVX2's 16, 2
// with SSE2; wider groups would spill the 14 state vectors to memory.
template <std::size_t N>
struct Lanes;

template <>
struct Lanes<8> {
    using Vec = double __attribute__((vector_size(8 * sizeof(double))));
    using Mask = long long __attribute__((vector_size(8 * sizeof(long long))));
    // At 8-byte alignment, for loads and stores anywhere in a double array.
    // GCC gives vector types their element's alias set, so these accesses
    // keep type-based alias analysis intact (memcpy would not).
    using Unaligned = double __attribute__((vector_size(8 * sizeof(double)), aligned(alignof(double))));
    static constexpr Mask kFirst = {0, 1, 2, 3, 4, 5, 6, 7};
};

template <>
struct Lanes<4> {
    using Vec = double __attribute__((vector_size(4 * sizeof(double))));
    using Mask = long long __attribute__((vector_size(4 * sizeof(long long))));
    using Unaligned = double __attribute__((vector_size(4 * sizeof(double)), aligned(alignof(double))));
    static constexpr Mask kFirst = {0, 1, 2, 3};
};

template <>
struct Lanes<2> {
    using Vec = double __attribute__((vector_size(2 * sizeof(double))));
    using Mask = long long __attribute__((vector_size(2 * sizeof(long long))));
    using Unaligned = double __attribute__((vector_size(2 * sizeof(double)), aligned(alignof(double))));
    static constexpr Mask kFirst = {0, 1};
};

static_assert(kLaneWidth == 8, "a sample's best values are kept in 8 lanes");

template <std::size_t N>
using Vec = typename Lanes<N>::Vec;
template <std::size_t N>
using Mask = typename Lanes<N>::Mask;

template <std::size_t N>
TACTISCOPE_INLINE Vec<N> load(const double* p)
{
    return *reinterpret_cast<const typename Lanes<N>::Unaligned*>(p);
}

template <std::size_t N>
TACTISCOPE_INLINE void store(double* p, Vec<N> v)
{
    *reinterpret_cast<typename Lanes<N>::Unaligned*>(p) = v;
}

template <std::size_t N>
TACTISCOPE_INLINE Vec<N> splat(double x)
{
    return Vec<N>{} + x;
}

template <std::size_t N>
TACTISCOPE_INLINE Mask<N> loadMask(const long long* p)
{
    return reinterpret_cast<Mask<N>>(load<N>(reinterpret_cast<const double*>(p)));
}

// |v| by clearing the sign bit: one AND, no compare into a mask register.
template <std::size_t N>
TACTISCOPE_INLINE Vec<N> absolute(Vec<N> v)
{
    return reinterpret_cast<Vec<N>>(reinterpret_cast<Mask<N>>(v) & (Mask<N>{} + 0x7fffffffffffffffLL));
}

// Covariance matrix entries v_jk of u = [a, b, a(t−k), b(t−k)] for N lags,
// up to a positive factor per lane.
template <std::size_t N>
struct Covariance {
    Vec<N> v00, v01, v02, v03, v11, v12, v13, v22, v23, v33;
};

// R_ab and R_ba of N lags as ratios: sign(R)·R² = num/den with den > 0.
template <std::size_t N>
struct SignedSquares {
    Vec<N> numAb, denAb, numBa, denBa;
};

// The partial correlation of two variables x, y given two others z, w, as
// the ratio sign(R)·R² = num/den. The covariance of (x, y) given (z, w) is
// the Schur complement Σ_XX − Σ_XZ Σ_ZZ⁻¹ Σ_ZX; scaled by det Σ_ZZ > 0 it
// needs no division, and the scale cancels in R. Arguments: the Z block
// (zz, ww, zw), the cross covariances (xz, xw, yz, yw) and the X block
// (xx, yy, xy).
template <std::size_t N>
TACTISCOPE_INLINE void conditionalCorrelation(Vec<N> zz, Vec<N> ww, Vec<N> zw, Vec<N> xz, Vec<N> xw, Vec<N> yz,
                                              Vec<N> yw, Vec<N> xx, Vec<N> yy, Vec<N> xy, Vec<N>& num, Vec<N>& den)
{
    const Vec<N> det = zz * ww - zw * zw;
    // adj(Σ_ZZ)·(yz, yw) and adj(Σ_ZZ)·(xz, xw)
    const Vec<N> ya = ww * yz - zw * yw;
    const Vec<N> yb = zz * yw - zw * yz;
    const Vec<N> xa = ww * xz - zw * xw;
    const Vec<N> xb = zz * xw - zw * xz;
    const Vec<N> cxx = det * xx - (xz * xa + xw * xb);
    const Vec<N> cyy = det * yy - (yz * ya + yw * yb);
    const Vec<N> cxy = det * xy - (xz * ya + xw * yb);
    num = cxy * absolute<N>(cxy);
    den = cxx * cyy;
}

// R_ab of eq. 4 (b(t) with a(t−k), given a(t) and b(t−k)) and R_ba of eq. 5
// (a(t) with b(t−k), given b(t) and a(t−k)); this equals −U₂₃/√(U₂₂U₃₃) and
// −U₁₄/√(U₁₁U₄₄) with U = V⁻¹. sign(R)·R² = num/den ranks lags like R;
// ratios are compared by cross-multiplication, because a vector division
// would hold a multiply-add pipe for many cycles.
template <std::size_t N>
TACTISCOPE_INLINE SignedSquares<N> partialCorrelations(const Covariance<N>& c)
{
    SignedSquares<N> r;
    conditionalCorrelation<N>(c.v00, c.v33, c.v03, c.v01, c.v13, c.v02, c.v23, c.v11, c.v22, c.v12, r.numAb, r.denAb);
    conditionalCorrelation<N>(c.v11, c.v22, c.v12, c.v01, c.v02, c.v13, c.v23, c.v00, c.v33, c.v03, r.numBa, r.denBa);
    return r;
}

// Per sample, the per-lane best ratio num/den seen so far and its lag index.
struct SampleBest {
    double numAb[kLaneWidth], denAb[kLaneWidth], numBa[kLaneWidth], denBa[kLaneWidth];
    long long indexAb[kLaneWidth], indexBa[kLaneWidth];
};

TACTISCOPE_INLINE void startBest(SampleBest& best)
{
    // −2/1 is below any sign(R)·R² (≥ −1).
    store<8>(best.numAb, splat<8>(-2.0));
    store<8>(best.numBa, splat<8>(-2.0));
    store<8>(best.denAb, splat<8>(1.0));
    store<8>(best.denBa, splat<8>(1.0));
    std::fill(std::begin(best.indexAb), std::end(best.indexAb), -1);
    std::fill(std::begin(best.indexBa), std::end(best.indexBa), -1);
}

// Keeps, in the first N lanes, the larger of the stored and the candidate
// ratio: c/d > b/e ⇔ c·e > b·d for positive denominators. A 0/0 or NaN
// candidate never compares greater.
template <std::size_t N>
TACTISCOPE_INLINE void offer(double* num, double* den, long long* index, Vec<N> candidateNum, Vec<N> candidateDen,
                             Mask<N> candidateIndex)
{
    const Vec<N> bestNum = load<N>(num);
    const Vec<N> bestDen = load<N>(den);
    const Mask<N> better = candidateNum * bestDen > bestNum * candidateDen;
    store<N>(num, better ? candidateNum : bestNum);
    store<N>(den, better ? candidateDen : bestDen);
    store<N>(reinterpret_cast<double*>(index), reinterpret_cast<Vec<N>>(better ? candidateIndex : loadMask<N>(index)));
}

// Offers one group's correlations for one sample. In the group that holds
// padding lanes (weight 0) those become 0/0, which never compares greater.
template <std::size_t N, bool HasPadding>
TACTISCOPE_INLINE void offerGroup(SampleBest& best, SignedSquares<N> r, Mask<N> index, Mask<N> padding)
{
    if constexpr (HasPadding) {
        r.numAb = padding ? Vec<N>{} : r.numAb;
        r.denAb = padding ? Vec<N>{} : r.denAb;
        r.numBa = padding ? Vec<N>{} : r.numBa;
        r.denBa = padding ? Vec<N>{} : r.denBa;
    }
    offer<N>(best.numAb, best.denAb, best.indexAb, r.numAb, r.denAb, index);
    offer<N>(best.numBa, best.denBa, best.indexBa, r.numBa, r.denBa, index);
}

// R from sign(R)·R²; 0 for a degenerate lag (NaN or no lag at all).
TACTISCOPE_INLINE double signedRootOf(double signedSquare)
{
    const double magnitude = __builtin_sqrt(signedSquare < 0.0 ? -signedSquare : signedSquare);
    // −2 marks "no valid lag"; rounding can put a true −1 a little below −1.
    return signedSquare > -1.5 ? (signedSquare < 0.0 ? -magnitude : magnitude) : 0.0;
}

// The best of the 8 lanes, branch-free: a shuffle tree finds the largest
// value, then the smallest lag index among the lanes that hold it.
// Lane permutations of an 8-lane vector (GCC and clang spell them differently).
#if defined(__clang__)
#define TACTISCOPE_PERMUTE(v, ...) __builtin_shufflevector(v, v, __VA_ARGS__)
#else
#define TACTISCOPE_PERMUTE(v, ...) __builtin_shuffle(v, Mask<8>{__VA_ARGS__})
#endif

template <typename V>
TACTISCOPE_INLINE V largestOf(V v)
{
    V swapped = TACTISCOPE_PERMUTE(v, 4, 5, 6, 7, 0, 1, 2, 3);
    v = v > swapped ? v : swapped;
    swapped = TACTISCOPE_PERMUTE(v, 2, 3, 0, 1, 6, 7, 4, 5);
    v = v > swapped ? v : swapped;
    swapped = TACTISCOPE_PERMUTE(v, 1, 0, 3, 2, 5, 4, 7, 6);
    return v > swapped ? v : swapped;
}

TACTISCOPE_INLINE LagMaximum reduceBest(const double* num, const double* den, const long long* index)
{
    const Vec<8> q = load<8>(num) / load<8>(den);  // one division per sample, not per lag
    const Vec<8> best = largestOf(q);
    // Negated indices of the lanes holding the maximum: the largest of them
    // is the smallest index.
    const Mask<8> candidates = q == best ? -loadMask<8>(index) : Mask<8>{} + (-0x7fffffffffffffffLL);
    return {best[0], static_cast<std::int32_t>(-largestOf(candidates)[0])};
}

// The N samples x(t − k) of lanes g … g+N−1 for the sample at `origin` of a
// reversed series (reversed[origin + k] = x(t − k)).
template <std::size_t N>
TACTISCOPE_INLINE Vec<N> delayed(const double* reversed, std::size_t origin, const std::uint32_t* lag, bool contiguous)
{
    if (contiguous) return load<N>(reversed + origin + lag[0]);
    Vec<N> v;
    for (std::size_t lane = 0; lane < N; ++lane) v[lane] = reversed[origin + lag[lane]];
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

// Exponential form for one group of N lags over the block's n samples.
template <std::size_t N, bool HasPadding>
TACTISCOPE_INLINE void exponentialGroup(LagMoments& s, std::size_t g, const Scratch& scratch, std::size_t n,
                                        double epsilonSquared)
{
    const Vec<N> w = load<N>(&s.weight[g]);
    const Vec<N> r = load<N>(&s.forgetting[g]);
    const Vec<N> ridge = epsilonSquared / r;
    const Mask<N> padding = w == 0.0;
    const Mask<N> index = Lanes<N>::kFirst + static_cast<long long>(g);
    auto& S = s.moment;
    Vec<N> m0 = load<N>(&s.mean[0][g]), m1 = load<N>(&s.mean[1][g]);
    Vec<N> m2 = load<N>(&s.mean[2][g]), m3 = load<N>(&s.mean[3][g]);
    Covariance<N> c{load<N>(&S[S00][g]), load<N>(&S[S01][g]), load<N>(&S[S02][g]), load<N>(&S[S03][g]),
                    load<N>(&S[S11][g]), load<N>(&S[S12][g]), load<N>(&S[S13][g]), load<N>(&S[S22][g]),
                    load<N>(&S[S23][g]), load<N>(&S[S33][g])};
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t origin = n - 1 - j;
        const Vec<N> d0 = scratch.reversedA[origin] - m0;
        const Vec<N> d1 = scratch.reversedB[origin] - m1;
        const Vec<N> d2 = delayed<N>(scratch.reversedA, origin, &s.lag[g], s.contiguous) - m2;
        const Vec<N> d3 = delayed<N>(scratch.reversedB, origin, &s.lag[g], s.contiguous) - m3;
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
        offerGroup<N, HasPadding>(scratch.best[j], partialCorrelations<N>(c), index, padding);
    }
    store<N>(&s.mean[0][g], m0);
    store<N>(&s.mean[1][g], m1);
    store<N>(&s.mean[2][g], m2);
    store<N>(&s.mean[3][g], m3);
    store<N>(&S[S00][g], c.v00);
    store<N>(&S[S01][g], c.v01);
    store<N>(&S[S02][g], c.v02);
    store<N>(&S[S03][g], c.v03);
    store<N>(&S[S11][g], c.v11);
    store<N>(&S[S12][g], c.v12);
    store<N>(&S[S13][g], c.v13);
    store<N>(&S[S22][g], c.v22);
    store<N>(&S[S23][g], c.v23);
    store<N>(&S[S33][g], c.v33);
}

// Sliding-window form for one group: window sums of u and uuᵀ, then
// h²·V = h·Σuuᵀ − Σu·Σuᵀ (+ h²ε²·I), a positive multiple of the window's V.
template <std::size_t N>
TACTISCOPE_INLINE Covariance<N> windowCovariance(const Vec<N> (&m)[4], const Vec<N> (&q)[kMomentCount], double h,
                                                 Vec<N> ridge)
{
    return {h * q[S00] - m[0] * m[0] + ridge, h * q[S01] - m[0] * m[1],         h * q[S02] - m[0] * m[2],
            h * q[S03] - m[0] * m[3],         h * q[S11] - m[1] * m[1] + ridge, h * q[S12] - m[1] * m[2],
            h * q[S13] - m[1] * m[3],         h * q[S22] - m[2] * m[2] + ridge, h * q[S23] - m[2] * m[3],
            h * q[S33] - m[3] * m[3] + ridge};
}

template <std::size_t N, bool HasPadding>
TACTISCOPE_INLINE void slidingGroup(LagMoments& s, std::size_t g, const Scratch& scratch, std::size_t n,
                                    std::uint32_t window, double epsilonSquared)
{
    const Vec<N> w = load<N>(&s.weight[g]);
    const double h = window;
    const Vec<N> ridge = w * (h * h * epsilonSquared);
    const Mask<N> padding = w == 0.0;
    const Mask<N> index = Lanes<N>::kFirst + static_cast<long long>(g);
    Vec<N> m[4];
    for (std::size_t i = 0; i < 4; ++i) m[i] = load<N>(&s.mean[i][g]);
    Vec<N> q[kMomentCount];
    for (std::size_t i = 0; i < kMomentCount; ++i) q[i] = load<N>(&s.moment[i][g]);
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t origin = n - 1 - j;
        const std::size_t leaving = origin + window;
        // Padding lanes (w = 0) see only zeros.
        const Vec<N> x[4] = {w * scratch.reversedA[origin], w * scratch.reversedB[origin],
                             w * delayed<N>(scratch.reversedA, origin, &s.lag[g], s.contiguous),
                             w * delayed<N>(scratch.reversedB, origin, &s.lag[g], s.contiguous)};
        const Vec<N> y[4] = {w * scratch.reversedA[leaving], w * scratch.reversedB[leaving],
                             w * delayed<N>(scratch.reversedA, leaving, &s.lag[g], s.contiguous),
                             w * delayed<N>(scratch.reversedB, leaving, &s.lag[g], s.contiguous)};
        for (std::size_t i = 0; i < 4; ++i) m[i] += x[i] - y[i];
        q[S00] += x[0] * x[0] - y[0] * y[0];
        q[S01] += x[0] * x[1] - y[0] * y[1];
        q[S02] += x[0] * x[2] - y[0] * y[2];
        q[S03] += x[0] * x[3] - y[0] * y[3];
        q[S11] += x[1] * x[1] - y[1] * y[1];
        q[S12] += x[1] * x[2] - y[1] * y[2];
        q[S13] += x[1] * x[3] - y[1] * y[3];
        q[S22] += x[2] * x[2] - y[2] * y[2];
        q[S23] += x[2] * x[3] - y[2] * y[3];
        q[S33] += x[3] * x[3] - y[3] * y[3];
        offerGroup<N, HasPadding>(scratch.best[j], partialCorrelations<N>(windowCovariance<N>(m, q, h, ridge)), index,
                                  padding);
    }
    for (std::size_t i = 0; i < 4; ++i) store<N>(&s.mean[i][g], m[i]);
    for (std::size_t i = 0; i < kMomentCount; ++i) store<N>(&s.moment[i][g], q[i]);
}

template <std::size_t N, bool HasPadding>
TACTISCOPE_INLINE void runGroupAs(LagMoments& s, std::size_t g, const Scratch& scratch, std::size_t n,
                                  const KernelInput& in)
{
    if (in.window == 0)
        exponentialGroup<N, HasPadding>(s, g, scratch, n, in.epsilonSquared);
    else
        slidingGroup<N, HasPadding>(s, g, scratch, n, in.window, in.epsilonSquared);
}

// The whole kernel with groups of W lanes. Forced inline into each
// instruction-set entry point below; no lambdas, which would be functions of
// their own compiled for the baseline.
template <std::size_t W>
TACTISCOPE_INLINE void runKernel(const KernelInput& in, LagMoments& s, SampleMaxima* out)
{
    const Scratch scratch(in.scratch, s, in.window);
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
        for (std::size_t g = 0; g < s.lagCount; g += W) {
            const std::size_t remaining = s.lagCount - g;
            if (remaining >= W) {
                runGroupAs<W, false>(s, g, scratch, n, in);
            } else if constexpr (W == 8) {
                // A short tail runs at half width: 75 lags compute 76 lanes, not 80.
                if (remaining > 4)
                    runGroupAs<8, true>(s, g, scratch, n, in);
                else if (remaining == 4)
                    runGroupAs<4, false>(s, g, scratch, n, in);
                else
                    runGroupAs<4, true>(s, g, scratch, n, in);
            } else {
                runGroupAs<W, true>(s, g, scratch, n, in);
            }
        }
        SampleMaxima* block = out + j0;
        for (std::size_t j = 0; j < n; ++j) {
            const SampleBest& best = scratch.best[j];
            block[j] = {reduceBest(best.numAb, best.denAb, best.indexAb),
                        reduceBest(best.numBa, best.denBa, best.indexBa)};
        }
        // sign(R)·R² → R for the whole block at once (vectorised square roots).
        for (std::size_t j = 0; j < n; ++j) {
            block[j].ab.r = signedRootOf(block[j].ab.r);
            block[j].ba.r = signedRootOf(block[j].ba.r);
        }
    }
}

__attribute__((target("arch=x86-64-v4"))) void runAvx512(const KernelInput& in, LagMoments& s, SampleMaxima* out)
{
    runKernel<8>(in, s, out);
}

__attribute__((target("arch=x86-64-v3"))) void runAvx2(const KernelInput& in, LagMoments& s, SampleMaxima* out)
{
    runKernel<4>(in, s, out);
}

void runBaseline(const KernelInput& in, LagMoments& s, SampleMaxima* out)
{
    runKernel<2>(in, s, out);
}

}  // namespace

double signedRoot(double signedSquare)
{
    return signedRootOf(signedSquare);
}

std::size_t kernelScratchSize(const LagMoments& moments, std::uint32_t window)
{
    const std::size_t reversedLength = kBlock + moments.largestLaneLag() + window + 1;
    return 2 * reversedLength + kBlock * sizeof(SampleBest) / sizeof(double);
}

KernelVariant bestKernelVariant()
{
    // Feature by feature rather than "x86-64-v4": both GCC and clang know these.
    static const KernelVariant best = [] {
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
            __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") &&
            __builtin_cpu_supports("avx512cd"))
            return KernelVariant::Avx512;
        if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2"))
            return KernelVariant::Avx2;
        return KernelVariant::Baseline;
    }();
    return best;
}

bool kernelVariantSupported(KernelVariant variant)
{
    return static_cast<int>(variant) <= static_cast<int>(bestKernelVariant());
}

const char* toString(KernelVariant variant)
{
    switch (variant) {
    case KernelVariant::Baseline:
        return "x86-64 baseline (SSE2)";
    case KernelVariant::Avx2:
        return "AVX2+FMA";
    case KernelVariant::Avx512:
        return "AVX-512";
    }
    return "?";
}

void runPartialCorrelationKernel(KernelVariant variant, const KernelInput& in, LagMoments& s, SampleMaxima* out)
{
    switch (variant) {
    case KernelVariant::Avx512:
        runAvx512(in, s, out);
        return;
    case KernelVariant::Avx2:
        runAvx2(in, s, out);
        return;
    case KernelVariant::Baseline:
        runBaseline(in, s, out);
        return;
    }
}

void correlationsFromMoments(const LagMoments& s, std::uint32_t window, double epsilonSquared, double* rab, double* rba)
{
    const auto& S = s.moment;
    for (std::size_t g = 0; g < s.paddedCount; g += kLaneWidth) {
        Covariance<8> c;
        if (window == 0) {
            c = {load<8>(&S[S00][g]), load<8>(&S[S01][g]), load<8>(&S[S02][g]), load<8>(&S[S03][g]),
                 load<8>(&S[S11][g]), load<8>(&S[S12][g]), load<8>(&S[S13][g]), load<8>(&S[S22][g]),
                 load<8>(&S[S23][g]), load<8>(&S[S33][g])};
        } else {
            Vec<8> m[4];
            Vec<8> q[kMomentCount];
            for (std::size_t i = 0; i < 4; ++i) m[i] = load<8>(&s.mean[i][g]);
            for (std::size_t i = 0; i < kMomentCount; ++i) q[i] = load<8>(&S[i][g]);
            const double h = window;
            c = windowCovariance<8>(m, q, h, load<8>(&s.weight[g]) * (h * h * epsilonSquared));
        }
        const SignedSquares<8> r = partialCorrelations<8>(c);
        for (std::size_t lane = 0; lane < kLaneWidth && g + lane < s.lagCount; ++lane) {
            rab[g + lane] = signedRoot(r.numAb[lane] / r.denAb[lane]);
            rba[g + lane] = signedRoot(r.numBa[lane] / r.denBa[lane]);
        }
    }
}

}  // namespace tactiscope::core::detector
