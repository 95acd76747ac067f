// The review window's account of a palpation session in the clinician's
// terms: every press (time, site, k_o ± SE, depth range), each site's
// presses summed up (n, mean, SD), the phantom's grid map and the tissue
// scale with each site's mean, as the live view showed them; the presses
// read again (PalpationReanalysisBox) listed beside them. A click on a
// press shows it on the plot.
#pragma once

#include "ui/review/ReviewAccount.h"

#include <optional>
#include <vector>

class QLabel;
class QTreeWidget;

namespace tactiscope::ui {

class PalpationReanalysisBox;
class StiffnessScale;

class PressesPanel : public ReviewAccount {
    Q_OBJECT

public:
    // The store and session are the review window's; the re-analysis reads them.
    PressesPanel(const ReviewAccountContext& context, QWidget* parent);

    // The re-read presses until they are saved.
    std::optional<Unsaved> unsaved() const override;
    // The recorded presses fill every view; the others join the press list.
    void showReadings(const std::vector<core::storage::SessionReading>& recorded,
                      const std::vector<Readings>& others) override;
    bool wantsRoom() const override { return true; }
    PalpationReanalysisBox* reanalysis() const { return m_reanalysis; }
    QTreeWidget* pressList() const { return m_presses; }
    QTreeWidget* siteList() const { return m_sites; }

private:
    QTreeWidget* m_presses;
    PalpationReanalysisBox* m_reanalysis;
    QTreeWidget* m_sites;
    QLabel* m_grid;
    StiffnessScale* m_scale;
};

}  // namespace tactiscope::ui
