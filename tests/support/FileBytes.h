// A file's whole content as bytes, to check that a file was left untouched.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace tactiscope::testing {

inline std::string fileBytes(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    return content.str();
}

}  // namespace tactiscope::testing
