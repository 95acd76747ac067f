/* The partial-correlation detector of seed 000 for a probe's own processor:
 * single precision, no heap, no library beyond <math.h>, fixed-size state
 * for the lag set it is built with. The workstation compiles this same file
 * (tests, `tactiscope-cli detect --engine probe`, the emulated probe), so a
 * probe and the workstation run the same code, bit for bit where both
 * follow IEEE 754 without contraction (-ffp-contract=off).
 *
 * Why the form matters (seed 000's open problem, "inexpensive processors"):
 * in raw strain the weighted covariance V is about 1e-10, so det V of the
 * textbook 4×4 inverse is about 1e-40, below float's smallest normal number,
 * and half the correlations become inf or NaN. Here the inputs are scaled
 * by 2^17 (about 1/ε, exact in binary), the covariance is kept centred
 * (Welford-type updates of the weighted mean and co-moment, as the
 * workstation's double kernel does), and each partial correlation comes
 * from the 2×2 Schur complement, the covariance of the pair given the other
 * two variables, scaled by that block's determinant so no division is
 * needed. The threshold test R > θ is X₂₃ > 0 and X₂₃² > θ²·X₂₂·X₃₃: no
 * square root, no division per lag.
 */
#ifndef TACTISCOPE_PROBE_DETECTOR_H
#define TACTISCOPE_PROBE_DETECTOR_H

#ifdef __cplusplus
extern "C" {
#endif

/* The lag set the probe is built for: the paper's 2…150 ms in 2 ms steps at
 * 500 Hz is 75 lags of 1…75 samples. */
#ifndef PD_MAX_LAGS
#define PD_MAX_LAGS 75
#endif
#ifndef PD_MAX_LAG_SAMPLES
#define PD_MAX_LAG_SAMPLES 75
#endif

/* Input scale: strain × 2^17 keeps V near 1 (see above). A power of two, so
 * scaling rounds nothing. */
#define PD_INPUT_SCALE 131072.0f

typedef struct {
    double sample_interval_s;        /* Δt */
    unsigned lag_count;              /* 1 … PD_MAX_LAGS */
    const unsigned short* lags;      /* k in samples: increasing, 1 … PD_MAX_LAG_SAMPLES */
    const double* forgetting_time_s; /* λ per lag (the paper: λ = c, the lag in seconds) */
    double epsilon;                  /* regularisation ε, in the unit of a and b (strain) */
    double threshold;                /* θ on R, 0 … 1 */
    int face_to_face;                /* gauges face to face: b is negated */
} pd_config;

/* What the detector says about one sample: +1 A then B (some lag's R_ab
 * above θ), −1 B then A, 0 none; when both hold the larger R decides and
 * an exact tie says 0. rab and rba are the best R of each direction over
 * the lags; lag_ab and lag_ba their lags in samples (0: no lag yet). */
typedef struct {
    signed char decision;
    float rab;
    float rba;
    unsigned short lag_ab;
    unsigned short lag_ba;
    unsigned char restarted; /* 1: this sample was not finite; skipped, the detector begins again */
} pd_output;

/* All state; about 6 KB at the default sizes. */
typedef struct {
    unsigned lag_count;
    unsigned short lag[PD_MAX_LAGS];
    float r[PD_MAX_LAGS];     /* forgetting factor exp(−Δt/λ) */
    float w[PD_MAX_LAGS];     /* 1 − r */
    float ridge[PD_MAX_LAGS]; /* (2^17·ε)² / r, added to V's diagonal each sample */
    float threshold;
    float threshold_squared;
    float b_sign;
    /* Weighted means of u = [a, b, a(t−k), b(t−k)] and the centred
     * co-moments V/(w·r), per lag: entries 00 01 02 03 11 12 13 22 23 33. */
    float mean[4][PD_MAX_LAGS];
    float v[10][PD_MAX_LAGS];
    /* The last PD_MAX_LAG_SAMPLES + 1 scaled samples; zeros before the
     * first, as the paper starts from silence. */
    float history_a[PD_MAX_LAG_SAMPLES + 1];
    float history_b[PD_MAX_LAG_SAMPLES + 1];
    unsigned head;
} pd_detector;

/* Why pd_init refused a configuration. */
enum {
    PD_OK = 0,
    PD_BAD_LAG_COUNT = -1,  /* 0 or more than PD_MAX_LAGS */
    PD_BAD_LAGS = -2,       /* not increasing, 0, or beyond PD_MAX_LAG_SAMPLES */
    PD_BAD_INTERVAL = -3,   /* Δt not positive and finite */
    PD_BAD_FORGETTING = -4, /* λ not positive and finite */
    PD_BAD_EPSILON = -5,    /* ε negative or not finite */
    PD_BAD_THRESHOLD = -6   /* θ outside 0 … 1 */
};

/* Sets up `d` for `config`, from silence. Returns PD_OK or the reason. The
 * factors are computed with basic IEEE operations only (no libm exp), so
 * every build derives the same bits from the same configuration. */
int pd_init(pd_detector* d, const pd_config* config);

/* Back to silence, the configuration kept. */
void pd_reset(pd_detector* d);

/* One sample of each cantilever, in strain: the detector's state advances
 * and `out` says what it decided. A sample that is not a finite number (a
 * NaN from a dropped reading, an infinity) would poison every lag's sums
 * for good, so that the detector decided nothing for the rest of the scan:
 * instead it is skipped, the detector starts again from silence, and `out`
 * says so (restarted 1, decision 0). Finite values beyond ±2^100 make no
 * sense for strain and are not checked here; the caller keeps them out. */
void pd_step(pd_detector* d, float a, float b, pd_output* out);

#ifdef __cplusplus
}
#endif

#endif
