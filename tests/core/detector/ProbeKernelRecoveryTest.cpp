// The probe's kernel (firmware/probe-detector/probe_detector.c, through its
// C API) fed a sample that is not a finite number: before, one NaN or one
// 1e300 (infinite as a float) poisoned every lag's sums and the kernel
// decided nothing for the rest of the scan, which reads as "no defect".
// Now it skips that sample, says so (restarted), and starts again from
// silence: every output after it is, bit for bit, what a kernel started on
// the next sample gives, and the dent 2 s in is found.
#include "probe_detector.h"
#include "support/GeneratedScans.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

constexpr double kInterval_s = 0.002;

// The paper's settings at 500 Hz: lags of 2…150 ms (1…75 samples), λ = c.
struct PaperKernel {
    PaperKernel()
    {
        for (unsigned short k = 1; k <= 75; ++k) {
            lags.push_back(k);
            lambda_s.push_back(k * kInterval_s);
        }
        const pd_config config{kInterval_s, 75, lags.data(), lambda_s.data(), 7e-6, 0.85, 0};
        EXPECT_EQ(pd_init(&detector, &config), PD_OK);
    }
    std::vector<unsigned short> lags;
    std::vector<double> lambda_s;
    pd_detector detector{};
};

std::vector<pd_output> run(const std::vector<double>& a, const std::vector<double>& b, std::size_t from)
{
    PaperKernel kernel;
    std::vector<pd_output> out(a.size() - from);
    for (std::size_t i = from; i < a.size(); ++i)
        pd_step(&kernel.detector, static_cast<float>(a[i]), static_cast<float>(b[i]), &out[i - from]);
    return out;
}

class ProbeKernelRecovery : public ::testing::TestWithParam<double> {};

}  // namespace

TEST_P(ProbeKernelRecovery, SkipsTheSampleSaysSoAndDecidesAgainAsIfStartedAfterIt)
{
    const auto scan = tactiscope::testing::generateScan({"dent", 0.3}, 5);
    constexpr std::size_t kBad = 300;  // 0.6 s in, well before the dent at 2 s
    auto a = scan.a;
    a[kBad] = GetParam();
    const std::vector<pd_output> all = run(a, scan.b, 0);
    EXPECT_EQ(all[kBad].restarted, 1);
    EXPECT_EQ(all[kBad].decision, 0);
    std::size_t restarts = 0;
    for (const pd_output& o : all) restarts += o.restarted;
    EXPECT_EQ(restarts, 1U);

    const std::vector<pd_output> fresh = run(a, scan.b, kBad + 1);
    std::size_t decided = 0;
    for (std::size_t i = 0; i < fresh.size(); ++i) {
        const pd_output& o = all[kBad + 1 + i];
        ASSERT_EQ(o.decision, fresh[i].decision) << "sample " << kBad + 1 + i;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(o.rab), std::bit_cast<std::uint32_t>(fresh[i].rab));
        ASSERT_EQ(std::bit_cast<std::uint32_t>(o.rba), std::bit_cast<std::uint32_t>(fresh[i].rba));
        ASSERT_EQ(o.lag_ab, fresh[i].lag_ab);
        ASSERT_EQ(o.lag_ba, fresh[i].lag_ba);
        decided += o.decision == scan.direction;
    }
    EXPECT_GT(decided, 5U) << "the dent after the bad sample is found";
}

INSTANTIATE_TEST_SUITE_P(NotFinite, ProbeKernelRecovery,
                         ::testing::Values(std::numeric_limits<double>::quiet_NaN(), 1e300,
                                           -std::numeric_limits<double>::infinity()));
