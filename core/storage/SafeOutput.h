// Writing a file that a command or a window produces (an export, a report,
// the detector's outputs) so that it can neither destroy an input nor be
// left half written: refused when it is the same file as one being read
// (compared by device and inode, not by name, so links and "./x" are
// caught), written to a temporary beside it with every write and the close
// checked, then renamed over the target. A full disk leaves no partial file.
// The temporary is a new file of an unguessable name (mkstemp: O_EXCL, so
// no existing file or link is ever opened through it).
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace tactiscope::core::storage {

// The files of a store: itself, its WAL and shared memory, its recorder lock.
std::vector<std::string> storeFiles(const std::string& storePath);

// Throws StorageError naming both when `output` is one of `inputs`.
void refuseOverwriting(const std::string& output, const std::vector<std::string>& inputs);

// Writes through `write` to a new hidden temporary beside `path`
// (".NAME.XXXXXX"), synced to the disk, then renames it to `path`.
// Throws StorageError (the temporary removed) when any of it fails; an
// exception from `write` itself removes the temporary and goes on.
void writeAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace tactiscope::core::storage
