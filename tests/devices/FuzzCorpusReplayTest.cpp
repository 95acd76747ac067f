// Replays the kept fuzzing corpus (fuzz/corpus/) through the same entry
// points the libFuzzer targets use, with whatever compiler built the suite:
// an input that once crashed a decoder or the CSV reader keeps being checked.
#include "FuzzEntryPoints.h"
#include "core/storage/Schema.h"
#include "core/storage/SessionStore.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

std::size_t replay(const std::string& directory, void (*entry)(const std::uint8_t*, std::size_t))
{
    std::size_t files = 0;
    for (const auto& file : std::filesystem::directory_iterator(directory)) {
        std::ifstream in(file.path(), std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        entry(bytes.data(), bytes.size());
        ++files;
    }
    return files;
}

}  // namespace

TEST(FuzzCorpusReplay, BinaryDecoderSurvivesEveryKeptInput)
{
    EXPECT_GE(replay(TACTISCOPE_SOURCE_DIR "/fuzz/corpus/binary", tactiscope::fuzz::binaryStream), 500u);
}

TEST(FuzzCorpusReplay, TextDecoderSurvivesEveryKeptInput)
{
    EXPECT_GE(replay(TACTISCOPE_SOURCE_DIR "/fuzz/corpus/text", tactiscope::fuzz::textStream), 300u);
}

TEST(FuzzCorpusReplay, CsvReaderSurvivesEveryKeptInput)
{
    EXPECT_GE(replay(TACTISCOPE_SOURCE_DIR "/fuzz/corpus/csv", tactiscope::fuzz::csvReader), 100u);
}

// Store files: one of each kind of session (fuzz/MakeStoreSeeds.cpp) and
// the damages attacks found (a first index of 4e18, a gap of 2^62, the
// channel rows deleted, a negative and a 2^40 chunk count, a chunk before
// its session's start, a missing chunk), each read whole as a reviewer's
// store: refused with a StorageError, never a crash, an allocation of
// gigabytes or NaN rows without end.
TEST(FuzzCorpusReplay, StoreFilesSurviveEveryKeptInput)
{
    EXPECT_GE(replay(TACTISCOPE_SOURCE_DIR "/fuzz/corpus/store", tactiscope::fuzz::storeFile), 12u);
}

// Every kept store seed opens as a current store: a seed of an older
// version (the corpus once held version 5 stores when the store was at 8)
// spends the fuzzer's time on the version check and its private copy,
// never reaching the readers; one that is no store at all tests only the
// refusal. Rerun fuzz/make-store-seeds.sh when this fails.
TEST(FuzzCorpusReplay, EveryStoreSeedIsAtTheCurrentVersion)
{
    using namespace tactiscope::core::storage;
    for (const auto& file : std::filesystem::directory_iterator(TACTISCOPE_SOURCE_DIR "/fuzz/corpus/store")) {
        const std::string copy = (std::filesystem::temp_directory_path() / "tactiscope-seed-check").string();
        for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(copy + suffix);
        std::filesystem::copy_file(file.path(), copy);
        try {
            const SessionStore store(copy, Database::Access::ReadOnly);
            EXPECT_EQ(store.versionFound(), kSchemaVersion)
                << file.path() << " is an older store: run fuzz/make-store-seeds.sh";
        } catch (const StorageError& e) {
            ADD_FAILURE() << file.path() << " does not open as a store (" << e.what()
                          << "): run fuzz/make-store-seeds.sh";
        }
        for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(copy + suffix);
    }
}
