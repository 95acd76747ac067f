// ScrollingMinMax: the open column, closing it into points, dropping old ones.
#include "core/signal/ScrollingMinMax.h"

#include "core/signal/MinMaxDecimation.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::signal {

ScrollingMinMax::ScrollingMinMax(double columnWidth_s)
    : m_width_s(columnWidth_s)
{
    if (!(columnWidth_s > 0.0)) throw std::invalid_argument("ScrollingMinMax: column width must be positive");
}

double ScrollingMinMax::columnOf(double t_s) const
{
    return std::floor(t_s / m_width_s);  // as decimateMinMax does
}

void ScrollingMinMax::append(std::span<const double> t, std::span<const double> y)
{
    if (t.size() != y.size()) throw std::invalid_argument("ScrollingMinMax: t and y differ in length");
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!m_openT.empty() && columnOf(t[i]) != columnOf(m_openT.front())) closeColumn();
        m_openT.push_back(t[i]);
        m_openY.push_back(y[i]);
    }
}

void ScrollingMinMax::closeColumn()
{
    const auto [first, second] = columnExtremes(m_openY);
    m_t.push_back(m_openT[first]);
    m_y.push_back(m_openY[first]);
    if (second != first) {
        m_t.push_back(m_openT[second]);
        m_y.push_back(m_openY[second]);
    }
    m_openT.clear();
    m_openY.clear();
}

void ScrollingMinMax::dropBefore(double t_s)
{
    const double column = columnOf(t_s);
    while (!m_t.empty() && columnOf(m_t.front()) < column) {
        m_t.pop_front();
        m_y.pop_front();
    }
}

void ScrollingMinMax::points(std::vector<double>& tOut, std::vector<double>& yOut) const
{
    tOut.assign(m_t.begin(), m_t.end());
    yOut.assign(m_y.begin(), m_y.end());
    if (m_openT.empty()) return;
    // The open column as it stands.
    std::vector<double> t, y;
    decimateMinMax(m_openT, m_openY, m_width_s, t, y);
    tOut.insert(tOut.end(), t.begin(), t.end());
    yOut.insert(yOut.end(), y.begin(), y.end());
}

}  // namespace tactiscope::core::signal
