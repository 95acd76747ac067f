// A second device a calibration wizard reads a reference force from
// (issue 40): a load cell on another board, opened from its port's path
// (a serial port, an emulator's link) through a handshake off the GUI
// thread (DeviceConnector), streamed by an acquisition of its own into a
// live buffer, its clock mapped onto the host's as it streams. It lives
// as long as the wizard; the window's device is not touched. A device
// already in the session is never opened here: the wizard reads it there.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/timing/ClockAlignment.h"
#include "ui/calibration/CalibrationContext.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace tactiscope::devices {
class Acquisition;
class BlockSource;
}  // namespace tactiscope::devices

namespace tactiscope::ui {

class DeviceConnector;

class ReferenceLink : public QObject {
    Q_OBJECT

public:
    explicit ReferenceLink(QObject* parent = nullptr);
    ~ReferenceLink() override;  // stops its acquisition

    // Connects to the device at `path` (TSP/1, 921600 Bd); a device already
    // open goes first.
    void open(const QString& path);
    void close();

    bool isOpen() const { return m_acquisition != nullptr; }
    QString deviceName() const { return m_name; }
    const std::vector<core::ChannelDescriptor>& channels() const { return m_channels; }
    std::shared_ptr<const core::LiveBuffer> buffer() const { return m_buffer; }
    double sampleRate_hz() const { return m_rate_hz; }
    std::optional<core::timing::ClockMapping> hostClock() const;
    // What the wizard reads a reference from; the link outlives no wizard.
    ReferenceDevice reference() const;

signals:
    void opened();
    void failed(const QString& why);

private:
    void start(std::unique_ptr<devices::BlockSource> source);

    DeviceConnector* m_connector;
    std::unique_ptr<devices::Acquisition> m_acquisition;
    std::shared_ptr<core::LiveBuffer> m_buffer;
    std::vector<core::ChannelDescriptor> m_channels;
    QString m_name;
    double m_rate_hz = 0.0;
};

}  // namespace tactiscope::ui
