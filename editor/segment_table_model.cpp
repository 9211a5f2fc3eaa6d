#include "editor/segment_table_model.h"

#include <QColor>
#include <QFont>
#include <QGuiApplication>
#include <QLocale>
#include <QPalette>

#include <algorithm>

#include "edit/document_edits.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "scenario/scenario_character.h"

namespace thespis::editor {

using core::scene::SegmentRole;
using core::scene::SegmentTag;

SegmentTableModel::SegmentTableModel(QObject* parent) : QAbstractTableModel(parent) {}

SegmentTableModel::~SegmentTableModel() = default;

void SegmentTableModel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_bodies.clear();
    if (m_document)
        connect(m_document, &Document::edited, this, &SegmentTableModel::onDocumentEdited);
    m_character = -1;
    reload();
}

void SegmentTableModel::setCharacter(int character)
{
    if (character == m_character)
        return;
    m_character = character;
    reload();
}

std::string SegmentTableModel::bodyKey(int character) const
{
    const core::scenario::Character& spec = m_document->scenario().characters[std::size_t(character)];
    // The procedural body depends on the skeleton's level, a model body on its file; a '\n'
    // cannot occur in either.
    return spec.skeleton + '\n' + spec.model + '\n' + m_document->baseDir().toStdString();
}

const SegmentTableModel::Body* SegmentTableModel::loadBody(int character)
{
    const std::string key = bodyKey(character);
    if (auto found = m_bodies.find(character); found != m_bodies.end() && found->second.key == key)
        return &found->second;

    // A scenario holding only what decides the body (not the clips, layers or tags), with the
    // character at its own index so that errors name it as the document does.
    const core::scenario::Character& spec = m_document->scenario().characters[std::size_t(character)];
    core::scenario::Scenario bare;
    bare.characters.resize(std::size_t(character) + 1);
    core::scenario::Character& copy = bare.characters[std::size_t(character)];
    copy.name = spec.name;
    copy.skeleton = spec.skeleton;
    copy.model = spec.model;
    copy.extra = spec.extra;

    Body body;
    body.key = key;
    auto loaded = core::scenario::loadCharacterBody(bare, std::size_t(character), m_document->assets());
    if (loaded) {
        for (const core::scene::Segment& segment : loaded->mesh.segments)
            body.rows.push_back({fromUtf8(segment.name), fromUtf8(segment.joint), segment.vertexCount,
                                 segment.triangleCount});
    } else {
        body.error = fromUtf8(loaded.error().message);
    }
    return &(m_bodies[character] = std::move(body));
}

void SegmentTableModel::reload()
{
    beginResetModel();
    m_rows.clear();
    m_tags.clear();
    m_loadError.clear();
    if (!m_document || m_character < 0 || std::size_t(m_character) >= m_document->scenario().characters.size()) {
        m_character = -1;
    } else {
        const Body* body = loadBody(m_character);
        m_rows = body->rows;
        m_loadError = body->error;
        m_tags = m_document->scenario().characters[std::size_t(m_character)].segmentTags;
    }
    endResetModel();
    emit segmentsReloaded();
}

void SegmentTableModel::onDocumentEdited()
{
    if (!m_document)
        return;
    const auto& characters = m_document->scenario().characters;
    if (m_character < 0 || std::size_t(m_character) >= characters.size()
        || bodyKey(m_character) != m_bodies[m_character].key) {
        // The character is gone or its body changed: the rows change too.
        if (m_character >= 0 && std::size_t(m_character) >= characters.size())
            m_character = characters.empty() ? -1 : 0;
        reload();
        return;
    }
    // Bodies of other characters may be stale now; they are checked when shown.
    const auto& tags = characters[std::size_t(m_character)].segmentTags;
    if (tags == m_tags)
        return;
    m_tags = tags;
    if (!m_rows.empty())
        emit dataChanged(index(0, RoleColumn), index(int(m_rows.size()) - 1, RoleColumn));
}

int SegmentTableModel::rowOf(const QString& segment) const
{
    for (std::size_t r = 0; r < m_rows.size(); ++r)
        if (m_rows[r].name == segment)
            return int(r);
    return -1;
}

QString SegmentTableModel::segmentName(int row) const
{
    return row >= 0 && std::size_t(row) < m_rows.size() ? m_rows[std::size_t(row)].name : QString();
}

QString SegmentTableModel::jointName(int row) const
{
    return row >= 0 && std::size_t(row) < m_rows.size() ? m_rows[std::size_t(row)].joint : QString();
}

const SegmentTag* SegmentTableModel::tagOf(int row) const
{
    if (row < 0 || std::size_t(row) >= m_rows.size())
        return nullptr;
    const std::string name = m_rows[std::size_t(row)].name.toStdString();
    for (const SegmentTag& tag : m_tags)
        if (tag.segment == name)
            return &tag;
    return nullptr;
}

SegmentRole SegmentTableModel::role(int row) const
{
    const SegmentTag* tag = tagOf(row);
    return tag ? tag->role : SegmentRole::None;
}

core::Result<void> SegmentTableModel::applyTags(const std::vector<int>& rows, SegmentRole role)
{
    if (!m_document || m_character < 0)
        return core::makeError(core::ErrorCode::InvalidArgument, tr("No character is shown.").toStdString());
    std::vector<SegmentTag> tags = m_document->scenario().characters[std::size_t(m_character)].segmentTags;
    int count = 0;
    for (int row : rows) {
        if (row < 0 || std::size_t(row) >= m_rows.size())
            continue;
        ++count;
        const std::string name = m_rows[std::size_t(row)].name.toStdString();
        auto tag = std::find_if(tags.begin(), tags.end(), [&](const SegmentTag& t) { return t.segment == name; });
        if (tag == tags.end()) {
            tags.push_back({name, SegmentRole::None});
            tag = tags.end() - 1;
        }
        tag->role = role;
        if (tag->role == SegmentRole::None)
            tags.erase(tag);
    }
    if (count == 0)
        return {};
    return m_document->edit(core::edit::setSegmentTags(m_document->scenario(), m_character, std::move(tags)),
                            tr("Tag %n Segment(s)", nullptr, count));
}

QString SegmentTableModel::roleText(SegmentRole role)
{
    switch (role) {
    case SegmentRole::None: return tr("None");
    case SegmentRole::Receiver: return tr("Receiver");
    case SegmentRole::Occluder: return tr("Occluder");
    }
    return {};
}

QString SegmentTableModel::roleDescription(SegmentRole role)
{
    switch (role) {
    case SegmentRole::None: return tr("Casts shadows and receives them.");
    case SegmentRole::Receiver:
        return tr("Receives shadows but casts none: left out of the shadow proxy (hair, loose clothes).");
    case SegmentRole::Occluder:
        return tr("Casts shadows but is not lit itself: no transfer is baked for it (props, phantom geometry).");
    }
    return {};
}

QColor SegmentTableModel::roleColor(SegmentRole role)
{
    switch (role) {
    case SegmentRole::None: return QColor(0x8a, 0x90, 0x99);
    case SegmentRole::Receiver: return QColor(0x3d, 0x8e, 0xe0);
    case SegmentRole::Occluder: return QColor(0xa8, 0x5c, 0xd6);
    }
    return {};
}

int SegmentTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int SegmentTableModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant SegmentTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || std::size_t(index.row()) >= m_rows.size())
        return {};
    const SegmentRow& row = m_rows[std::size_t(index.row())];
    const SegmentRole segmentRole = this->role(index.row());
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case SegmentColumn: return row.name;
        case JointColumn: return row.joint.isEmpty() ? tr("(root)") : row.joint;
        case RoleColumn: return roleText(segmentRole);
        case VerticesColumn: return QLocale().toString(qulonglong(row.vertices));
        case TrianglesColumn: return QLocale().toString(qulonglong(row.triangles));
        }
        break;
    case Qt::EditRole:
        switch (index.column()) {
        case RoleColumn: return int(segmentRole);
        case VerticesColumn: return qulonglong(row.vertices);
        case TrianglesColumn: return qulonglong(row.triangles);
        default: return data(index, Qt::DisplayRole);
        }
    case Qt::DecorationRole:
        if (index.column() == RoleColumn)
            return roleColor(segmentRole);
        break;
    case Qt::ForegroundRole:
        // Values nobody set (role None) recede; tags stand out.
        if ((index.column() == RoleColumn && segmentRole == SegmentRole::None) || index.column() == VerticesColumn
            || index.column() == TrianglesColumn)
            return QGuiApplication::palette().color(QPalette::PlaceholderText);
        break;
    case Qt::TextAlignmentRole:
        if (index.column() == VerticesColumn || index.column() == TrianglesColumn)
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        break;
    case Qt::ToolTipRole:
        switch (index.column()) {
        case SegmentColumn:
        case JointColumn:
            return tr("Segment %1 follows joint %2").arg(row.name, row.joint.isEmpty() ? tr("(root)") : row.joint);
        case RoleColumn: return roleText(segmentRole) + QStringLiteral(": ") + roleDescription(segmentRole);
        }
        break;
    default: break;
    }
    return {};
}

bool SegmentTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (role != Qt::EditRole || !index.isValid() || std::size_t(index.row()) >= m_rows.size())
        return false;
    bool ok = false;
    const int number = value.toInt(&ok);
    core::Result<void> done;
    if (index.column() == RoleColumn && ok && number >= 0 && number <= int(SegmentRole::Occluder))
        done = applyTags({index.row()}, SegmentRole(number));
    else
        return false;
    if (!done) {
        emit problem(fromUtf8(done.error().message));
        return false;
    }
    return true;
}

QVariant SegmentTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::DisplayRole) {
        switch (section) {
        case SegmentColumn: return tr("Segment");
        case JointColumn: return tr("Joint");
        case RoleColumn: return tr("Role");
        case VerticesColumn: return tr("Vertices");
        case TrianglesColumn: return tr("Triangles");
        }
    } else if (role == Qt::ToolTipRole) {
        switch (section) {
        case SegmentColumn: return tr("The mesh segment (paper §6.1.3)");
        case JointColumn: return tr("The H-Anim joint whose frame the segment follows");
        case RoleColumn:
            return tr("Receiver: in shadow but casts none. Occluder: casts shadows, not lit. None: both.");
        case VerticesColumn: return tr("Vertices of the segment");
        case TrianglesColumn: return tr("Triangles of the segment");
        }
    } else if (role == Qt::TextAlignmentRole && (section == VerticesColumn || section == TrianglesColumn)) {
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    }
    return {};
}

Qt::ItemFlags SegmentTableModel::flags(const QModelIndex& index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags result = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.column() == RoleColumn)
        result |= Qt::ItemIsEditable;
    return result;
}

} // namespace thespis::editor
