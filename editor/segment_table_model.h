#pragma once
// SegmentTableModel: the mesh segments of one character's body as a table — segment, H-Anim
// joint, role (none / receiver / occluder), vertex and triangle counts — for
// the segment tag editor (paper §6.1.3). Rows follow the body's segment order, so a row is also
// the segment's index in the rendered body (ScenePreview's picks and highlights).
//
// The body comes from core::scenario::loadCharacterBody without the scenario's tags, and is
// cached per character of the document: it is loaded again only when what decides it (skeleton
// level, model file, folder) changes. Roles shown are the document's segment tags, read again
// after every edit, undo and redo. Changing them — one cell (setData) or many rows at once (applyTags) —
// pushes one undoable setSegmentTags edit to the document.

#include <QAbstractTableModel>
#include <QPointer>
#include <QString>

#include <cstdint>
#include <map>
#include <vector>

#include "scene/character_mesh.h"
#include "util/error.h"

class QColor;

namespace thespis::editor {

class Document;

class SegmentTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { SegmentColumn, JointColumn, RoleColumn, VerticesColumn, TrianglesColumn, ColumnCount };

    explicit SegmentTableModel(QObject* parent = nullptr);
    ~SegmentTableModel() override;

    /// The document whose tags are shown and edited (null: an empty table). Forgets the bodies
    /// cached for the previous document.
    void setDocument(Document* document);
    Document* document() const { return m_document; }
    /// Shows the segments of character `character` of the document (-1 or out of range: none).
    void setCharacter(int character);
    int character() const { return m_character; }
    /// Why the shown character's body could not be loaded (file, field and reason); empty when
    /// it was.
    QString loadError() const { return m_loadError; }

    /// The row of a segment by name, -1 when the body has none.
    int rowOf(const QString& segment) const;
    QString segmentName(int row) const;
    QString jointName(int row) const;
    core::scene::SegmentRole role(int row) const;

    /// Sets the role of the segments in `rows` as one undoable edit ("Tag 3 Segments"). A segment
    /// tagged back to role None loses its tag. Changing nothing pushes nothing. Errors (no
    /// document, a refused edit) say why.
    core::Result<void> applyTags(const std::vector<int>& rows, core::scene::SegmentRole role);

    static QString roleText(core::scene::SegmentRole role);       ///< "None", "Receiver", "Occluder"
    static QString roleDescription(core::scene::SegmentRole role); ///< what the role does, one sentence
    /// The colour that stands for a role in the table and on the panel's buttons.
    static QColor roleColor(core::scene::SegmentRole role);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    /// Display texts; EditRole of Role is the enum's integer value; tool tips.
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    /// Role cells take the enum's integer value (EditRole); one undoable edit each.
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

signals:
    /// An edit that could not be made (setData), for the panel's message line.
    void problem(const QString& message);
    /// The rows were replaced (another character, another document, the body reloaded).
    void segmentsReloaded();

private:
    struct SegmentRow {
        QString name;
        QString joint;
        std::uint32_t vertices = 0;
        std::uint32_t triangles = 0;
    };
    struct Body {
        std::string key; // what the body depends on (skeleton, model, folder)
        std::vector<SegmentRow> rows;
        QString error;
    };
    // Loads (or takes from the cache) the body of m_character, and reads the document's tags.
    void reload();
    void onDocumentEdited();
    const Body* loadBody(int character);
    std::string bodyKey(int character) const;
    const core::scene::SegmentTag* tagOf(int row) const;

    QPointer<Document> m_document;
    int m_character = -1;
    std::vector<SegmentRow> m_rows;
    std::vector<core::scene::SegmentTag> m_tags; // the document's tags of m_character
    QString m_loadError;
    std::map<int, Body> m_bodies; // by character index, for m_document
};

} // namespace thespis::editor
