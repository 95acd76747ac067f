/* The probe detector on an emulated Cortex-M: reads probe-in.bin (a scan
 * and the detector's settings, scan_format.h) from the host's working
 * directory through semihosting, runs pd_step on every sample and writes
 * probe-out.bin. Status 0 when every sample was decided, 2 for a file it
 * cannot read or settings the kernel refuses. */
#include "../probe_detector.h"
#include "../scan_format.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

static pd_detector detector; /* about 6 KB: static, never on the stack */

static int read_exactly(FILE* in, void* to, size_t bytes)
{
    return fread(to, 1, bytes, in) == bytes;
}

static uint32_t u32_at(const unsigned char* p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void put_u32(unsigned char* p, uint32_t v)
{
    for (int i = 0; i < 4; ++i) p[i] = (unsigned char)(v >> (8 * i));
}

int main(void)
{
    FILE* in = fopen("probe-in.bin", "rb");
    FILE* out = fopen("probe-out.bin", "wb");
    if (!in || !out) {
        fputs("probe: cannot open probe-in.bin or probe-out.bin\n", stderr);
        return 2;
    }
    unsigned char header[4 + 3 * 4 + 3 * 8];
    if (!read_exactly(in, header, sizeof header) || memcmp(header, PD_SCAN_MAGIC, 4) != 0) {
        fputs("probe: probe-in.bin is no scan\n", stderr);
        return 2;
    }
    const uint32_t lag_count = u32_at(header + 4);
    const uint32_t face_to_face = u32_at(header + 8);
    const uint32_t samples = u32_at(header + 12);
    double settings[3];
    memcpy(settings, header + 16, sizeof settings);
    if (lag_count == 0 || lag_count > PD_MAX_LAGS) {
        fputs("probe: more lags than this build holds\n", stderr);
        return 2;
    }
    unsigned short lags[PD_MAX_LAGS];
    double lambda[PD_MAX_LAGS];
    for (uint32_t i = 0; i < lag_count; ++i) {
        unsigned char lag[12];
        if (!read_exactly(in, lag, sizeof lag)) return 2;
        const uint32_t k = u32_at(lag);
        lags[i] = (unsigned short)(k > 0xffffu ? 0u : k);
        memcpy(&lambda[i], lag + 4, sizeof(double));
    }
    const pd_config config = {settings[0], lag_count, lags, lambda, settings[1], settings[2], face_to_face != 0};
    const int refused = pd_init(&detector, &config);
    if (refused != PD_OK) {
        fprintf(stderr, "probe: settings refused (%d)\n", refused);
        return 2;
    }
    fwrite(PD_DECISIONS_MAGIC, 1, 4, out);
    for (uint32_t s = 0; s < samples; ++s) {
        float ab[2];
        if (!read_exactly(in, ab, sizeof ab)) {
            fputs("probe: the scan ends early\n", stderr);
            return 2;
        }
        pd_output o;
        pd_step(&detector, ab[0], ab[1], &o);
        unsigned char record[PD_DECISION_RECORD_BYTES];
        put_u32(record, (uint32_t)(int32_t)o.decision);
        put_u32(record + 4, o.lag_ab);
        put_u32(record + 8, o.lag_ba);
        memcpy(record + 12, &o.rab, 4);
        memcpy(record + 16, &o.rba, 4);
        if (fwrite(record, 1, sizeof record, out) != sizeof record) return 2;
    }
    return fclose(out) == 0 ? 0 : 2;
}
