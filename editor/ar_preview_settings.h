#pragma once
// What ar_preview_panel.cpp and ar_preview_inputs.cpp (the two halves of ArPreviewPanel) share:
// the panel's remembered choices under "arPreview/" in QSettings, its default board and the
// style of its error lines.

#include <QSettings>
#include <QString>
#include <QVariant>

namespace thespis::editor::ar_preview {

inline const QString kErrorStyle = QStringLiteral("color: #c0392b;");
/// A 4 × 3 grid of 4 cm ArUco markers, 1 cm apart (the README's AR examples use it too).
inline const QString kDefaultBoard = QStringLiteral("aruco-grid:DICT_4X4_50:4x3:0.04:0.01");
inline const QString kSettingsGroup = QStringLiteral("arPreview/");

inline QString setting(const char* key, const QString& fallback = {})
{
    return QSettings().value(kSettingsGroup + QLatin1String(key), fallback).toString();
}

inline void storeSetting(const char* key, const QVariant& value)
{
    QSettings().setValue(kSettingsGroup + QLatin1String(key), value);
}

} // namespace thespis::editor::ar_preview
