// The review window's account of a palpation session in the clinician's
// terms: every press (time, site, k_o ± SE, depth range), each site's
// presses summed up (n, mean, SD), the phantom's grid map and the tissue
// scale with each site's mean, as the live view showed them; the presses
// read again (PalpationReanalysisBox) listed beside them. A click on a
// press shows it on the plot.
#pragma once

#include "core/report/PressTable.h"
#include "core/storage/SessionStore.h"

#include <QGroupBox>

#include <vector>

class QLabel;
class QTreeWidget;

namespace tactiscope::ui {

class PalpationReanalysisBox;
class StiffnessScale;

class PressesPanel : public QGroupBox {
    Q_OBJECT

public:
    // The store and session are the review window's; the re-analysis reads them.
    PressesPanel(core::storage::SessionSource& store, const core::storage::SessionSummary& session, QWidget* parent);

    // Presses read by something else than the recording, listed beside its own.
    struct Source {
        QString name;  // "re-analysis", "saved \"…\""
        std::vector<core::report::PressRow> presses;
    };
    // The recorded presses fill every view; the others join the press list.
    void setPresses(std::vector<core::report::PressRow> recorded, const std::vector<Source>& others = {});
    PalpationReanalysisBox* reanalysis() const { return m_reanalysis; }
    QTreeWidget* pressList() const { return m_presses; }
    QTreeWidget* siteList() const { return m_sites; }

signals:
    void pressChosen(double start_s, double end_s);

private:
    QTreeWidget* m_presses;
    PalpationReanalysisBox* m_reanalysis;
    QTreeWidget* m_sites;
    QLabel* m_grid;
    StiffnessScale* m_scale;
};

}  // namespace tactiscope::ui
