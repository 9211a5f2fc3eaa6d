#pragma once
// ClipSettingsBox: on an action's Properties page, the settings of a synthesized clip the action
// plays (idle motion, blinks). The clip is the character's, so every action playing it changes
// with it; each change is one undoable command (edit::replaceClip). Subclasses add the fields.

#include <QGroupBox>

#include <functional>
#include <string>

#include "scenario/scenario.h"

namespace thespis::editor {

class Document;

class ClipSettingsBox : public QGroupBox {
    Q_OBJECT
public:
    using QGroupBox::QGroupBox;

signals:
    void problem(const QString& message);

protected:
    /// Finds the clip named `clip` of `character` that `accept` takes, remembers it for
    /// editClip and shows the box only when there is one.
    const core::scenario::ClipAsset* find(Document* document, int character, const std::string& clip,
                                          const std::function<bool(const core::scenario::ClipAsset&)>& accept);
    /// Replaces the clip found with `change` applied, as one command named `text` (nothing while
    /// the fields are being refreshed).
    void editClip(const QString& text, const std::function<void(core::scenario::ClipAsset&)>& change);

    Document* document() const { return m_document; }
    bool m_refreshing = false; ///< set while show() fills the fields: not user input

private:
    Document* m_document = nullptr;
    int m_character = -1;
    int m_clip = -1;
};

} // namespace thespis::editor
