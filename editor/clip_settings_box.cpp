#include "editor/clip_settings_box.h"

#include "edit/content_edits.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"

namespace thespis::editor {

const core::scenario::ClipAsset* ClipSettingsBox::find(Document* document, int character, const std::string& clip,
                                                      const std::function<bool(const core::scenario::ClipAsset&)>& accept)
{
    m_document = document;
    m_character = -1;
    m_clip = -1;
    const core::scenario::ClipAsset* found = nullptr;
    if (document && character >= 0 && std::size_t(character) < document->scenario().characters.size()) {
        const auto& clips = document->scenario().characters[std::size_t(character)].clips;
        for (std::size_t i = 0; i < clips.size(); ++i)
            if (clips[i].name == clip && accept(clips[i])) {
                found = &clips[i];
                m_character = character;
                m_clip = int(i);
            }
    }
    setVisible(found != nullptr);
    return found;
}

void ClipSettingsBox::editClip(const QString& text, const std::function<void(core::scenario::ClipAsset&)>& change)
{
    if (m_refreshing || !m_document || m_clip < 0)
        return;
    core::scenario::ClipAsset clip = m_document->scenario().characters[std::size_t(m_character)].clips[std::size_t(m_clip)];
    change(clip);
    const auto done = m_document->edit(core::edit::replaceClip(m_document->scenario(), {m_character, m_clip}, std::move(clip)), text);
    if (!done)
        emit problem(tr("%1: %2").arg(text, fromUtf8(done.error().message)));
}

} // namespace thespis::editor
