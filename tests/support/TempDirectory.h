// A fresh folder in the temporary directory for one test, named after it
// and removed with everything in it when the test ends: for store files
// and their WAL, lock and export side files.
#pragma once

#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace tactiscope::testing {

class TempDirectoryTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_dir = uniqueTempPath(::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(m_dir);
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }
    std::string file(const std::string& name) const { return (m_dir / name).string(); }

    std::filesystem::path m_dir;
};

}  // namespace tactiscope::testing
