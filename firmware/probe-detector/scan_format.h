/* The binary scan and decision files that carry a scan into the emulated
 * probe and its decisions back (QEMU's semihosting reads and writes host
 * files): little-endian, as both x86-64 and Cortex-M are.
 *
 * probe-in.bin:  "PDI1", u32 lag count, u32 face to face (0/1), u32 sample
 *                count, f64 Δt, f64 ε, f64 θ, then per lag u32 k and f64 λ,
 *                then per sample f32 a and f32 b (strain).
 * probe-out.bin: "PDO1", then per sample i32 decision, u32 lag_ab, u32
 *                lag_ba, f32 rab, f32 rba (20 bytes).
 */
#ifndef TACTISCOPE_PROBE_SCAN_FORMAT_H
#define TACTISCOPE_PROBE_SCAN_FORMAT_H

#define PD_SCAN_MAGIC "PDI1"
#define PD_DECISIONS_MAGIC "PDO1"
#define PD_DECISION_RECORD_BYTES 20

#endif
