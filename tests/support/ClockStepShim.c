/* Test-only LD_PRELOAD shim that sets the host's clock back (or forward)
 * in one process, as an administrator or NTP stepping the clock would,
 * without touching the machine's clock: TACTISCOPE_TEST_CLOCK_STEP="A,S"
 * makes CLOCK_REALTIME read S seconds off (S < 0: back) from A seconds
 * after the process started. The steady clocks are untouched, as the
 * kernel leaves CLOCK_MONOTONIC when the wall clock is set. Without the
 * variable every call goes straight to the C library.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

static int (*realClockGettime)(clockid_t, struct timespec*);
static double stepAfter_s = -1.0;
static double step_s = 0.0;
static struct timespec started;

/* The C library's, once this library's constructor ran; before (a
 * sanitizer's runtime asks for the time while it starts) the kernel's. */
static int readClock(clockid_t clock, struct timespec* time)
{
    if (!realClockGettime) return (int)syscall(SYS_clock_gettime, clock, time);
    return realClockGettime(clock, time);
}

__attribute__((constructor)) static void readStep(void)
{
    realClockGettime = (int (*)(clockid_t, struct timespec*))dlsym(RTLD_NEXT, "clock_gettime");
    const char* spec = getenv("TACTISCOPE_TEST_CLOCK_STEP");
    if (spec && sscanf(spec, "%lf,%lf", &stepAfter_s, &step_s) != 2) stepAfter_s = -1.0;
    readClock(CLOCK_MONOTONIC, &started);
}

int clock_gettime(clockid_t clock, struct timespec* time)
{
    const int result = readClock(clock, time);
    if (result != 0 || stepAfter_s < 0.0 || (clock != CLOCK_REALTIME && clock != CLOCK_REALTIME_COARSE)) return result;
    struct timespec now;
    readClock(CLOCK_MONOTONIC, &now);
    const double since_s = (double)(now.tv_sec - started.tv_sec) + (double)(now.tv_nsec - started.tv_nsec) * 1e-9;
    if (since_s < stepAfter_s) return result;
    const long long ns = (long long)time->tv_sec * 1000000000LL + time->tv_nsec + (long long)(step_s * 1e9);
    time->tv_sec = (time_t)(ns / 1000000000LL);
    time->tv_nsec = (long)(ns % 1000000000LL);
    return result;
}
