#pragma once
// BlinkProperties: on the Properties page of an action that plays blinks (a face layer's blink
// generator, core/motion/blink_synthesizer.h), the blink clip's settings — blinks a minute (about
// 17 at rest, 26 in conversation), the seed of the random intervals, the closing, shut and
// opening times. Shared by the actions playing the clip, one undoable command per change.

#include "editor/clip_settings_box.h"

class QDoubleSpinBox;
class QSpinBox;

namespace thespis::editor {

class BlinkProperties : public ClipSettingsBox {
    Q_OBJECT
public:
    explicit BlinkProperties(QWidget* parent = nullptr);

    /// Shows the blink clip `clip` of `character` (hidden when that clip is not blinks).
    void show(Document* document, int character, const std::string& clip, bool editable);

    QDoubleSpinBox* rateEdit() const { return m_rate; }
    QSpinBox* seedEdit() const { return m_seed; }
    QSpinBox* closeEdit() const { return m_close; }
    QSpinBox* shutEdit() const { return m_shut; }
    QSpinBox* openEdit() const { return m_open; }

private:
    QDoubleSpinBox* m_rate = nullptr;
    QSpinBox* m_seed = nullptr;
    QSpinBox* m_close = nullptr; ///< milliseconds
    QSpinBox* m_shut = nullptr;
    QSpinBox* m_open = nullptr;
};

} // namespace thespis::editor
