// RawConsole: counters line, text or hex view, freeze.
#include "ui/device/RawConsole.h"

#include "devices/BlockSource.h"
#include "devices/session/LiveSession.h"
#include "ui/live/LiveStation.h"

#include <QCheckBox>
#include <QFontDatabase>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace tactiscope::ui {
namespace {

constexpr int kRefresh_ms = 250;
constexpr int kLines = 40;
constexpr std::size_t kHexBytes = 512;

}  // namespace

QString lastLines(std::span<const std::uint8_t> bytes, int maxLines)
{
    // Only complete lines: drop the partial one at the end and the one cut at the start.
    const QString text =
        QString::fromLatin1(reinterpret_cast<const char*>(bytes.data()), static_cast<qsizetype>(bytes.size()));
    QStringList lines = text.split(QLatin1Char('\n'));
    lines.removeLast();
    if (!lines.isEmpty()) lines.removeFirst();
    for (QString& line : lines)
        if (line.endsWith(QLatin1Char('\r'))) line.chop(1);
    return lines.mid(std::max<qsizetype>(0, lines.size() - maxLines)).join(QLatin1Char('\n'));
}

QString hexDump(std::span<const std::uint8_t> bytes, std::size_t maxBytes)
{
    const std::size_t count = std::min(bytes.size(), maxBytes);
    const auto tail = bytes.subspan(bytes.size() - count);
    QStringList rows;
    for (std::size_t row = 0; row < tail.size(); row += 16) {
        QString hex, ascii;
        for (std::size_t i = row; i < std::min(row + 16, tail.size()); ++i) {
            hex += QStringLiteral("%1 ").arg(tail[i], 2, 16, QLatin1Char('0'));
            ascii += tail[i] >= 0x20 && tail[i] < 0x7f ? QChar(tail[i]) : QLatin1Char('.');
        }
        rows << QStringLiteral("-%1  %2 %3").arg(tail.size() - row, 4, 16, QLatin1Char('0')).arg(hex, -48).arg(ascii);
    }
    return rows.join(QLatin1Char('\n'));
}

RawConsole::RawConsole(QWidget* parent)
    : QWidget(parent),
      m_counters(new QLabel(this)),
      m_text(new QPlainTextEdit(this)),
      m_freeze(new QCheckBox(tr("Freeze"), this))
{
    m_counters->setObjectName(QStringLiteral("decoderCounters"));
    m_text->setObjectName(QStringLiteral("rawText"));
    m_counters->setWordWrap(true);
    m_counters->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_text->setReadOnly(true);
    m_text->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_freeze->setToolTip(tr("Stop updating, to read or copy what is shown"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_counters);
    layout->addWidget(m_text, 1);
    layout->addWidget(m_freeze);
    m_timer.setInterval(kRefresh_ms);
    connect(&m_timer, &QTimer::timeout, this, &RawConsole::refresh);
    setSource(nullptr);
}

void RawConsole::watch(const LiveStation& station)
{
    connect(&station, &LiveStation::connected, this, [this, &station] { setSource(&station.device()->source()); });
    connect(&station, &LiveStation::disconnecting, this, [this] { setSource(nullptr); });  // before the source goes
}

void RawConsole::setSource(const devices::BlockSource* source)
{
    m_source = source;
    if (m_source) {
        m_timer.start();
        refresh();
        return;
    }
    m_timer.stop();
    m_counters->setText(tr("Not connected."));
    m_text->clear();
}

void RawConsole::refresh()
{
    if (!m_source || m_freeze->isChecked() || !isVisible()) return;
    const auto bytes = m_source->recentBytes();
    const auto c = m_source->decoderCounters();
    if (bytes.empty() && c.bytes == 0) {
        m_counters->setText(tr("This source has no wire (the simulator): nothing to show."));
        m_text->clear();
        return;
    }
    const QLocale l;
    const auto n = [&l](std::uint64_t v) { return l.toString(static_cast<qulonglong>(v)); };
    const bool text = m_source->textProtocol();
    QString line = tr("%1 bytes · %2 good %3 · %4 CRC errors · %5 resyncs · %6 malformed · %7 lines skipped · "
                      "%8 samples lost")
                       .arg(n(c.bytes), n(c.frames), text ? tr("lines") : tr("frames"), n(c.crcErrors), n(c.resyncs),
                            n(c.malformedPayloads), n(c.linesSkipped), n(c.samplesLost));
    // A text board's values that were no number ("nan"): holes in their channel alone.
    if (c.valueHoles > 0) line += tr(" · %1 values no number (holes)").arg(n(c.valueHoles));
    // What the firmware got wrong, shown once it has.
    if (c.sequenceFaults > 0) line += tr(" · %1 sequence faults").arg(n(c.sequenceFaults));
    if (c.deviceRestarts > 0) line += tr(" · %1 device restarts").arg(n(c.deviceRestarts));
    m_counters->setText(line);
    m_text->setPlainText(text ? lastLines(bytes, kLines) : hexDump(bytes, kHexBytes));
    m_text->moveCursor(QTextCursor::End);
}

}  // namespace tactiscope::ui
