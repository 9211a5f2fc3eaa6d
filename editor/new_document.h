#pragma once
// File ▸ New's two starting points, as documents never saved: an empty scenario, or one character
// on the built-in humanoid standing in the demo's idle motion (its database named where the demo
// keeps it, since the new scenario has no folder yet).

#include <QString>

#include <memory>

#include "editor/document.h"
#include "util/error.h"

namespace thespis::editor {

/// `demoScenario` is the built-in demo's file (for its idle motion); `folder` where the new
/// document's files are looked for until it is saved.
core::Result<std::unique_ptr<Document>> newDocument(bool withCharacter, const QString& demoScenario, const QString& folder);

} // namespace thespis::editor
