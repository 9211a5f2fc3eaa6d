#include "editor/bml_lexicon_box.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

#include "edit/lexicon_edits.h"
#include "editor/bml_lexicon_model.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "editor/text_button.h"

namespace thespis::editor {

namespace {

// The Gesture column picks one of the character's gestures; a pick commits at once.
class LexemeDelegate : public QStyledItemDelegate {
public:
    LexemeDelegate(BmlLexiconModel* model, QObject* parent) : QStyledItemDelegate(parent), m_model(model) {}

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        if (index.column() != BmlLexiconModel::GestureColumn)
            return QStyledItemDelegate::createEditor(parent, option, index);
        auto* combo = new QComboBox(parent);
        combo->setFrame(false);
        combo->addItems(m_model->gestureNames());
        auto* self = const_cast<LexemeDelegate*>(this);
        QObject::connect(combo, &QComboBox::activated, self, [self, combo] {
            emit self->commitData(combo);
            emit self->closeEditor(combo);
        });
        return combo;
    }
    void setEditorData(QWidget* editor, const QModelIndex& index) const override
    {
        if (auto* combo = qobject_cast<QComboBox*>(editor))
            combo->setCurrentIndex(std::max(0, combo->findText(index.data(Qt::EditRole).toString())));
        else
            QStyledItemDelegate::setEditorData(editor, index);
    }
    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override
    {
        if (auto* combo = qobject_cast<QComboBox*>(editor))
            model->setData(index, combo->currentText(), Qt::EditRole);
        else
            QStyledItemDelegate::setModelData(editor, model, index);
    }

private:
    BmlLexiconModel* m_model;
};

} // namespace

BmlLexiconBox::BmlLexiconBox(QWidget* parent) : QWidget(parent), m_model(new BmlLexiconModel(this))
{
    setObjectName(QStringLiteral("bmlLexicon"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    auto* title = new QLabel(tr("BML lexemes"), this);
    QFont bold = title->font();
    bold.setBold(true);
    title->setFont(bold);
    m_state = new QLabel(this);
    m_state->setObjectName(QStringLiteral("bmlLexiconState"));
    m_state->setWordWrap(true);
    auto* top = new QHBoxLayout;
    top->addWidget(title);
    top->addWidget(m_state, 1);
    layout->addLayout(top);

    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("bmlLexiconTable"));
    m_table->setModel(m_model);
    m_table->setItemDelegate(new LexemeDelegate(m_model, m_table));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                             | QAbstractItemView::SelectedClicked);
    m_table->setAlternatingRowColors(true);
    m_table->setShowGrid(false);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 10);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setMinimumHeight(4 * (m_table->fontMetrics().height() + 10));
    layout->addWidget(m_table, 1);

    auto* buttons = new QHBoxLayout;
    m_add = textButton(tr("Add"), tr("Add a lexeme playing the character's first gesture"),
                       QStringLiteral("addLexeme"), this);
    m_remove = textButton(tr("Remove"), tr("Remove the selected lexeme"), QStringLiteral("removeLexeme"), this);
    m_reset = textButton(tr("Reset to Defaults"),
                         tr("Give the character the default lexemes again (BEAT, NOD and AGREE: agree; WAVE and GREET: "
                            "greet; POINT: point)"),
                         QStringLiteral("resetLexicon"), this);
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    buttons->addStretch(1);
    buttons->addWidget(m_reset);
    layout->addLayout(buttons);

    connect(m_add, &QToolButton::clicked, this, &BmlLexiconBox::addRow);
    connect(m_remove, &QToolButton::clicked, this, &BmlLexiconBox::removeCurrent);
    connect(m_reset, &QToolButton::clicked, this, &BmlLexiconBox::resetToDefaults);
    connect(m_model, &BmlLexiconModel::editFailed, this, &BmlLexiconBox::message);
    connect(m_model, &BmlLexiconModel::editSucceeded, this, [this] { emit message({}); });
    connect(m_model, &QAbstractItemModel::modelReset, this, &BmlLexiconBox::updateActions);
    connect(m_model, &QAbstractItemModel::dataChanged, this, &BmlLexiconBox::updateActions); // own table or not
    connect(m_table->selectionModel(), &QItemSelectionModel::currentChanged, this, &BmlLexiconBox::updateActions);
    updateActions();
}

void BmlLexiconBox::setDocument(Document* document)
{
    m_document = document;
    m_model->setDocument(document);
}

void BmlLexiconBox::setCharacter(int character)
{
    m_model->setCharacter(character);
}

void BmlLexiconBox::updateActions()
{
    const bool character = m_document && m_model->character() >= 0;
    const bool gestures = !m_model->gestureNames().isEmpty();
    m_add->setEnabled(character && gestures);
    m_remove->setEnabled(character && m_table->currentIndex().isValid());
    m_reset->setEnabled(m_model->isOwnTable());
    m_state->setText(!character                ? QString()
                     : m_model->isOwnTable() ? tr("(the character's own)")
                                             : tr("(the defaults)"));
}

void BmlLexiconBox::addRow()
{
    const int c = m_model->character();
    const QStringList gestures = m_model->gestureNames();
    if (!m_document || c < 0 || gestures.isEmpty())
        return;
    // "LEXEME", else "LEXEME_2", "LEXEME_3", … (a lexeme has no spaces).
    std::string lexeme = "LEXEME";
    for (int n = 2; m_model->rowOf(fromUtf8(lexeme)) >= 0; ++n)
        lexeme = "LEXEME_" + std::to_string(n);
    auto edit = core::edit::setBmlLexeme(m_document->scenario(), c, lexeme, gestures.front().toStdString());
    if (auto done = m_document->edit(std::move(edit), tr("Add BML Lexeme")); !done) {
        emit message(fromUtf8(done.error().message));
        return;
    }
    emit message({});
    const QModelIndex name = m_model->index(m_model->rowOf(fromUtf8(lexeme)), BmlLexiconModel::LexemeColumn);
    m_table->setCurrentIndex(name);
    m_table->edit(name);
}

void BmlLexiconBox::removeCurrent()
{
    const QString lexeme = m_model->lexeme(m_table->currentIndex().row());
    if (!m_document || lexeme.isEmpty())
        return;
    const int row = m_table->currentIndex().row();
    auto edit = core::edit::setBmlLexeme(m_document->scenario(), m_model->character(), lexeme.toStdString(), std::nullopt);
    if (auto done = m_document->edit(std::move(edit), tr("Remove BML Lexeme")); !done) {
        emit message(fromUtf8(done.error().message));
        return;
    }
    emit message({});
    if (m_model->rowCount() > 0)
        m_table->setCurrentIndex(m_model->index(std::min(row, m_model->rowCount() - 1), 0));
}

void BmlLexiconBox::resetToDefaults()
{
    if (!m_document || !m_model->isOwnTable())
        return;
    auto edit = core::edit::setBmlLexicon(m_document->scenario(), m_model->character(), std::nullopt);
    if (auto done = m_document->edit(std::move(edit), tr("Reset BML Lexemes")); !done) {
        emit message(fromUtf8(done.error().message));
        return;
    }
    emit message({});
}

} // namespace thespis::editor
