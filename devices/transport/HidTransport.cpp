// HID report framing and the thin hidapi layer.
#include "devices/transport/HidTransport.h"

#include "devices/transport/ReadAheadTransport.h"

#include <hidapi.h>

#include <algorithm>
#include <cwchar>

namespace tactiscope::devices::transport {
namespace {

std::string narrow(const wchar_t* text)
{
    if (!text) return {};
    std::string out;
    for (; *text; ++text) out.push_back(*text < 128 ? static_cast<char>(*text) : '?');
    return out;
}

void initialiseHidapi()
{
    static const int result = hid_init();
    if (result != 0) throw TransportError("cannot initialise hidapi");
}

class HidApiReportReader final : public ReportReader {
public:
    explicit HidApiReportReader(const std::string& path)
        : m_path(path)
    {
        initialiseHidapi();
        m_device = hid_open_path(path.c_str());
        if (!m_device)
            throw TransportError("cannot open HID device " + path +
                                 " (check the Tactiscope udev rules, or that another program is not using it)");
    }
    ~HidApiReportReader() override { hid_close(m_device); }
    HidApiReportReader(const HidApiReportReader&) = delete;
    HidApiReportReader& operator=(const HidApiReportReader&) = delete;

    std::string description() const override { return "HID " + m_path; }

    std::optional<std::vector<std::uint8_t>> readReport(std::chrono::milliseconds timeout) override
    {
        std::vector<std::uint8_t> report(kHidReportSize);
        const int n = hid_read_timeout(m_device, report.data(), report.size(), static_cast<int>(timeout.count()));
        if (n < 0)
            throw TransportError(m_path + ": the HID device was disconnected (" + narrow(hid_error(m_device)) + ")");
        if (n == 0) return std::nullopt;
        report.resize(static_cast<std::size_t>(n));
        return report;
    }

    void writeReport(std::span<const std::uint8_t> report) override
    {
        // Report ID 0 first: the device uses unnumbered reports.
        std::vector<std::uint8_t> bytes{0};
        bytes.insert(bytes.end(), report.begin(), report.end());
        if (hid_write(m_device, bytes.data(), bytes.size()) < 0)
            throw TransportError(m_path + ": HID write failed (" + narrow(hid_error(m_device)) + ")");
    }

private:
    std::string m_path;
    hid_device* m_device = nullptr;
};

}  // namespace

std::optional<std::vector<std::uint8_t>> hidReportPayload(std::span<const std::uint8_t> report)
{
    if (report.empty()) return std::nullopt;
    const std::size_t n = report[0];
    if (n == 0 || n > kHidReportPayload || n + 1 > report.size()) return std::nullopt;
    return std::vector<std::uint8_t>(report.begin() + 1, report.begin() + 1 + static_cast<std::ptrdiff_t>(n));
}

std::vector<std::array<std::uint8_t, kHidReportSize>> packHidReports(std::span<const std::uint8_t> bytes)
{
    std::vector<std::array<std::uint8_t, kHidReportSize>> reports;
    for (std::size_t i = 0; i < bytes.size(); i += kHidReportPayload) {
        std::array<std::uint8_t, kHidReportSize> report{};
        const std::size_t n = std::min(kHidReportPayload, bytes.size() - i);
        report[0] = static_cast<std::uint8_t>(n);
        std::copy_n(bytes.begin() + static_cast<std::ptrdiff_t>(i), n, report.begin() + 1);
        reports.push_back(report);
    }
    return reports;
}

HidTransport::HidTransport(std::unique_ptr<ReportReader> reader)
    : m_reader(std::move(reader))
{
}

std::size_t HidTransport::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout)
{
    if (m_queue.empty()) {
        if (auto report = m_reader->readReport(timeout)) {
            if (auto payload = hidReportPayload(*report))
                m_queue.insert(m_queue.end(), payload->begin(), payload->end());
            else
                ++m_malformed;
        }
    }
    const std::size_t n = std::min(buffer.size(), m_queue.size());
    std::copy_n(m_queue.begin(), n, buffer.begin());
    m_queue.erase(m_queue.begin(), m_queue.begin() + static_cast<std::ptrdiff_t>(n));
    return n;
}

void HidTransport::write(std::span<const std::uint8_t> bytes)
{
    const std::lock_guard lock(m_writeMutex);
    for (const auto& report : packHidReports(bytes)) m_reader->writeReport(report);
}

std::vector<HidDeviceInfo> listHidDevices(std::optional<std::uint16_t> vendorId, std::optional<std::uint16_t> productId)
{
    initialiseHidapi();
    std::vector<HidDeviceInfo> result;
    hid_device_info* list = hid_enumerate(vendorId.value_or(0), productId.value_or(0));
    for (hid_device_info* d = list; d; d = d->next) {
        result.push_back({d->path ? d->path : "", d->vendor_id, d->product_id, narrow(d->serial_number),
                          narrow(d->manufacturer_string), narrow(d->product_string)});
    }
    hid_free_enumeration(list);
    return result;
}

std::unique_ptr<Transport> openHidTransport(const std::string& path)
{
    return std::make_unique<ReadAheadTransport>(
        std::make_unique<HidTransport>(std::make_unique<HidApiReportReader>(path)));
}

}  // namespace tactiscope::devices::transport
