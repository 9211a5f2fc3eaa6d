#pragma once
// Merge keys of the commands a drag pushes step by step (Document::Merge). Steps with the same
// key merge into one undo command until the step that finishes the drag (STYLE.md §5).

namespace thespis::editor {

enum CommandId : int {
    MoveActionsId = 1,
    TrimActionId,
    FadeActionId,
    MoveMarkerId,
    MoveCurveKeysId,
    CurveTangentId,
    PaintMaskId,
    CurveParameterId,
};

} // namespace thespis::editor
