// The linearity plot of a calibration wizard: the captured points (loading
// and unloading apart, so hysteresis shows) with the fitted line on top and
// their residuals below, on a shared x axis. It draws what it is given;
// the fit itself comes from core.
#pragma once

#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

class QCustomPlot;

namespace tactiscope::ui {

struct CalibrationPoint {
    double x = 0.0;
    double y = 0.0;
    bool loading = true;
};

class CalibrationPlot : public QWidget {
    Q_OBJECT

public:
    explicit CalibrationPlot(QWidget* parent = nullptr);

    void setTitles(const QString& x, const QString& y, const QString& residual);
    // Legend names of the two kinds of point ("loading", "unloading").
    void setSeriesNames(const QString& loading, const QString& unloading);
    // Points and, when there is one, the fitted line y = intercept + slope·x
    // (residuals are shown against it).
    void setData(const std::vector<CalibrationPoint>& points, std::optional<std::pair<double, double>> slopeIntercept);

    // For tests: the residuals drawn, in point order.
    const std::vector<double>& residuals() const { return m_residuals; }

private:
    QCustomPlot* m_plot;
    std::vector<double> m_residuals;
};

}  // namespace tactiscope::ui
