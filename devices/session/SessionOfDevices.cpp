// SessionOfDevices: the lock, the session row and its end.
#include "devices/session/SessionOfDevices.h"

#include "core/storage/AutomaticVerdict.h"
#include "core/storage/SessionStore.h"
#include "devices/SteadyClock.h"

#include <algorithm>
#include <cctype>

namespace tactiscope::devices::session {
namespace {

// Lower case, runs of anything else than letters and digits as one '-'.
std::string slug(const std::string& text)
{
    std::string name;
    for (const char c : text) {
        if (std::isalnum(static_cast<unsigned char>(c)))
            name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (!name.empty() && name.back() != '-')
            name += '-';
    }
    while (!name.empty() && name.back() == '-') name.pop_back();
    return name;
}

}  // namespace

std::string partName(const DeviceIdentity& identity, std::span<const std::string> taken)
{
    const auto free = [&](const std::string& name) { return std::ranges::find(taken, name) == taken.end(); };
    std::string name = slug(identity.model);
    if (name.empty()) name = "device";
    if (free(name)) return name;
    if (const std::string serial = slug(identity.serial); !serial.empty() && free(name + "-" + serial))
        return name + "-" + serial;
    for (int copy = 2;; ++copy)
        if (free(name + "-" + std::to_string(copy))) return name + "-" + std::to_string(copy);
}

SessionOfDevices::SessionOfDevices(const std::string& storePath, const core::storage::SessionMetadata& metadata)
    : m_storePath(storePath),
      m_lock(core::storage::RecorderLock::acquire(storePath))
{
    core::storage::SessionStore store(storePath);
    store.refuseIfDamaged();
    store.markCrashedSessionsInterrupted();
    m_start_host_s = steadySeconds();
    m_session = store.beginSessionOfDevices(metadata);
}

SessionOfDevices::~SessionOfDevices()
{
    try {
        finish();
    } catch (const core::storage::StorageError&) {  // a reader shows it interrupted (no recorder holds the store)
    }
}

LiveSessionOptions::PartOfSession SessionOfDevices::partFor(const std::string& deviceName) const
{
    return {m_session, deviceName, m_start_host_s};
}

std::optional<core::Verdict> SessionOfDevices::finish()
{
    if (m_finished) return m_verdict;
    m_finished = true;
    core::storage::SessionStore store(m_storePath);
    const auto parts = store.parts(m_session);
    const bool whole = !parts.empty() && std::ranges::all_of(parts, [](const core::storage::SessionPart& p) {
        return p.status == core::SessionStatus::Complete;
    });
    store.endSession(m_session, whole ? core::SessionStatus::Complete : core::SessionStatus::Interrupted);
    // The session's verdict is its parts': lists, filters and the central
    // store read it from the session as from a session of one device.
    std::vector<core::storage::SessionSummary> summaries;
    for (const auto& part : parts)
        if (auto summary = store.session(part.id)) summaries.push_back(std::move(*summary));
    if (const auto decision = core::storage::partsDecision(summaries)) {
        store.decideVerdict(m_session, *decision);
        m_verdict = decision->verdict;
    } else if (const auto why = core::storage::partsUnjudged(summaries); !why.empty()) {
        store.markUnjudged(m_session, why);
    }
    return m_verdict;
}

}  // namespace tactiscope::devices::session
