#include "editor/gesticon_model.h"

#include <QLocale>
#include <QPalette>
#include <QRegularExpression>

#include <cmath>
#include <variant>

#include "edit/document_edits.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "util/tick.h"

namespace thespis::editor {

using core::scenario::Gesture;

GesticonModel::GesticonModel(QObject* parent) : QAbstractTableModel(parent)
{
}

void GesticonModel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (m_document)
        connect(m_document, &Document::edited, this, &GesticonModel::onEdited);
    m_character = m_document && !m_document->scenario().characters.empty() ? 0 : -1;
    reset();
}

void GesticonModel::setCharacter(int character)
{
    const bool valid = m_document && character >= 0
                       && std::size_t(character) < m_document->scenario().characters.size();
    m_character = valid ? character : -1;
    reset();
}

const core::scenario::Character* GesticonModel::currentCharacter() const
{
    if (!m_document || m_character < 0 || std::size_t(m_character) >= m_document->scenario().characters.size())
        return nullptr;
    return &m_document->scenario().characters[std::size_t(m_character)];
}

const Gesture* GesticonModel::gesture(int row) const
{
    const core::scenario::Character* character = currentCharacter();
    if (!character || row < 0 || std::size_t(row) >= character->gestures.size() || row >= m_rows)
        return nullptr;
    return &character->gestures[std::size_t(row)];
}

int GesticonModel::rowOf(const QString& name) const
{
    const std::string wanted = name.toStdString();
    for (int row = 0; row < m_rows; ++row)
        if (const Gesture* g = gesture(row); g && g->name == wanted)
            return row;
    return -1;
}

QStringList GesticonModel::clipNames() const
{
    QStringList names;
    if (const core::scenario::Character* character = currentCharacter())
        for (const core::scenario::ClipAsset& clip : character->clips)
            names << fromUtf8(clip.name);
    return names;
}

QStringList GesticonModel::maskNames() const
{
    QStringList names;
    if (m_document)
        for (const core::scenario::NamedMask& mask : m_document->scenario().masks)
            names << fromUtf8(mask.name);
    return names;
}

int GesticonModel::liveRowCount() const
{
    const core::scenario::Character* character = currentCharacter();
    return character ? int(character->gestures.size()) : 0;
}

int GesticonModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : m_rows;
}

int GesticonModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant GesticonModel::data(const QModelIndex& index, int role) const
{
    const Gesture* g = index.isValid() ? gesture(index.row()) : nullptr;
    if (!g)
        return {};
    const int column = index.column();
    if (column == FilterColumn) {
        if (role == Qt::CheckStateRole)
            return g->dependentJointFilter ? Qt::Checked : Qt::Unchecked;
        if (role == Qt::ToolTipRole)
            return g->dependentJointFilter
                       ? tr("The dependent-joint filter runs over this gesture: spine and neck follow it")
                       : tr("Only the joints of the gesture's clip move");
        return {};
    }
    if (column == HoldColumn) {
        if (role == Qt::CheckStateRole)
            return g->hold ? Qt::Checked : Qt::Unchecked;
        if (role == Qt::ToolTipRole)
            return g->hold ? tr("Speech plays it at its own speed and holds its stroke while the words last")
                           : tr("Speech stretches or shrinks it to its words");
        return {};
    }
    if (column == BandColumn && role == Qt::ForegroundRole && !g->dependentJointFilter)
        return QPalette().color(QPalette::Disabled, QPalette::Text); // kept, but the filter is off
    if (role == Qt::TextAlignmentRole)
        return column == FadeInColumn || column == FadeOutColumn || column == StrokeColumn
                   ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                                                                 : QVariant(Qt::AlignLeft | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::EditRole && role != Qt::ToolTipRole)
        return {};
    switch (column) {
    case NameColumn:
        return fromUtf8(g->name);
    case ClipColumn:
        return fromUtf8(g->clip);
    case MaskColumn:
        if (role == Qt::EditRole)
            return fromUtf8(g->mask);
        if (g->mask.empty())
            return role == Qt::ToolTipRole ? tr("The gesture drives every joint its clip has") : tr("Whole body");
        return role == Qt::ToolTipRole ? tr("The gesture drives the joints of mask \"%1\"").arg(fromUtf8(g->mask))
                                       : fromUtf8(g->mask);
    case FadeInColumn:
    case FadeOutColumn: {
        const double seconds = core::ticksToSeconds(column == FadeInColumn ? g->fadeIn : g->fadeOut);
        if (role == Qt::EditRole)
            return seconds;
        return QLocale().toString(seconds, 'f', 2);
    }
    case StrokeColumn:
        if (role == Qt::EditRole)
            return g->stroke;
        if (role == Qt::ToolTipRole)
            return g->stroke < 0 ? tr("No stroke marked: speech fits the gesture as a whole")
                                 : tr("The stroke, %1 s into the clip, falls on the first stressed word of its words")
                                       .arg(QLocale().toString(g->stroke, 'f', 2));
        return g->stroke < 0 ? tr("none") : QLocale().toString(g->stroke, 'f', 2);
    case BandColumn:
        if (role == Qt::ToolTipRole)
            return tr("The filter keeps upper-body PCs 1–%1, fades them out to PC %2 and mutes the rest: a later "
                      "start keeps the gesture closer to its keys")
                .arg(g->filterFadeFrom)
                .arg(g->filterMuteAbove);
        return QStringLiteral("%1–%2").arg(g->filterFadeFrom).arg(g->filterMuteAbove);
    default:
        return {};
    }
}

QVariant GesticonModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return QAbstractTableModel::headerData(section, orientation, role);
    if (role == Qt::DisplayRole) {
        switch (section) {
        case NameColumn: return tr("Name");
        case ClipColumn: return tr("Clip");
        case MaskColumn: return tr("Body part");
        case FadeInColumn: return tr("Fade in (s)");
        case FadeOutColumn: return tr("Fade out (s)");
        case FilterColumn: return tr("Dependent joints");
        case BandColumn: return tr("Filter PCs");
        case HoldColumn: return tr("Holds");
        case StrokeColumn: return tr("Stroke (s)");
        default: return {};
        }
    }
    if (role == Qt::TextAlignmentRole) {
        // As the cells below: numbers on the right, the check box in the middle.
        const Qt::Alignment horizontal =
            section == FadeInColumn || section == FadeOutColumn || section == StrokeColumn ? Qt::AlignRight
            : isCheckColumn(section)                                                     ? Qt::AlignHCenter
                                                                                         : Qt::AlignLeft;
        return QVariant::fromValue(horizontal | Qt::AlignVCenter);
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case NameColumn: return tr("The name speech scripts use to trigger the gesture");
        case ClipColumn: return tr("The character's clip the gesture plays");
        case MaskColumn: return tr("The joint mask that limits the gesture to a body part");
        case FadeInColumn: return tr("How long the gesture takes to blend in, in seconds");
        case FadeOutColumn: return tr("How long the gesture takes to blend out, in seconds");
        case FilterColumn:
            return tr("Dependent-joint filter: joints the gesture does not drive (spine, neck) follow it");
        case BandColumn:
            return tr("The filter's band, e.g. 20–30: PCs kept up to the first, muted above the second (paper: 20–30 of 48)");
        case HoldColumn:
            return tr("Words longer than the gesture: hold its stroke (checked) or stretch it (unchecked)");
        case StrokeColumn:
            return tr("Where the gesture's stroke is in its clip, in seconds: speech puts it on the stressed word");
        default: return {};
        }
    }
    return {};
}

Qt::ItemFlags GesticonModel::flags(const QModelIndex& index) const
{
    if (!index.isValid() || !gesture(index.row()))
        return Qt::NoItemFlags;
    const Qt::ItemFlags base = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    return isCheckColumn(index.column()) ? base | Qt::ItemIsUserCheckable : base | Qt::ItemIsEditable;
}

bool GesticonModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    const Gesture* current = index.isValid() ? gesture(index.row()) : nullptr;
    if (!current || !m_document)
        return false;
    Gesture next = *current;
    QString text;
    const int column = index.column();
    if (column == FilterColumn) {
        if (role != Qt::CheckStateRole)
            return false;
        next.dependentJointFilter = value.value<Qt::CheckState>() == Qt::Checked;
        text = next.dependentJointFilter ? tr("Turn Dependent-Joint Filter On") : tr("Turn Dependent-Joint Filter Off");
    } else if (column == HoldColumn) {
        if (role != Qt::CheckStateRole)
            return false;
        next.hold = value.value<Qt::CheckState>() == Qt::Checked;
        text = next.hold ? tr("Hold Gesture Stroke") : tr("Stretch Gesture to Its Words");
    } else {
        if (role != Qt::EditRole)
            return false;
        switch (column) {
        case NameColumn:
            next.name = value.toString().trimmed().toStdString();
            text = tr("Rename Gesture");
            break;
        case ClipColumn:
            next.clip = value.toString().toStdString();
            text = tr("Change Gesture Clip");
            break;
        case MaskColumn:
            next.mask = value.toString().toStdString();
            text = tr("Change Gesture Body Part");
            break;
        case BandColumn: {
            static const QRegularExpression band(QStringLiteral("^\\s*(\\d+)\\s*[-–]\\s*(\\d+)\\s*$"));
            const QRegularExpressionMatch match = band.match(value.toString());
            if (!match.hasMatch()) {
                emit editFailed(tr("Write the filter's band as two PC numbers, e.g. 30–40."));
                return false;
            }
            next.filterFadeFrom = match.captured(1).toInt();
            next.filterMuteAbove = match.captured(2).toInt();
            text = tr("Change Filter Band");
            break;
        }
        case StrokeColumn: {
            bool ok = false;
            const double seconds = value.toDouble(&ok);
            if (!ok || !std::isfinite(seconds)) {
                emit editFailed(tr("A stroke is a number of seconds into the clip (below 0: none)."));
                return false;
            }
            next.stroke = seconds < 0 ? -1.0 : seconds;
            text = tr("Mark Gesture Stroke");
            break;
        }
        case FadeInColumn:
        case FadeOutColumn: {
            bool ok = false;
            const double seconds = value.toDouble(&ok);
            if (!ok || !std::isfinite(seconds)) {
                emit editFailed(tr("A fade time must be a number of seconds."));
                return false;
            }
            (column == FadeInColumn ? next.fadeIn : next.fadeOut) = core::secondsToTicks(seconds);
            text = column == FadeInColumn ? tr("Change Gesture Fade In") : tr("Change Gesture Fade Out");
            break;
        }
        default:
            return false;
        }
    }
    if (next == *current)
        return true;
    const core::edit::CharacterItemPath path{m_character, index.row()};
    if (auto done = m_document->edit(core::edit::replaceGesture(m_document->scenario(), path, std::move(next)), text);
        !done) {
        emit editFailed(fromUtf8(done.error().message));
        return false;
    }
    emit editSucceeded();
    return true;
}

void GesticonModel::onEdited(const core::edit::Edit& edit)
{
    // Replacing gestures keeps the rows (a rename, a fade): only those rows change. Anything
    // that inserts or removes a gesture of this character resets the table.
    if (m_character >= 0 && std::size_t(m_character) >= m_document->scenario().characters.size())
        m_character = m_document->scenario().characters.empty() ? -1 : 0;
    bool structural = liveRowCount() != m_rows;
    std::vector<int> rows;
    for (const core::edit::Change& change : edit.changes()) {
        const auto* g = std::get_if<core::edit::GestureChange>(&change);
        if (!g || g->at.character != m_character)
            continue;
        if (!g->before || !g->after)
            structural = true;
        else
            rows.push_back(g->at.index);
    }
    if (structural) {
        reset();
        return;
    }
    for (int row : rows)
        if (row >= 0 && row < m_rows)
            emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

void GesticonModel::reset()
{
    beginResetModel();
    m_rows = liveRowCount();
    endResetModel();
}

} // namespace thespis::editor
