#include "editor/bml_lexicon_model.h"

#include <algorithm>
#include <iterator>
#include <variant>

#include "edit/lexicon_edits.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "util/text.h"

namespace thespis::editor {

BmlLexiconModel::BmlLexiconModel(QObject* parent) : QAbstractTableModel(parent)
{
}

void BmlLexiconModel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (m_document)
        connect(m_document, &Document::edited, this, &BmlLexiconModel::onEdited);
    m_character = m_document && !m_document->scenario().characters.empty() ? 0 : -1;
    reset();
}

void BmlLexiconModel::setCharacter(int character)
{
    const bool valid = m_document && character >= 0
                       && std::size_t(character) < m_document->scenario().characters.size();
    m_character = valid ? character : -1;
    reset();
}

bool BmlLexiconModel::isOwnTable() const
{
    return m_document && m_character >= 0
           && m_document->scenario().characters[std::size_t(m_character)].bmlLexicon.has_value();
}

QString BmlLexiconModel::lexeme(int row) const
{
    if (row < 0 || row >= int(m_rows.size()))
        return {};
    return fromUtf8(std::next(m_rows.begin(), row)->first);
}

int BmlLexiconModel::rowOf(const QString& lexeme) const
{
    const auto found = m_rows.find(core::uppercase(lexeme.toStdString()));
    return found == m_rows.end() ? -1 : int(std::distance(m_rows.begin(), found));
}

QStringList BmlLexiconModel::gestureNames() const
{
    QStringList names;
    if (m_document && m_character >= 0)
        for (const core::scenario::Gesture& g : m_document->scenario().characters[std::size_t(m_character)].gestures)
            names << fromUtf8(g.name);
    return names;
}

int BmlLexiconModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int BmlLexiconModel::columnCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant BmlLexiconModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_rows.size()))
        return {};
    const auto& [lexeme, gesture] = *std::next(m_rows.begin(), index.row());
    if (role == Qt::DisplayRole || role == Qt::EditRole)
        return fromUtf8(index.column() == LexemeColumn ? lexeme : gesture);
    if (role == Qt::ToolTipRole && index.column() == GestureColumn && !gestureNames().contains(fromUtf8(gesture)))
        return tr("The character has no gesture named “%1”: BML's %2 plays no gesture through this row.")
            .arg(fromUtf8(gesture), fromUtf8(lexeme));
    return {};
}

QVariant BmlLexiconModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return section == LexemeColumn ? tr("Lexeme") : tr("Gesture");
}

Qt::ItemFlags BmlLexiconModel::flags(const QModelIndex& index) const
{
    return index.isValid() ? Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsEditable : Qt::NoItemFlags;
}

bool BmlLexiconModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || role != Qt::EditRole || !m_document || index.row() >= int(m_rows.size()))
        return false;
    const auto& [lexeme, gesture] = *std::next(m_rows.begin(), index.row());
    const std::string next = value.toString().trimmed().toStdString();
    const bool rename = index.column() == LexemeColumn;
    if (rename ? core::uppercase(next) == lexeme : next == gesture)
        return true;
    const core::scenario::Scenario& scenario = m_document->scenario();
    auto edit = rename ? core::edit::renameBmlLexeme(scenario, m_character, lexeme, next)
                       : core::edit::setBmlLexeme(scenario, m_character, lexeme, next);
    if (auto done = m_document->edit(std::move(edit), rename ? tr("Rename BML Lexeme") : tr("Set BML Lexeme")); !done) {
        emit editFailed(fromUtf8(done.error().message));
        return false;
    }
    emit editSucceeded();
    return true;
}

void BmlLexiconModel::onEdited(const core::edit::Edit& edit)
{
    if (m_character >= 0 && std::size_t(m_character) >= m_document->scenario().characters.size())
        m_character = m_document->scenario().characters.empty() ? -1 : 0;
    // Its own table, or the gestures the defaults' rows name, may have changed. The same lexemes
    // keep their rows (a gesture picked, in an editor that is still closing); others reset.
    if (std::all_of(edit.changes().begin(), edit.changes().end(), [](const core::edit::Change& change) {
            return std::holds_alternative<core::edit::ActionChange>(change);
        }))
        return;
    std::map<std::string, std::string> rows;
    if (m_document && m_character >= 0)
        rows = core::edit::bmlLexiconRows(m_document->scenario().characters[std::size_t(m_character)]);
    const bool sameLexemes = std::equal(rows.begin(), rows.end(), m_rows.begin(), m_rows.end(),
                                        [](const auto& a, const auto& b) { return a.first == b.first; });
    if (!sameLexemes) {
        reset();
        return;
    }
    m_rows = std::move(rows);
    if (!m_rows.empty())
        emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
}

void BmlLexiconModel::reset()
{
    beginResetModel();
    m_rows.clear();
    if (m_document && m_character >= 0)
        m_rows = core::edit::bmlLexiconRows(m_document->scenario().characters[std::size_t(m_character)]);
    endResetModel();
}

} // namespace thespis::editor
