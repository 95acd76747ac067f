// The review window's account of a palpation session in the clinician's
// terms: every press (time, site, k_o ± SE, depth range), each site's
// presses summed up (n, mean, SD), the phantom's grid map and the tissue
// scale with each site's mean, as the live view showed them. A click on a
// press shows it on the plot.
#pragma once

#include "core/report/PressTable.h"

#include <QGroupBox>

#include <vector>

class QLabel;
class QTreeWidget;

namespace tactiscope::ui {

class StiffnessScale;

class PressesPanel : public QGroupBox {
    Q_OBJECT

public:
    explicit PressesPanel(QWidget* parent);

    void setPresses(std::vector<core::report::PressRow> presses);
    QTreeWidget* pressList() const { return m_presses; }
    QTreeWidget* siteList() const { return m_sites; }

signals:
    void pressChosen(double start_s, double end_s);

private:
    QTreeWidget* m_presses;
    QTreeWidget* m_sites;
    QLabel* m_grid;
    StiffnessScale* m_scale;
};

}  // namespace tactiscope::ui
