// LinkStatus: the counters from the acquisition and the reconnecting source.
#include "ui/device/LinkStatus.h"

#include "devices/Acquisition.h"
#include "devices/ReconnectingSource.h"
#include "ui/common/NumberText.h"

#include <QLocale>
#include <QObject>

namespace tactiscope::ui {

LinkCounters linkCounters(const devices::AcquisitionStats& stats, const devices::BlockSource& source)
{
    LinkCounters counters;
    counters.rate_hz = stats.measuredRate_hz;
    counters.nominalRate_hz = source.nominalSampleRate_hz();
    counters.nominalMeasured = source.rateNote().has_value();
    counters.nominalRateU_hz = source.rateUncertainty_hz();
    counters.samples = stats.samples;
    counters.samplesLost = stats.samplesLost;
    switch (stats.state) {
    case devices::AcquisitionState::Idle:
        counters.state = QObject::tr("Idle");
        break;
    case devices::AcquisitionState::Streaming:
        counters.state = QObject::tr("Streaming");
        break;
    case devices::AcquisitionState::Finished:
        counters.state = QObject::tr("Finished");
        break;
    case devices::AcquisitionState::Failed:
        counters.state = QObject::tr("Failed: %1").arg(QString::fromStdString(stats.error));
        counters.healthy = false;
        break;
    }
    // A device away (unplugged) is still "streaming" to the acquisition.
    if (const auto* reconnecting = dynamic_cast<const devices::ReconnectingSource*>(&source)) {
        counters.decoder = reconnecting->decoderCounters();
        counters.reconnections = reconnecting->reconnections();
        switch (reconnecting->state()) {
        case devices::DeviceState::Lost:
            counters.state = QObject::tr("Device lost");
            counters.healthy = false;
            break;
        case devices::DeviceState::Reconnecting:
            counters.state = QObject::tr("Reconnecting…");
            counters.healthy = false;
            break;
        case devices::DeviceState::Streaming:
            break;
        }
    }
    return counters;
}

QString linkLine(const LinkCounters& counters)
{
    QString line = counters.state;
    if (counters.rate_hz) line += QObject::tr(" · %1 Hz").arg(fixedText(*counters.rate_hz, 1));
    if (counters.samplesLost > 0)
        line += QObject::tr(" · %1 lost").arg(QLocale().toString(static_cast<qulonglong>(counters.samplesLost)));
    return line;
}

}  // namespace tactiscope::ui
