#pragma once
// ScenarioTreeModel: the scenario as a tree for the outline dock — characters, their layers,
// and the actions of each layer — with the columns Name, Clip, Start (s), Mode, Weight (the
// weight curve's kind and parameters) and Mask. A read-only adapter over a Document; it also
// marks the actions that play at the preview's current time (setTime), so the outline shows
// what the clock is doing. Rebuilt when a document is set; the document must outlive it or be
// replaced first.

#include <QAbstractItemModel>
#include <QIcon>

#include <optional>
#include <vector>

#include "anim/blending_params.h"
#include "anim/curve.h"
#include "util/tick.h"

namespace thespis::editor {

class Document;

/// "cubic fade, in 0.5 s, out 0.5 s" and the like.
QString describeCurve(const core::anim::Curve& curve);
/// "normalized", "additive", "override".
QString describeBlendMode(core::anim::BlendMode mode);

class ScenarioTreeModel final : public QAbstractItemModel {
    Q_OBJECT
public:
    enum Column { NameColumn, ClipColumn, StartColumn, ModeColumn, WeightColumn, MaskColumn, ColumnCount };
    enum class NodeKind { Character, Layer, Action };
    /// Data role: the NodeKind of a row, as int.
    static constexpr int NodeKindRole = Qt::UserRole + 1;
    /// Data role: true for an action that plays at the current time.
    static constexpr int ActiveRole = Qt::UserRole + 2;

    explicit ScenarioTreeModel(QObject* parent = nullptr);

    void setDocument(const Document* document);

    /// What a row is: a character, a layer of it or an action of that layer (indices into the
    /// document; -1 where the row is above that level).
    struct Location {
        NodeKind kind = NodeKind::Character;
        int character = -1, layer = -1, action = -1;
    };
    std::optional<Location> locationOf(const QModelIndex& index) const;
    /// The row of a character (layer -1) or of one of its layers.
    QModelIndex indexOf(int character, int layer = -1) const;
    /// Updates which actions are marked as playing; emits dataChanged only for rows that change.
    void setTime(core::Tick time);

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    struct Node {
        NodeKind kind = NodeKind::Character;
        int character = -1, layer = -1, action = -1;
        int parent = -1; // node index, -1 for top level
        int row = 0;
        std::vector<int> children;
        bool active = false;
    };

    void rebuild();
    const Node* nodeOf(const QModelIndex& index) const;
    QVariant displayData(const Node& node, int column) const;
    QString toolTip(const Node& node) const;
    bool actionActive(const Node& node, core::Tick time) const;

    const Document* m_document = nullptr;
    std::vector<Node> m_nodes;
    std::vector<int> m_topLevel;
    QIcon m_activeIcon, m_idleIcon;
    std::vector<QIcon> m_characterIcons;
};

} // namespace thespis::editor
