#pragma once
// ScriptTrust: which scenario files the user trusts to run their scripts (a script can do
// whatever the user's account can). Remembered per file content (SHA-256 of its bytes) in the
// settings, so a file changed by someone else asks again; a file the user saved is trusted.

#include <QString>

namespace thespis::editor {

class ScriptTrust {
public:
    /// SHA-256 of the file's bytes (hex), or empty when it cannot be read.
    static QString fileHash(const QString& path);
    static bool isTrusted(const QString& path);
    static void trust(const QString& path);
};

} // namespace thespis::editor
