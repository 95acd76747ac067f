// What Help → About says: the version from the build (git describe), the
// three papers Tactiscope implements, the licence and what it is built on.
#pragma once

#include <QString>

namespace tactiscope::ui {

QString aboutText();  // rich text

}  // namespace tactiscope::ui
