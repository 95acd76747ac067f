/* The probe's detector: the seed-000 partial correlations in single
 * precision, per lag and sample about 116 floating-point operations. See
 * probe_detector.h for the form and why. */
#include "probe_detector.h"

#include <math.h>

/* The per-lag helpers inline into the loop: a call per lag cost a third of
 * the cycles on a Cortex-M4 (the results went through memory). */
#if defined(__GNUC__)
#define PD_INLINE static inline __attribute__((always_inline))
#else
#define PD_INLINE static inline
#endif

/* e^x for x ≤ 0 from basic double operations only (halvings, a Taylor
 * series, squarings), so a Cortex-M's soft double and an x86's SSE2 give
 * the same bits: libm's exp differs between newlib and glibc in the last
 * place. Relative error below 1e-13 for x ≥ −50, far under float's 6e-8. */
static double exp_of_negative(double x)
{
    int halvings = 0;
    while (x < -0.00390625) { /* 2^-8 */
        x *= 0.5;
        ++halvings;
    }
    /* Horner to x^10/10!: the next term is below 1e-28. */
    double sum = 1.0;
    for (int n = 10; n >= 1; --n) sum = 1.0 + sum * x / (double)n;
    while (halvings-- > 0) sum *= sum;
    return sum;
}

int pd_init(pd_detector* d, const pd_config* config)
{
    if (config->lag_count == 0 || config->lag_count > PD_MAX_LAGS) return PD_BAD_LAG_COUNT;
    if (!(config->sample_interval_s > 0.0) || !isfinite(config->sample_interval_s)) return PD_BAD_INTERVAL;
    if (!(config->epsilon >= 0.0) || !isfinite(config->epsilon)) return PD_BAD_EPSILON;
    if (!(config->threshold >= 0.0 && config->threshold <= 1.0)) return PD_BAD_THRESHOLD;
    const double scaled_epsilon = config->epsilon * (double)PD_INPUT_SCALE;
    for (unsigned i = 0; i < config->lag_count; ++i) {
        const unsigned k = config->lags[i];
        if (k == 0 || k > PD_MAX_LAG_SAMPLES || (i > 0 && k <= config->lags[i - 1])) return PD_BAD_LAGS;
        const double lambda = config->forgetting_time_s[i];
        /* A memory under a fiftieth of a sample remembers nothing. */
        if (!(lambda > 0.0) || !isfinite(lambda) || config->sample_interval_s / lambda > 50.0) return PD_BAD_FORGETTING;
        const double r = exp_of_negative(-config->sample_interval_s / lambda);
        d->lag[i] = (unsigned short)k;
        d->r[i] = (float)r;
        d->w[i] = (float)(1.0 - r);
        d->ridge[i] = (float)(scaled_epsilon * scaled_epsilon / r);
    }
    d->lag_count = config->lag_count;
    d->threshold = (float)config->threshold;
    d->threshold_squared = (float)(config->threshold * config->threshold);
    d->b_sign = config->face_to_face ? -1.0f : 1.0f;
    pd_reset(d);
    return PD_OK;
}

void pd_reset(pd_detector* d)
{
    for (unsigned i = 0; i < PD_MAX_LAGS; ++i) {
        for (unsigned j = 0; j < 4; ++j) d->mean[j][i] = 0.0f;
        for (unsigned j = 0; j < 10; ++j) d->v[j][i] = 0.0f;
    }
    for (unsigned i = 0; i <= PD_MAX_LAG_SAMPLES; ++i) d->history_a[i] = d->history_b[i] = 0.0f;
    d->head = 0;
}

/* The partial correlation of x and y given z and w as sign(R)·R² = num/den
 * (den ≥ 0): the Schur complement Σ_XX − Σ_XZ Σ_ZZ⁻¹ Σ_ZX scaled by
 * det Σ_ZZ, written with the adjugate, so no division. The same formula as
 * the workstation's double kernel. */
PD_INLINE void conditional_correlation(float zz, float ww, float zw, float xz, float xw, float yz, float yw, float xx,
                                       float yy, float xy, float* num, float* den)
{
    const float det = zz * ww - zw * zw;
    const float ya = ww * yz - zw * yw;
    const float yb = zz * yw - zw * yz;
    const float xa = ww * xz - zw * xw;
    const float xb = zz * xw - zw * xz;
    const float cxx = det * xx - (xz * xa + xw * xb);
    const float cyy = det * yy - (yz * ya + yw * yb);
    const float cxy = det * xy - (xz * ya + xw * yb);
    *num = cxy * fabsf(cxy);
    *den = cxx * cyy;
}

/* A direction's best lag so far, as the ratio num/den. */
typedef struct {
    float num;
    float den;
    int index;
} best_ratio;

/* c/d > b/e ⇔ c·e > b·d for positive denominators; a 0/0 or NaN candidate
 * never wins, and a tie keeps the shorter lag (offered first). */
PD_INLINE void offer(best_ratio* best, float num, float den, int index)
{
    if (num * best->den > best->num * den) {
        best->num = num;
        best->den = den;
        best->index = index;
    }
}

/* R > θ without a root or a division: num > 0 and num > θ²·den. */
static int above(const best_ratio* best, float threshold_squared)
{
    return best->index >= 0 && best->num > 0.0f && best->num > threshold_squared * best->den;
}

/* R itself, for the output: one root and one division per direction and
 * sample, not per lag. */
static float root_of(const best_ratio* best)
{
    if (best->index < 0 || !(best->den > 0.0f)) return 0.0f;
    const float magnitude = sqrtf(fabsf(best->num) / best->den);
    return best->num < 0.0f ? -magnitude : magnitude;
}

void pd_step(pd_detector* d, float a, float b, pd_output* out)
{
    const unsigned size = PD_MAX_LAG_SAMPLES + 1;
    const float sa = a * PD_INPUT_SCALE;
    const float sb = d->b_sign * b * PD_INPUT_SCALE;
    if (!isfinite(sa) || !isfinite(sb)) {
        pd_reset(d);
        out->decision = 0;
        out->rab = 0.0f;
        out->rba = 0.0f;
        out->lag_ab = 0;
        out->lag_ba = 0;
        out->restarted = 1;
        return;
    }
    d->head = d->head + 1 == size ? 0 : d->head + 1;
    d->history_a[d->head] = sa;
    d->history_b[d->head] = sb;

    best_ratio ab = {-2.0f, 1.0f, -1}; /* −2/1 is below any sign(R)·R² (≥ −1) */
    best_ratio ba = {-2.0f, 1.0f, -1};
    float *m0 = d->mean[0], *m1 = d->mean[1], *m2 = d->mean[2], *m3 = d->mean[3];
    float *v00 = d->v[0], *v01 = d->v[1], *v02 = d->v[2], *v03 = d->v[3], *v11 = d->v[4];
    float *v12 = d->v[5], *v13 = d->v[6], *v22 = d->v[7], *v23 = d->v[8], *v33 = d->v[9];
    for (unsigned i = 0; i < d->lag_count; ++i) {
        const unsigned k = d->lag[i];
        const unsigned at = d->head >= k ? d->head - k : d->head + size - k;
        const float r = d->r[i], w = d->w[i], ridge = d->ridge[i];
        /* Welford: d = u − ū(t−Δt); ū ← ū + w·d; V̂ ← r·V̂ + d·dᵀ + ridge·I. */
        const float d0 = sa - m0[i];
        const float d1 = sb - m1[i];
        const float d2 = d->history_a[at] - m2[i];
        const float d3 = d->history_b[at] - m3[i];
        m0[i] += w * d0;
        m1[i] += w * d1;
        m2[i] += w * d2;
        m3[i] += w * d3;
        v00[i] = r * v00[i] + (d0 * d0 + ridge);
        v01[i] = r * v01[i] + d0 * d1;
        v02[i] = r * v02[i] + d0 * d2;
        v03[i] = r * v03[i] + d0 * d3;
        v11[i] = r * v11[i] + (d1 * d1 + ridge);
        v12[i] = r * v12[i] + d1 * d2;
        v13[i] = r * v13[i] + d1 * d3;
        v22[i] = r * v22[i] + (d2 * d2 + ridge);
        v23[i] = r * v23[i] + d2 * d3;
        v33[i] = r * v33[i] + (d3 * d3 + ridge);
        float num, den;
        /* R_ab (eq. 4): b(t) with a(t−k), given a(t) and b(t−k). */
        conditional_correlation(v00[i], v33[i], v03[i], v01[i], v13[i], v02[i], v23[i], v11[i], v22[i], v12[i], &num,
                                &den);
        offer(&ab, num, den, (int)i);
        /* R_ba (eq. 5): a(t) with b(t−k), given b(t) and a(t−k). */
        conditional_correlation(v11[i], v22[i], v12[i], v01[i], v02[i], v13[i], v23[i], v00[i], v33[i], v03[i], &num,
                                &den);
        offer(&ba, num, den, (int)i);
    }

    const int hit_ab = above(&ab, d->threshold_squared);
    const int hit_ba = above(&ba, d->threshold_squared);
    signed char decision = 0;
    if (hit_ab && hit_ba) {
        /* The larger R decides: compare the ratios, an exact tie names no direction. */
        const float left = ab.num * ba.den, right = ba.num * ab.den;
        decision = left > right ? 1 : (right > left ? -1 : 0);
    } else if (hit_ab) {
        decision = 1;
    } else if (hit_ba) {
        decision = -1;
    }
    out->decision = decision;
    out->rab = root_of(&ab);
    out->rba = root_of(&ba);
    out->lag_ab = ab.index >= 0 ? d->lag[ab.index] : 0;
    out->lag_ba = ba.index >= 0 ? d->lag[ba.index] : 0;
    out->restarted = 0;
}
