// Replays the kept fuzzing corpus (fuzz/corpus/) through the same entry
// points the libFuzzer targets use, with whatever compiler built the suite:
// an input that once crashed a decoder or the CSV reader keeps being checked.
#include "FuzzEntryPoints.h"

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

// Store files: two valid ones (a panel scan and a palpation) and the
// five damages an attack found (a first index of 4e18, a gap of 2^62, the
// channel rows deleted, a negative and a 2^40 chunk count), each read
// whole as a reviewer's store: refused with a StorageError, never a crash,
// an allocation of gigabytes or NaN rows without end.
TEST(FuzzCorpusReplay, StoreFilesSurviveEveryKeptInput)
{
    EXPECT_GE(replay(TACTISCOPE_SOURCE_DIR "/fuzz/corpus/store", tactiscope::fuzz::storeFile), 7u);
}
