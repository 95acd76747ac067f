/* The host's side of the emulated probe (qemu-detect.sh):
 *   scan_io pack SCAN.csv probe-in.bin     the scan and the paper's settings
 *   scan_io unpack SCAN.csv probe-out.bin OUT.csv
 * pack reads the columns t, a and b (a unit in brackets may follow a name,
 * "t [s]"), takes the sampling interval as the workstation does (the whole
 * file's mean), resolves the paper's lags (2–150 ms in 2 ms steps, λ = c,
 * ε = 7·10⁻⁶, θ = 0.85) as core/detector/DetectorParameters.cpp does, and
 * writes scan_format.h's input. unpack writes the rows of `tactiscope-cli
 * detect --output` (t,out,rab,rba,lag_ab_ms,lag_ba_ms) with numbers in
 * their shortest round-trip form, as that command writes them, so the two
 * files compare byte for byte. */
#include "../scan_format.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_LAGS 4096

static int fail(const char* what, const char* path)
{
    fprintf(stderr, "scan_io: %s: %s\n", path, what);
    return 2;
}

/* Growing arrays of the three columns. */
typedef struct {
    double *t, *a, *b;
    size_t count, room;
} scan;

static int push(scan* s, double t, double a, double b)
{
    if (s->count == s->room) {
        s->room = s->room ? 2 * s->room : 4096;
        s->t = realloc(s->t, s->room * sizeof(double));
        s->a = realloc(s->a, s->room * sizeof(double));
        s->b = realloc(s->b, s->room * sizeof(double));
        if (!s->t || !s->a || !s->b) return 0;
    }
    s->t[s->count] = t;
    s->a[s->count] = a;
    s->b[s->count] = b;
    ++s->count;
    return 1;
}

/* Whether header cell `cell` names `name`, alone or with " [unit]". */
static int names(const char* cell, size_t length, const char* name)
{
    const size_t n = strlen(name);
    return length >= n && strncmp(cell, name, n) == 0 && (length == n || strncmp(cell + n, " [", 2) == 0);
}

static int read_scan(const char* path, scan* s)
{
    FILE* in = fopen(path, "r");
    if (!in) return fail("cannot be read", path);
    char line[4096];
    if (!fgets(line, sizeof line, in)) return fail("is empty", path);
    int column[3] = {-1, -1, -1};
    const char* wanted[3] = {"t", "a", "b"};
    int index = 0;
    for (char* cell = line;; ++index) {
        size_t length = strcspn(cell, ",\r\n");
        for (int c = 0; c < 3; ++c)
            if (column[c] < 0 && names(cell, length, wanted[c])) column[c] = index;
        if (cell[length] != ',') break;
        cell += length + 1;
    }
    if (column[0] < 0 || column[1] < 0 || column[2] < 0) return fail("has no columns t, a and b", path);
    while (fgets(line, sizeof line, in)) {
        double value[3] = {NAN, NAN, NAN};
        char* cell = line;
        for (index = 0;; ++index) {
            for (int c = 0; c < 3; ++c)
                if (column[c] == index) value[c] = strtod(cell, NULL);
            const size_t length = strcspn(cell, ",\r\n");
            if (cell[length] != ',') break;
            cell += length + 1;
        }
        if (!isfinite(value[0]) || !isfinite(value[1]) || !isfinite(value[2]))
            return fail("holds a row without a finite t, a and b", path);
        if (!push(s, value[0], value[1], value[2])) return fail("does not fit in memory", path);
    }
    fclose(in);
    if (s->count < 2) return fail("has fewer than two rows", path);
    return 0;
}

static void put_u32(FILE* out, uint32_t v)
{
    unsigned char b[4] = {(unsigned char)v, (unsigned char)(v >> 8), (unsigned char)(v >> 16),
                          (unsigned char)(v >> 24)};
    fwrite(b, 1, 4, out);
}

static double interval_of(const scan* s)
{
    return (s->t[s->count - 1] - s->t[0]) / (double)(s->count - 1);
}

static int pack(const char* csv, const char* bin)
{
    scan s = {0};
    if (read_scan(csv, &s)) return 2;
    const double dt = interval_of(&s);
    if (!(dt > 0.0)) return fail("its times do not increase", csv);
    /* The paper's lags, resolved as the workstation resolves them. */
    const double start = 0.002, stop = 0.150, step = 0.002;
    const double count = floor((stop - start) / step + 1e-9 / step) + 1.0;
    uint32_t lags[MAX_LAGS];
    unsigned n = 0;
    for (unsigned i = 0; i < (unsigned)count; ++i) {
        const double k = round((start + (double)i * step) / dt);
        if (k < 1.0 || k > MAX_LAGS) return fail("its sampling is too slow or too fast for the paper's lags", csv);
        if (n == 0 || (uint32_t)k > lags[n - 1]) lags[n++] = (uint32_t)k;
    }
    FILE* out = fopen(bin, "wb");
    if (!out) return fail("cannot be written", bin);
    fwrite(PD_SCAN_MAGIC, 1, 4, out);
    put_u32(out, n);
    put_u32(out, 0); /* not face to face */
    put_u32(out, (uint32_t)s.count);
    const double settings[3] = {dt, 7e-6, 0.85};
    fwrite(settings, sizeof(double), 3, out);
    for (unsigned i = 0; i < n; ++i) {
        put_u32(out, lags[i]);
        const double lambda = (double)lags[i] * dt; /* λ = c */
        fwrite(&lambda, sizeof lambda, 1, out);
    }
    for (size_t i = 0; i < s.count; ++i) {
        const float ab[2] = {(float)s.a[i], (float)s.b[i]};
        fwrite(ab, sizeof(float), 2, out);
    }
    return fclose(out) == 0 ? 0 : fail("cannot be written", bin);
}

/* The shortest decimal that reads back as `x`, in the form C++'s
 * std::to_chars gives: fixed or scientific, whichever is shorter (fixed on
 * a tie), exponents of two digits at least. */
static void shortest(char* text, double x)
{
    if (x == 0.0) {
        strcpy(text, signbit(x) ? "-0" : "0");
        return;
    }
    char sci[40];
    int digits = 1;
    for (; digits <= 17; ++digits) {
        snprintf(sci, sizeof sci, "%.*e", digits - 1, x);
        if (strtod(sci, NULL) == x) break;
    }
    const int negative = sci[0] == '-';
    const char* p = sci + negative;
    char mantissa[20];
    int m = 0;
    for (; *p && *p != 'e'; ++p)
        if (*p != '.') mantissa[m++] = *p;
    mantissa[m] = '\0';
    const int exponent = atoi(p + 1);
    char fixed[64], scientific[40];
    char* f = fixed;
    if (negative) *f++ = '-';
    if (exponent < 0) {
        f += sprintf(f, "0.");
        for (int i = 0; i < -exponent - 1; ++i) *f++ = '0';
        f += sprintf(f, "%s", mantissa);
    } else if (m - 1 <= exponent) {
        f += sprintf(f, "%s", mantissa);
        for (int i = 0; i < exponent - (m - 1); ++i) *f++ = '0';
    } else {
        memcpy(f, mantissa, (size_t)exponent + 1);
        f += exponent + 1;
        *f++ = '.';
        f += sprintf(f, "%s", mantissa + exponent + 1);
    }
    *f = '\0';
    snprintf(scientific, sizeof scientific, "%s%c%s%se%c%02d", negative ? "-" : "", mantissa[0], m > 1 ? "." : "",
             mantissa + 1, exponent < 0 ? '-' : '+', abs(exponent));
    strcpy(text, strlen(scientific) < strlen(fixed) ? scientific : fixed);
}

static uint32_t u32_of(const unsigned char* p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* A lag in ms as the workstation prints it: k·Δt rounded to 1 ns. */
static double lag_ms(uint32_t k, double dt)
{
    return round((double)k * dt * 1e9) / 1e6;
}

static int unpack(const char* csv, const char* bin, const char* outPath)
{
    scan s = {0};
    if (read_scan(csv, &s)) return 2;
    const double dt = interval_of(&s);
    FILE* in = fopen(bin, "rb");
    if (!in) return fail("cannot be read", bin);
    unsigned char magic[4];
    if (fread(magic, 1, 4, in) != 4 || memcmp(magic, PD_DECISIONS_MAGIC, 4) != 0)
        return fail("holds no decisions", bin);
    FILE* out = fopen(outPath, "w");
    if (!out) return fail("cannot be written", outPath);
    fputs("t,out,rab,rba,lag_ab_ms,lag_ba_ms\n", out);
    for (size_t i = 0; i < s.count; ++i) {
        unsigned char r[PD_DECISION_RECORD_BYTES];
        if (fread(r, 1, sizeof r, in) != sizeof r) return fail("ends before the scan does", bin);
        float rab, rba;
        memcpy(&rab, r + 12, 4);
        memcpy(&rba, r + 16, 4);
        char t[40], a[40], b[40], la[40], lb[40];
        shortest(t, s.t[i]);
        shortest(a, (double)rab);
        shortest(b, (double)rba);
        shortest(la, lag_ms(u32_of(r + 4), dt));
        shortest(lb, lag_ms(u32_of(r + 8), dt));
        fprintf(out, "%s,%d,%s,%s,%s,%s\n", t, (int)(int32_t)u32_of(r), a, b, la, lb);
    }
    return fclose(out) == 0 ? 0 : fail("cannot be written", outPath);
}

int main(int argc, char** argv)
{
    if (argc == 4 && strcmp(argv[1], "pack") == 0) return pack(argv[2], argv[3]);
    if (argc == 5 && strcmp(argv[1], "unpack") == 0) return unpack(argv[2], argv[3], argv[4]);
    fputs("usage: scan_io pack SCAN.csv probe-in.bin | scan_io unpack SCAN.csv probe-out.bin OUT.csv\n", stderr);
    return 2;
}
