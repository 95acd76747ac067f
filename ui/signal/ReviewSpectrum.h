// Review ▸ Signal ▸ Spectrum of the range shown…: the spectrum of one of a
// stored session's channels, or of the filtered and math channels it was
// recorded with (computed again from its samples), over the range the
// review shows (its first 4 Mi samples when longer). The samples are read
// from the store, gaps as gaps.
#pragma once

#include "core/storage/SessionExport.h"
#include "core/storage/SessionSource.h"

#include <QDialog>

#include <memory>

namespace tactiscope::ui {

class SpectrumView;

class ReviewSpectrum : public QDialog {
    Q_OBJECT

public:
    // The most samples read for one spectrum: 32 MB of doubles.
    static constexpr std::uint64_t kMostSamples = std::uint64_t{1} << 22;

    ReviewSpectrum(core::storage::SessionSource& store, const core::storage::SessionSummary& session, double from_s,
                   double to_s, QWidget* parent = nullptr);
    ~ReviewSpectrum() override;
    SpectrumView* view() const { return m_view; }

private:
    void draw();

    core::storage::SessionSource& m_store;
    core::storage::SessionSummary m_session;
    std::size_t m_stored = 0;                                  // stored channels; the recorded signal's after
    std::unique_ptr<core::storage::ComputedColumns> m_signal;  // null without a setup
    std::uint64_t m_first = 0, m_count = 0;
    double m_rate_hz = 0.0;
    QString m_span;
    SpectrumView* m_view;
};

}  // namespace tactiscope::ui
