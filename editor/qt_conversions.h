#pragma once
// Conversions between the std types core uses (UTF-8 std::string, std::filesystem::path) and
// Qt's. One place, so that file names with non-ASCII characters are handled the same everywhere.

#include <QFile>
#include <QString>

#include <filesystem>
#include <string>

namespace thespis::editor {

/// A Qt file name as a path in the local 8-bit file name encoding (what the OS expects).
inline std::filesystem::path toFsPath(const QString& path)
{
    return std::filesystem::path(QFile::encodeName(path).toStdString());
}

inline QString fromFsPath(const std::filesystem::path& path)
{
    return QFile::decodeName(QByteArray::fromStdString(path.native()));
}

inline QString fromUtf8(const std::string& text)
{
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

} // namespace thespis::editor
