#include "editor/new_document.h"

#include <QCoreApplication>

#include "edit/content_edits.h"
#include "editor/qt_conversions.h"
#include "scenario/scenario_io.h"

namespace thespis::editor {

core::Result<std::unique_ptr<Document>> newDocument(bool withCharacter, const QString& demoScenario, const QString& folder)
{
    core::scenario::Scenario scenario;
    scenario.name = QCoreApplication::translate("thespis::editor::newDocument", "New scenario").toStdString();
    scenario.duration = 10 * core::TicksPerSecond;
    if (withCharacter) {
        core::scenario::Character actor = core::edit::newCharacter(
            QCoreApplication::translate("thespis::editor::newDocument", "Actor").toStdString(), "", "hanim-25");
        const std::filesystem::path demoPath = toFsPath(demoScenario);
        const auto demo = core::scenario::loadScenario(demoPath);
        const core::scenario::ClipAsset* idle =
            demo && !demo->characters.empty() ? demo->characters[0].findClip("creon_idle") : nullptr;
        if (idle && idle->idle) {
            core::scenario::ClipAsset clip = *idle;
            clip.name = "idle";
            clip.idle->database = (demoPath.parent_path() / clip.idle->database).lexically_normal().string();
            actor.clips.push_back(std::move(clip));
            core::scenario::ActionSpec stand;
            stand.name = "idle";
            stand.clip = "idle";
            actor.layers[0].actions.push_back(stand);
        }
        scenario.characters.push_back(actor);
    }
    return Document::fromScenario(std::move(scenario), folder);
}

} // namespace thespis::editor
