// Direct (Eigen 4×4 inverse) implementation of the detector's equations.
#include "DirectDetector.h"

#include <Eigen/LU>

#include <cmath>

namespace tactiscope::reference {

using core::detector::DetectorOutput;

DirectDetector::DirectDetector(const core::detector::DetectorParameters& p)
{
    const auto resolved = core::detector::resolve(p);
    m_lags = resolved.lags;
    for (std::uint32_t k : m_lags) {
        const double lambda = p.lambdaRule == core::detector::LambdaRule::EqualsLag
                                  ? static_cast<double>(k) * p.sampleInterval_s
                                  : p.fixedLambda_s;
        m_r.push_back(std::exp(-p.sampleInterval_s / lambda));
    }
    m_eps2 = p.epsilon * p.epsilon;
    m_threshold = p.threshold;
    m_bSign = p.faceToFace ? -1.0 : 1.0;
    m_window = resolved.window;
    m_mean.assign(m_lags.size(), Eigen::Vector4d::Zero());
    m_second.assign(m_lags.size(), Eigen::Matrix4d::Zero());
    m_rab.assign(m_lags.size(), 0.0);
    m_rba.assign(m_lags.size(), 0.0);
    m_plainAb.assign(m_lags.size(), 0.0);
}

double DirectDetector::delayed(const std::vector<double>& x, std::size_t t, std::size_t k) const
{
    return t >= k ? x[t - k] : 0.0;  // the paper's zero initial values
}

Eigen::Matrix4d DirectDetector::covariance(std::size_t i, std::size_t t)
{
    const std::size_t k = m_lags[i];
    if (m_window == 0) {
        const Eigen::Vector4d u(m_a[t], m_b[t], delayed(m_a, t, k), delayed(m_b, t, k));
        const double r = m_r[i];
        m_mean[i] = r * m_mean[i] + (1.0 - r) * u;  // eq. 8
        m_second[i] = r * m_second[i] + (1.0 - r) * (u * u.transpose()) +
                      (1.0 - r) * m_eps2 * Eigen::Matrix4d::Identity();  // eq. 9
        return m_second[i] - m_mean[i] * m_mean[i].transpose();          // eq. 10
    }
    // Eqs 2–3 over the last h samples (zeros before the first), plus ε²·I.
    Eigen::Vector4d mean = Eigen::Vector4d::Zero();
    Eigen::Matrix4d second = Eigen::Matrix4d::Zero();
    for (std::size_t back = 0; back < m_window; ++back) {
        if (back > t) break;  // earlier samples are zero and add nothing
        const std::size_t s = t - back;
        const Eigen::Vector4d u(m_a[s], m_b[s], delayed(m_a, s, k), delayed(m_b, s, k));
        mean += u;
        second += u * u.transpose();
    }
    const double h = static_cast<double>(m_window);
    mean /= h;
    second /= h;
    return second - mean * mean.transpose() + m_eps2 * Eigen::Matrix4d::Identity();
}

void DirectDetector::process(std::span<const double> a, std::span<const double> b, std::span<DetectorOutput> out)
{
    for (std::size_t j = 0; j < a.size(); ++j) {
        m_a.push_back(a[j]);
        m_b.push_back(m_bSign * b[j]);
        const std::size_t t = m_a.size() - 1;
        DetectorOutput o;
        o.rab = -2.0;
        o.rba = -2.0;
        for (std::size_t i = 0; i < m_lags.size(); ++i) {
            const Eigen::Matrix4d V = covariance(i, t);
            const Eigen::Matrix4d U = V.inverse();
            m_rab[i] = -U(1, 2) / std::sqrt(U(1, 1) * U(2, 2));  // eq. 4
            m_rba[i] = -U(0, 3) / std::sqrt(U(0, 0) * U(3, 3));  // eq. 5
            m_plainAb[i] = V(1, 2) / std::sqrt(V(1, 1) * V(2, 2));
            if (m_rab[i] > o.rab) {
                o.rab = m_rab[i];
                o.lagAb = m_lags[i];
            }
            if (m_rba[i] > o.rba) {
                o.rba = m_rba[i];
                o.lagBa = m_lags[i];
            }
        }
        const bool ab = o.rab > m_threshold;
        const bool ba = o.rba > m_threshold;
        o.decision = 0;
        if (ab && (!ba || o.rab > o.rba)) o.decision = 1;
        if (ba && (!ab || o.rba > o.rab)) o.decision = -1;
        out[j] = o;
    }
}

}  // namespace tactiscope::reference
