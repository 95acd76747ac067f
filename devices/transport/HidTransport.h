// USB HID as a byte stream (docs/protocol.md, "HID"): TSP/1 bytes travel in
// vendor-defined 64-byte reports whose byte 0 is the number n (1…63) of
// valid bytes that follow in bytes 1…n; the rest is padding. Input reports
// are drained into a queue, so decoders see one continuous stream and never
// know about reports; a frame may span any number of reports. Commands go
// out the same way as output reports.
//
// The hidapi layer is kept thin behind ReportReader, so the framing is tested
// with recorded reports (no HID device exists on the test machines).
#pragma once

#include "devices/transport/Transport.h"

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace tactiscope::devices::transport {

inline constexpr std::size_t kHidReportSize = 64;
inline constexpr std::size_t kHidReportPayload = kHidReportSize - 1;

// The valid bytes of a report, or nothing for a malformed one (n = 0 or
// n larger than the report holds).
std::optional<std::vector<std::uint8_t>> hidReportPayload(std::span<const std::uint8_t> report);
// Bytes cut into padded reports.
std::vector<std::array<std::uint8_t, kHidReportSize>> packHidReports(std::span<const std::uint8_t> bytes);

// Report-level access to one HID device.
class ReportReader {
public:
    virtual ~ReportReader() = default;
    virtual std::string description() const = 0;
    // One input report, or nothing on timeout; throws TransportError when
    // the device is gone.
    virtual std::optional<std::vector<std::uint8_t>> readReport(std::chrono::milliseconds timeout) = 0;
    virtual void writeReport(std::span<const std::uint8_t> report) = 0;
};

class HidTransport final : public Transport {
public:
    explicit HidTransport(std::unique_ptr<ReportReader> reader);

    std::string description() const override { return m_reader->description(); }
    std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
    void write(std::span<const std::uint8_t> bytes) override;
    std::uint64_t malformedReports() const { return m_malformed; }

private:
    std::unique_ptr<ReportReader> m_reader;
    std::deque<std::uint8_t> m_queue;
    std::uint64_t m_malformed = 0;
    std::mutex m_writeMutex;
};

struct HidDeviceInfo {
    std::string path;
    std::uint16_t vendorId = 0;
    std::uint16_t productId = 0;
    std::string serialNumber, manufacturer, product;
};

// HID devices, optionally only those with the given vendor and product ids.
std::vector<HidDeviceInfo> listHidDevices(std::optional<std::uint16_t> vendorId = std::nullopt,
                                          std::optional<std::uint16_t> productId = std::nullopt);
// A transport on a device found by listHidDevices(). Throws TransportError.
std::unique_ptr<Transport> openHidTransport(const std::string& path);

}  // namespace tactiscope::devices::transport
