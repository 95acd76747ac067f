// The application's version string, from `git describe` at configure time.
#pragma once

namespace tactiscope::core {

const char* versionString();

}  // namespace tactiscope::core
