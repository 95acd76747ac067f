// A store is one file, whatever name it is reached by. SQLite names its
// write-ahead files (-wal, -shm) beside the file it opens, resolving a
// symbolic link to its target; Tactiscope's recorder lock and every
// "is this the store?" check use that same resolved name, so a store
// reached through a link is the same store (one recorder, and a sync skips
// the session being recorded through any name). A hard link has no name
// to resolve to: two names would be two write-ahead logs of one file, and
// a recording through one would be lost through the other, so a store with
// several names is refused.
#pragma once

#include <string>

namespace tactiscope::core::storage {

// The store's own file name: symbolic links (of the file and of its
// folders) resolved; a store not yet made resolved as far as its folder.
std::string realStorePath(const std::string& path);

// Throws StoreInputError when the file has more than one name (hard links),
// saying why and what to do.
void refuseSeveralNames(const std::string& path);

}  // namespace tactiscope::core::storage
