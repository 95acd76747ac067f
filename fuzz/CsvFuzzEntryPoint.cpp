// Fuzz entry point for the CSV reader: the input is written to a file in
// memory (memfd) and read as an import reads it: the header, every row,
// every cell as a number. A CsvError is the reader doing its job; anything
// else (a crash, a row of the wrong width, an infinity) is a finding.
#include "FuzzEntryPoints.h"

#include "core/io/CsvReader.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cmath>
#include <string>

namespace tactiscope::fuzz {

void csvReader(const std::uint8_t* data, std::size_t size)
{
    const int fd = ::memfd_create("fuzz.csv", MFD_CLOEXEC);
    if (fd < 0) return;
    if (::write(fd, data, size) == static_cast<ssize_t>(size)) {
        try {
            core::io::CsvReader reader("/proc/self/fd/" + std::to_string(fd));
            std::vector<std::string_view> fields;
            while (reader.next(fields)) {
                if (fields.size() != reader.header().size()) __builtin_trap();
                for (std::size_t c = 0; c < fields.size(); ++c) {
                    if (fields[c].empty()) continue;  // a missing value
                    if (std::isinf(reader.number(fields[c], c))) __builtin_trap();
                }
            }
        } catch (const core::io::CsvError&) {
            // Refused with a message: what a bad file should get.
        }
    }
    ::close(fd);
}

}  // namespace tactiscope::fuzz
