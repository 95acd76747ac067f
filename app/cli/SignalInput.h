// Where the signal tools (spectrum, health) read samples from: a CSV file,
// imported first into a temporary store so it is read exactly as
// `import` reads it (time column, units, missing rows as gaps), or a
// session of a store (--db F --session N). Either way the samples come
// from one SessionSource, gaps read as NaN.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/storage/SessionSource.h"

#include <QCommandLineParser>
#include <QString>
#include <QTemporaryDir>

#include <memory>
#include <optional>

namespace tactiscope::cli {

struct SignalInput {
    std::unique_ptr<QTemporaryDir> scratch;  // a CSV's temporary store
    std::unique_ptr<core::storage::SessionSource> store;
    std::int64_t session = 0;
    QString name;  // the file, or "session N"
    double sampleRate_hz = 0.0;
    std::uint64_t sampleCount = 0;
    std::vector<core::storage::StoredChannel> channels;
};

// --db and --session, and FILE.csv's --rate and --time-column (as import takes them).
void addSignalInputOptions(QCommandLineParser& parser);

// Opens what the command line names; on failure prints the error and
// returns the exit code (2 for a bad argument or file, 1 for a store that
// could not be read).
std::optional<int> openSignalInput(const QCommandLineParser& parser, const QString& command, const QString& usage,
                                   SignalInput& input);

// The index of the channel called `name`; none, after printing the
// channels there are, when there is none.
std::optional<std::size_t> findSignalChannel(const SignalInput& input, const QString& name, const QString& command,
                                             const std::vector<core::ChannelDescriptor>& computed = {});

// A stored value (SI) as shown: strain in µε, force in mN, capacitance in
// pF, length in mm; another unit as it is.
struct ShownUnit {
    std::string unit;
    double scale = 1.0;  // shown per stored
};
ShownUnit shownUnit(const core::ChannelDescriptor& channel);

}  // namespace tactiscope::cli
