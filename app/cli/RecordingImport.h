// A raw recording — the simulator's CSV, a session export, another DAQ
// program's file — read by the importer (its header units, time column,
// side file and gaps, exactly as `import` reads it) into a session of a
// temporary store, so the analysis commands read it through the same code
// as a stored session. The store lives as long as the object.
#pragma once

#include "core/Vocabulary.h"
#include "core/storage/CsvImport.h"
#include "core/storage/SessionStore.h"

#include <QTemporaryDir>

#include <memory>
#include <string>

namespace tactiscope::cli {

class ImportedRecording {
public:
    // Throws core::io::CsvError for a file the importer refuses and
    // core::storage::StorageError when the temporary store fails.
    ImportedRecording(const std::string& path, core::Mode mode);

    core::storage::SessionStore& store() { return *m_store; }
    std::int64_t session() const { return m_result.session; }
    const core::storage::CsvImportResult& result() const { return m_result; }
    const core::storage::SessionMetadata& metadata() const { return m_metadata; }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<core::storage::SessionStore> m_store;
    core::storage::CsvImportResult m_result;
    core::storage::SessionMetadata m_metadata;
};

}  // namespace tactiscope::cli
