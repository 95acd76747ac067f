// A real-to-complex FFT of one length through FFTW, the field's FFT
// library. FFTW's planner is not thread-safe, so plans are made and freed
// under one lock; running a plan is safe from any thread.
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace tactiscope::core::dsp {

class RealFft {
public:
    explicit RealFft(std::size_t length);
    ~RealFft();
    RealFft(const RealFft&) = delete;
    RealFft& operator=(const RealFft&) = delete;

    std::size_t length() const { return m_length; }
    // The length/2 + 1 bins of `input` (length samples).
    std::span<const std::complex<double>> transform(std::span<const double> input);

private:
    std::size_t m_length;
    double* m_in = nullptr;
    void* m_out = nullptr;   // fftw_complex*
    void* m_plan = nullptr;  // fftw_plan
    std::vector<std::complex<double>> m_bins;
};

}  // namespace tactiscope::core::dsp
