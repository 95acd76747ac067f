// LivePipeline: the devices, the session they record into, and each
// poll's news.
#include "devices/session/LivePipeline.h"

#include "core/storage/SessionStore.h"
#include "devices/session/SessionOfDevices.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::devices::session {
namespace {

bool linkEnded(const LiveSession& live)
{
    const auto state = live.stats().state;
    return state == AcquisitionState::Finished || state == AcquisitionState::Failed;
}

bool sameStatus(const TriggerStatus& a, const TriggerStatus& b)
{
    return a.state == b.state && a.sessionsCut == b.sessionsCut;
}

}  // namespace

LivePipeline::LivePipeline(std::string storePath)
    : m_storePath(std::move(storePath))
{
}

LivePipeline::~LivePipeline()
{
    clear();
}

std::optional<std::string> LivePipeline::add(std::unique_ptr<BlockSource> source, LiveSessionOptions options,
                                             std::string name)
{
    if (isRecording()) return "a session keeps the devices it started with; stop recording first";
    if (triggerArmed()) return "the armed trigger records one device; disarm it first";
    if (!source) throw std::invalid_argument("a device needs a source");
    const auto taken = names();
    if (name.empty())
        name = partName(source->identity(), taken);
    else if (std::ranges::find(taken, name) != taken.end())
        return "there is a device called '" + name + "' already";
    options.storePath = m_storePath;
    Device device;
    device.name = std::move(name);
    device.live = std::make_unique<LiveSession>(std::move(source), std::move(options));
    m_devices.push_back(std::move(device));
    return std::nullopt;
}

std::optional<std::string> LivePipeline::remove(std::size_t index)
{
    if (index >= m_devices.size()) return "there is no such device";
    if (isRecording()) return "a session keeps the devices it started with; stop recording first";
    if (triggerArmed()) return "the armed trigger records this device; disarm it first";
    m_devices.erase(m_devices.begin() + static_cast<std::ptrdiff_t>(index));
    return std::nullopt;
}

void LivePipeline::clear()
{
    disarmTrigger();
    stopRecording();
    m_devices.clear();
    m_toldTrigger.reset();
}

std::vector<std::string> LivePipeline::names() const
{
    std::vector<std::string> result;
    for (const Device& device : m_devices) result.push_back(device.name);
    return result;
}

void LivePipeline::start()
{
    for (Device& device : m_devices)
        if (!std::exchange(device.started, true)) device.live->start();
}

bool LivePipeline::streaming() const
{
    return std::ranges::any_of(m_devices, [](const Device& d) { return !linkEnded(*d.live); });
}

std::optional<std::string> LivePipeline::setStorePath(const std::string& path)
{
    if (isRecording()) return "a recording keeps its session store to its end";
    for (Device& device : m_devices)
        if (auto refusal = device.live->setStorePath(path)) return refusal;
    m_storePath = path;
    return std::nullopt;
}

bool LivePipeline::isRecording() const
{
    return several() || std::ranges::any_of(m_devices, [](const Device& d) { return d.live->isRecording(); });
}

std::int64_t LivePipeline::sessionId() const
{
    if (several()) return m_devicesSession->sessionId();
    return m_devices.empty() ? 0 : m_devices.front().live->sessionId();
}

bool LivePipeline::recordingComplete() const
{
    return !m_devices.empty() &&
           std::ranges::all_of(m_devices, [](const Device& d) { return d.live->recordingComplete(); });
}

std::optional<std::string> LivePipeline::startRecording(const core::storage::SessionMetadata& request,
                                                        std::optional<double> length_s)
{
    if (isRecording()) return std::nullopt;
    if (m_devices.empty()) return "there is no device to record";
    if (triggerArmed()) return "the armed trigger starts the recordings; disarm it first";
    if (m_devices.size() == 1) return m_devices.front().live->startRecording(request, length_s);
    // The session lists in its first device's mode (the one the GUI's views read).
    auto whole = request;
    whole.mode = m_devices.front().live->mode();
    try {
        m_devicesSession = std::make_unique<SessionOfDevices>(m_storePath, whole);
    } catch (const core::storage::StorageError& e) {
        return e.what();
    }
    for (std::size_t i = 0; i < m_devices.size(); ++i) {
        Device& device = m_devices[i];
        device.endedPart.reset();
        if (auto refusal = device.live->startRecordingPart(request, m_devicesSession->partFor(device.name), length_s)) {
            for (std::size_t j = 0; j < i; ++j) m_devices[j].live->stopRecording();
            m_devicesSession.reset();  // ends interrupted: nothing of it was meant to be
            return device.name + ": " + *refusal;
        }
    }
    return std::nullopt;
}

std::optional<RecordingEnd> LivePipeline::stopRecording()
{
    if (several()) return finishSeveral();
    for (Device& device : m_devices)
        if (auto summary = device.live->stopRecording()) return endOfOne(std::move(*summary), false);
    return std::nullopt;
}

// Each part's end (those ended early kept theirs), then the session's,
// with its parts' verdict.
RecordingEnd LivePipeline::finishSeveral()
{
    RecordingEnd end;
    end.session = m_devicesSession->sessionId();
    end.subject = m_devices.front().live->recordingMetadata().subject;
    for (Device& device : m_devices) {
        auto summary = device.live->isRecording() ? device.live->stopRecording() : std::exchange(device.endedPart, {});
        if (summary) end.parts.push_back({device.name, std::move(*summary)});
    }
    try {
        end.verdict = m_devicesSession->finish();
    } catch (const core::storage::StorageError&) {  // the parts are stored; a reader shows the session interrupted
    }
    m_devicesSession.reset();
    return end;
}

RecordingEnd LivePipeline::endOfOne(RecordingSummary summary, bool triggered) const
{
    RecordingEnd end;
    end.session = summary.session;
    end.subject = m_devices.front().live->recordingMetadata().subject;
    end.triggered = triggered;
    end.verdict = summary.verdict;
    end.parts.push_back({tellName(m_devices.front()), std::move(summary)});
    return end;
}

std::optional<std::string> LivePipeline::armTrigger(const core::trigger::TriggerSettings& settings,
                                                    const core::storage::SessionMetadata& request)
{
    if (m_devices.empty()) return "there is no device to watch";
    if (m_devices.size() > 1)
        return "a trigger records one device: a session of several devices is started and stopped by hand";
    if (isRecording()) return "a recording is running; stop it before arming the trigger";
    return m_devices.front().live->armTrigger(settings, request);
}

std::optional<RecordingEnd> LivePipeline::disarmTrigger()
{
    if (!triggerArmed()) return std::nullopt;
    auto open = m_devices.front().live->disarmTrigger();
    if (!open) return std::nullopt;
    return endOfOne(std::move(*open), true);
}

bool LivePipeline::triggerArmed() const
{
    return m_devices.size() == 1 && m_devices.front().live->triggerArmed();
}

TriggerStatus LivePipeline::triggerStatus() const
{
    return triggerArmed() ? m_devices.front().live->triggerStatus() : TriggerStatus{};
}

// The name a device's news carry: none for the only device of a session of one.
std::string LivePipeline::tellName(const Device& device) const
{
    return m_devices.size() == 1 ? std::string() : device.name;
}

PipelineNews LivePipeline::poll()
{
    PipelineNews news;
    for (Device& device : m_devices) pollDevice(device, news);
    // A session of several ends once its last part has.
    if (several() && std::ranges::none_of(m_devices, [](const Device& d) { return d.live->isRecording(); })) {
        news.partsEnded.clear();  // they are the session's end, told with it
        news.ended.push_back(finishSeveral());
    }
    if (triggerArmed() || m_toldTrigger) {
        const auto status = triggerStatus();
        if (!m_toldTrigger || !sameStatus(*m_toldTrigger, status)) news.trigger = status;
        m_toldTrigger = triggerArmed() ? std::optional(status) : std::nullopt;
    }
    return news;
}

// One device's news; a recording (or a part) it ended, by the disk, the
// trigger, or a link that failed or finished for good: a link gone records
// nothing more, so its recording ends with what came before.
void LivePipeline::pollDevice(Device& device, PipelineNews& news)
{
    LiveSession& live = *device.live;
    const std::string name = tellName(device);
    auto ended = live.poll();
    for (auto& problem : live.takeProblems()) news.problems.push_back({name, std::move(problem)});
    for (auto& notice : live.takeLinkNotices()) news.notices.push_back({name, std::move(notice)});
    for (auto& alarm : live.takeAlarms()) news.alarms.push_back({name, std::move(alarm)});
    for (auto& start : live.takeTriggeredStarts()) news.triggered.push_back(start);
    for (auto& summary : live.takeTriggeredSummaries()) news.ended.push_back(endOfOne(std::move(summary), true));
    if (auto refusal = live.takeTriggerRefusal()) news.triggerRefused = std::move(refusal);
    if (!ended && live.isRecording() && linkEnded(live)) ended = live.stopRecording();
    if (!ended) return;
    if (several()) {
        device.endedPart = *ended;
        news.partsEnded.push_back({device.name, std::move(*ended)});
    } else {
        news.ended.push_back(endOfOne(std::move(*ended), live.triggerArmed()));
    }
}

}  // namespace tactiscope::devices::session
