// The raw-data console, for troubleshooting a probe: what arrives on the
// wire — the last text lines, or a hex dump of the last binary bytes — and
// the decoder's counters (bytes, good frames or lines, CRC errors, resyncs,
// malformed payloads, skipped lines, lost samples), refreshed four times a
// second. It can be frozen to read. The simulator has no wire; the console
// says so.
#pragma once

#include <QTimer>
#include <QWidget>

#include <cstdint>
#include <span>

class QCheckBox;
class QLabel;
class QPlainTextEdit;

namespace tactiscope::devices {
class BlockSource;
}

namespace tactiscope::ui {

class LiveStation;

class RawConsole : public QWidget {
    Q_OBJECT

public:
    explicit RawConsole(QWidget* parent = nullptr);

    // The source to show; null when disconnected. It must outlive the
    // console's use of it (the main window clears it before a disconnect).
    void setSource(const devices::BlockSource* source);
    // Shows the live station's window device while it is connected.
    void watch(const LiveStation& station);
    void refresh();

private:
    const devices::BlockSource* m_source = nullptr;
    QLabel* m_counters = nullptr;
    QPlainTextEdit* m_text = nullptr;
    QCheckBox* m_freeze = nullptr;
    QTimer m_timer;
};

// The last `maxLines` complete lines of `bytes` (text protocols).
QString lastLines(std::span<const std::uint8_t> bytes, int maxLines);
// A hex dump of the last `maxBytes` of `bytes`, 16 per row with offsets
// counted back from the newest byte ("-0010"), and printable ASCII beside.
QString hexDump(std::span<const std::uint8_t> bytes, std::size_t maxBytes);

}  // namespace tactiscope::ui
