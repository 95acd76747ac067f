// Writes the store fuzzer's hand-made seeds (fuzz/corpus/store/seed-*) at
// this build's store version: one store per kind of session a reviewer
// reads (a panel scan with its trail, notes and a gap; a palpation with its
// readings and zeros; a capacitive beam; a session of two devices; a
// general session that gained a channel), and the damages attacks found,
// each a panel scan changed by hand as `sqlite3` would. Small pages keep
// every file under the fuzz run's -max_len. Run by fuzz/make-store-seeds.sh.
//   tactiscope_make_store_seeds FOLDER
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

constexpr double kRate_hz = 500.0;

// Samples [first, first + count) of `channels` channels: a slow sine each.
SampleBlock block(std::size_t channels, std::uint64_t first, std::size_t count)
{
    SampleBlock b(channels, count, static_cast<double>(first) / kRate_hz, 1.0 / kRate_hz, first);
    for (std::size_t c = 0; c < channels; ++c)
        for (std::size_t s = 0; s < count; ++s)
            b.channel(c)[s] = 1e-5 * std::sin(0.05 * static_cast<double>(first + s) + static_cast<double>(c));
    return b;
}

// A new store file at `path` with 1 KiB pages, its schema made by SessionStore.
void startFile(const std::string& path)
{
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
    Database(path, Database::Access::ReadWrite).exec("PRAGMA page_size = 1024");
}

// The file made whole and small: its log written back, unused pages gone,
// nothing beside it (the recorder's lock a read-write open leaves).
void finishFile(const std::string& path)
{
    {
        Database db(path, Database::Access::ReadWrite);
        db.exec("PRAGMA journal_mode = DELETE");
        db.exec("VACUUM");
    }
    std::filesystem::remove(path + "-recorder.lock");
}

std::int64_t panelScan(SessionStore& store)
{
    SessionMetadata m;
    m.subject = "door-17";
    m.operatorName = "Ada";
    m.site = "line 3";
    m.deviceModel = "TSP-2";
    m.deviceSerial = "0042";
    m.trigger = "a>2e-05, pre 0.5 s, post 1 s, hold-off 0 s";
    const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain, ChannelRole::CantileverA},
                                                  {"b", "", ChannelKind::Strain, ChannelRole::CantileverB}};
    const auto id = store.beginSession(m, channels, kRate_hz);
    store.appendBlocks(id, std::vector{block(2, 0, 150), block(2, 170, 150)});  // 20 lost between
    store.markLostUntil(id, 330);
    const SessionEvent defect{.kind = EventKind::Defect,
                              .start_s = 0.1,
                              .end_s = 0.15,
                              .direction = 1,
                              .peakR = 0.93,
                              .lag_s = 0.004,
                              .speed_m_per_s = 0.05,
                              .note = {}};
    SessionEvent again = defect;
    again.analysis = "threshold 0.8";
    SessionEvent alarm;
    alarm.kind = EventKind::Alarm;
    alarm.start_s = alarm.end_s = 0.3;
    alarm.note = "a above 1e-05";
    store.addEvents(id, std::vector{defect, again, alarm});
    store.decideVerdict(id, {0, VerdictRole::Automatic, Verdict::DefectsFound, "", "2026-11-28T10:00:00.000Z", "",
                             "{\"analysis\":\"live\",\"defects\":1}"});
    store.decideVerdict(id,
                        {0, VerdictRole::Operator, Verdict::Pass, "Ada", "2026-11-28T10:01:00.000Z", "a smudge", ""});
    store.addAnnotation(id, {0, 0.12, "Ada", "oil on the panel", "", ""});
    store.endSession(id, SessionStatus::Complete);
    return id;
}

void palpation(SessionStore& store)
{
    SessionMetadata m;
    m.mode = Mode::Palpation;
    m.subject = "phantom-2";
    m.site = "B2";
    const std::vector<ChannelDescriptor> channels{{"high", "N", ChannelKind::Force, ChannelRole::StiffBeam},
                                                  {"low", "N", ChannelKind::Force, ChannelRole::SoftBeam},
                                                  {"d", "m", ChannelKind::Position, ChannelRole::Displacement}};
    const auto id = store.beginSession(m, channels, kRate_hz);
    store.appendBlocks(id, std::vector{block(3, 0, 200)});
    store.addZero(id, {0, "{\"high\":0.01,\"low\":0.002}"});
    store.addZero(id, {120, "{\"high\":0.011,\"low\":0.002}"});
    SessionReading stiffness;
    stiffness.start_s = 0.1;
    stiffness.end_s = 0.3;
    stiffness.quantity = "stiffness";
    stiffness.value = 199.96;
    stiffness.unit = "N/m";
    stiffness.standardError = 0.41;
    stiffness.site = "B2";
    stiffness.detailsJson = "{\"q\":0.6}";
    store.addReading(id, stiffness);
    store.markUnjudged(id, "too short to judge (0.4 s of presses)");
    store.endSession(id, SessionStatus::Interrupted);
}

void capacitive(SessionStore& store)
{
    SessionMetadata m;
    m.mode = Mode::Capacitive;
    const std::vector<ChannelDescriptor> channels{{"c", "F", ChannelKind::Capacitance, ChannelRole::Capacitance}};
    const auto id = store.beginSession(m, channels, kRate_hz);
    store.appendBlocks(id, std::vector{block(1, 0, 200)});
    SessionReading force;
    force.kind = ReadingKind::Capacitive;
    force.start_s = 0.0;
    force.end_s = 0.4;
    force.quantity = "force";
    force.value = 12.5;
    force.unit = "uN";
    store.addReading(id, force);
    store.endSession(id, SessionStatus::Complete);
}

void devices(SessionStore& store)
{
    SessionMetadata m;
    m.subject = "door-18";
    const auto id = store.beginSessionOfDevices(m);
    for (const char* name : {"probe", "load-cell"}) {
        SessionMetadata part = m;
        part.partOf = id;
        part.deviceName = name;
        const std::vector<ChannelDescriptor> channels{{std::string(name) + "-x", "", ChannelKind::Strain}};
        const auto p = store.beginSession(part, channels, kRate_hz);
        store.appendBlocks(p, std::vector{block(1, 0, 100)});
        store.endSession(p, SessionStatus::Complete);
    }
    store.endSession(id, SessionStatus::Complete);
}

void general(SessionStore& store)
{
    SessionMetadata m;
    m.mode = Mode::General;
    const std::vector<ChannelDescriptor> first{{"t1", "degC", ChannelKind::Other}};
    const auto id = store.beginSession(m, first, kRate_hz);
    store.appendBlocks(id, std::vector{block(1, 0, 100)});
    const std::vector<ChannelDescriptor> added{{"t2", "degC", ChannelKind::Other}};
    store.addChannels(id, added);
    store.appendBlocks(id, std::vector{block(2, 100, 100)});
    store.endSession(id, SessionStatus::Complete);
}

// A store of one session written by `write`, at FOLDER/seed-NAME.
template <typename Write>
std::string seed(const std::string& folder, const std::string& name, Write write)
{
    const std::string path = folder + "/seed-" + name;
    startFile(path);
    {
        SessionStore store(path);
        write(store);
    }
    finishFile(path);
    return path;
}

// A panel scan damaged by `sql`, as an attack or a hand edit left it.
void damaged(const std::string& folder, const std::string& name, const std::string& sql)
{
    const std::string path = seed(folder, "damaged-" + name, [](SessionStore& store) { panelScan(store); });
    // As a hand edit can: the schema's checks off.
    Database(path, Database::Access::ReadWrite).exec("PRAGMA ignore_check_constraints = ON; " + sql);
    finishFile(path);
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: tactiscope_make_store_seeds FOLDER\n";
        return 2;
    }
    const std::string folder = argv[1];
    try {
        seed(folder, "panel", [](SessionStore& store) { panelScan(store); });
        seed(folder, "palpation", palpation);
        seed(folder, "capacitive", capacitive);
        seed(folder, "devices", devices);
        seed(folder, "general", general);
        // Issue 36's damages, then issue 54's.
        damaged(folder, "first-index", "UPDATE chunks SET first_index = 4000000000000000000 WHERE first_index = 0");
        damaged(folder, "gap", "INSERT INTO gaps VALUES (1, 330, 4611686018427387904)");
        damaged(folder, "channels", "DELETE FROM channels");
        damaged(folder, "negative-count", "UPDATE chunks SET count = -5");
        damaged(folder, "huge-count", "UPDATE chunks SET count = 1099511627776");
        damaged(folder, "chunk-outside", "UPDATE chunks SET first_index = -250 WHERE first_index = 0");
        damaged(folder, "missing-chunk", "DELETE FROM chunks WHERE first_index = 0");
    } catch (const std::exception& e) {
        std::cerr << "tactiscope_make_store_seeds: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
