// RecordDevices: the devices opened, named and recorded as parts of one
// session; the lines told at the end.
#include "RecordDevices.h"

#include "CliSupport.h"
#include "ProbePort.h"
#include "core/ModeCapability.h"
#include "core/storage/SessionStore.h"
#include "core/timing/ClockMappingText.h"
#include "devices/session/LiveSession.h"
#include "devices/session/SessionOfDevices.h"

#include <QLocale>
#include <QTextStream>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

namespace tactiscope::cli {

namespace {

bool isDeviceName(const std::string& name)
{
    return !name.empty() && std::ranges::none_of(name, [](char c) { return c == '/' || c == '=' || c == ' '; });
}

struct Device {
    std::string name;
    std::unique_ptr<devices::session::LiveSession> live;
    const devices::BlockSource* source = nullptr;
    std::optional<devices::session::RecordingSummary> summary;
    devices::AcquisitionStats acquired;
};

}  // namespace

std::optional<std::vector<ProbePortArgument>> parseProbePorts(const QStringList& values)
{
    std::vector<ProbePortArgument> ports;
    for (const QString& value : values) {
        const auto equals = value.indexOf(QLatin1Char('='));
        ProbePortArgument port{{}, value.toStdString()};
        if (equals >= 0) {
            port.name = value.left(equals).toStdString();
            port.path = value.mid(equals + 1).toStdString();
            if (!isDeviceName(port.name) || port.path.empty()) return std::nullopt;
            if (std::ranges::any_of(ports, [&](const ProbePortArgument& p) { return p.name == port.name; }))
                return std::nullopt;
        }
        ports.push_back(std::move(port));
    }
    if (ports.empty()) return std::nullopt;
    return ports;
}

int recordDevices(const DevicesRecording& setup)
{
    // Each device's roles, by the name before its channel's.
    std::map<std::string, core::RoleAssignment> roles;
    for (const auto& [key, role] : setup.roles) {
        const auto slash = key.find('/');
        if (slash == std::string::npos || slash == 0 || slash + 1 == key.size()) {
            printError(QStringLiteral("--roles: with several devices, name each channel as DEVICE/CHANNEL ('%1')")
                           .arg(toQString(key)));
            return kExitUsage;
        }
        roles[key.substr(0, slash)][key.substr(slash + 1)] = role;
    }
    std::vector<Device> devices;
    std::vector<std::unique_ptr<devices::ReconnectingSource>> sources;
    for (const ProbePortArgument& port : setup.ports) {
        try {
            sources.push_back(openProbePort(port.path, setup.baud, setup.options));
        } catch (const std::exception& e) {
            printError(QStringLiteral("%1: %2").arg(toQString(port.path), toQString(e.what())));
            return kExitFailure;
        }
        Device device;
        device.name = port.name;
        devices.push_back(std::move(device));
    }
    // Names not given come from the devices, unlike the given ones and each other.
    std::vector<std::string> taken;
    for (const ProbePortArgument& port : setup.ports)
        if (!port.name.empty()) taken.push_back(port.name);
    for (std::size_t i = 0; i < devices.size(); ++i)
        if (devices[i].name.empty()) {
            devices[i].name = devices::session::partName(sources[i]->identity(), taken);
            taken.push_back(devices[i].name);
        }
    for (const auto& [name, assignment] : roles)
        if (std::ranges::none_of(devices, [&](const Device& d) { return d.name == name; })) {
            printError(QStringLiteral("--roles: there is no device '%1'").arg(toQString(name)));
            return kExitUsage;
        }

    std::unique_ptr<devices::session::SessionOfDevices> session;
    try {
        session = std::make_unique<devices::session::SessionOfDevices>(setup.db, setup.metadata);
    } catch (const core::storage::StorageError& e) {
        printError(toQString(e.what()));
        return kExitUsage;
    }
    for (std::size_t i = 0; i < devices.size(); ++i) {
        Device& device = devices[i];
        devices::session::LiveSessionOptions options;
        options.storePath = setup.db;
        options.roles = roles[device.name];
        options.partOf = session->partFor(device.name);
        device.source = sources[i].get();
        try {
            device.live = std::make_unique<devices::session::LiveSession>(std::move(sources[i]), options);
        } catch (const std::invalid_argument& e) {
            printError(QStringLiteral("--roles: %1: %2").arg(toQString(device.name), toQString(e.what())));
            return kExitUsage;
        }
        auto& live = *device.live;
        if (const auto refusal = live.setMode(live.declaredMode())) {
            printError(QStringLiteral("%1: %2").arg(toQString(device.name), toQString(*refusal)));
            return kExitUsage;
        }
        live.setSite(setup.metadata.site);
        if (const auto refused = live.startRecording(setup.metadata)) {
            printError(QStringLiteral("%1: %2").arg(toQString(device.name), toQString(*refused)));
            return kExitFailure;
        }
    }
    installStopSignals();
    for (Device& device : devices) device.live->start();

    const auto start = std::chrono::steady_clock::now();
    const auto at = [](double time_s) { return QLocale::c().toString(time_s, 'f', 1); };
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        bool running = false;
        for (Device& device : devices) {
            if (device.summary) continue;
            device.summary = device.live->poll();  // the disk stopped this one
            for (const auto& notice : device.live->takeLinkNotices())
                printError(QStringLiteral("%1: at %2 s: %3")
                               .arg(toQString(device.name), at(notice.time_s), toQString(notice.text)));
            const auto state = device.live->stats().state;
            running = running || (!device.summary && state != devices::AcquisitionState::Finished &&
                                  state != devices::AcquisitionState::Failed);
        }
        const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!running || stopRequested() || (setup.seconds && elapsed_s >= *setup.seconds)) break;
    }
    for (Device& device : devices) {
        device.acquired = device.live->stats();
        if (!device.summary) device.summary = device.live->stopRecording();
    }
    try {
        session->finish();
    } catch (const core::storage::StorageError& e) {
        printError(toQString(e.what()));
    }

    // What was stored, read back: each part's gaps and clock.
    int exit = kExitOk;
    std::vector<core::storage::SessionPart> parts;
    std::map<std::int64_t, std::uint64_t> lost;
    try {
        core::storage::SessionStore readBack(setup.db, core::storage::Database::Access::ReadOnly);
        parts = readBack.parts(session->sessionId());
        for (const auto& part : parts)
            for (const auto& gap : readBack.gaps(part.id)) lost[part.id] += gap.count;
    } catch (const core::storage::StorageError& e) {
        printError(toQString(e.what()));
        exit = kExitFailure;
    }
    QTextStream out(stdout);
    out << "Recorded session " << session->sessionId() << ": " << devices.size() << " devices, into "
        << toQString(setup.db) << Qt::endl;
    for (const Device& device : devices) {
        if (!device.summary) {
            out << "  " << toQString(device.name) << ": not recorded" << Qt::endl;
            exit = kExitFailure;
            continue;
        }
        const auto& summary = *device.summary;
        const auto part = std::ranges::find_if(parts, [&](const auto& p) { return p.id == summary.session; });
        out << "  " << toQString(device.name) << " (session " << summary.session
            << "): " << summary.stats.samplesWritten << " samples per channel, " << lost[summary.session] << " lost, "
            << device.source->decoderCounters().crcErrors << " CRC errors (" << device.live->channels().size()
            << " channels at " << QLocale::c().toString(device.source->nominalSampleRate_hz()) << " Hz); "
            << toQString(core::toString(device.live->recordingMetadata().mode)) << ": " << toQString(summary.analysis)
            << "; "
            << "clock: " << toQString(core::timing::clockMappingText(part != parts.end() ? part->clockJson : ""))
            << Qt::endl;
        if (!summary.stats.error.empty()) {
            printError(QStringLiteral("%1: %2").arg(toQString(device.name), toQString(summary.stats.error)));
            exit = kExitFailure;
        } else if (summary.lostAt_s) {
            printError(QStringLiteral("%1: the probe was lost at %2 s and did not come back; %3 samples kept")
                           .arg(toQString(device.name), at(*summary.lostAt_s))
                           .arg(summary.stats.samplesWritten));
            exit = kExitFailure;
        }
    }
    return exit;
}

}  // namespace tactiscope::cli
