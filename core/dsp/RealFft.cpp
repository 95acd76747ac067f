// FFTW's r2c plan, made once per length under the planner's lock.
#include "core/dsp/RealFft.h"

#include <fftw3.h>

#include <algorithm>
#include <mutex>
#include <new>
#include <stdexcept>

namespace tactiscope::core::dsp {
namespace {

std::mutex& plannerLock()
{
    static std::mutex lock;
    return lock;
}

}  // namespace

RealFft::RealFft(std::size_t length)
    : m_length(length),
      m_bins(length / 2 + 1)
{
    if (length < 2) throw std::invalid_argument("an FFT needs two samples at least");
    const std::lock_guard guard(plannerLock());
    m_in = fftw_alloc_real(length);
    auto* out = fftw_alloc_complex(length / 2 + 1);
    m_out = out;
    if (m_in == nullptr || out == nullptr) {
        fftw_free(m_in);
        fftw_free(out);
        throw std::bad_alloc();
    }
    // FFTW_ESTIMATE: no timing runs, so a plan costs microseconds and the
    // same input gives the same bins on every run.
    m_plan = fftw_plan_dft_r2c_1d(static_cast<int>(length), m_in, out, FFTW_ESTIMATE);
}

RealFft::~RealFft()
{
    const std::lock_guard guard(plannerLock());
    fftw_destroy_plan(static_cast<fftw_plan>(m_plan));
    fftw_free(m_in);
    fftw_free(static_cast<fftw_complex*>(m_out));
}

std::span<const std::complex<double>> RealFft::transform(std::span<const double> input)
{
    std::copy_n(input.begin(), m_length, m_in);
    fftw_execute(static_cast<fftw_plan>(m_plan));
    const auto* out = static_cast<const fftw_complex*>(m_out);
    for (std::size_t k = 0; k < m_bins.size(); ++k) m_bins[k] = {out[k][0], out[k][1]};
    return m_bins;
}

}  // namespace tactiscope::core::dsp
