// ImportedRecording: a temporary store in a temporary directory.
#include "RecordingImport.h"

namespace tactiscope::cli {

ImportedRecording::ImportedRecording(const std::string& path, core::Mode mode)
{
    if (!m_dir.isValid())
        throw core::storage::StorageError("cannot create a temporary directory: " + m_dir.errorString().toStdString());
    m_store =
        std::make_unique<core::storage::SessionStore>(m_dir.filePath(QStringLiteral("recording.db")).toStdString());
    core::storage::CsvImportOptions options;
    options.mode = mode;
    m_result = core::storage::importCsv(*m_store, path, options);
    if (const auto summary = m_store->session(m_result.session)) m_metadata = summary->metadata;
}

}  // namespace tactiscope::cli
