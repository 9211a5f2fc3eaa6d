#include "editor/segment_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

#include "editor/character_choice.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "editor/scene_preview.h"
#include "editor/segment_table_model.h"

namespace thespis::editor {

using core::scene::SegmentRole;

namespace {

constexpr SegmentRole kRoles[] = {SegmentRole::None, SegmentRole::Receiver, SegmentRole::Occluder};

// A small rounded square of a role's colour, for buttons and combo items.
QIcon swatch(const QColor& color)
{
    QPixmap pixmap(24, 24);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(color.darker(140));
    painter.setBrush(color);
    painter.drawRoundedRect(QRectF(3.5, 3.5, 17, 17), 4, 4);
    return QIcon(pixmap);
}

// Role cells edit through a combo box that commits as soon as an item is chosen.
class TagDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex&) const override
    {
        auto* combo = new QComboBox(parent);
        combo->setObjectName(QStringLiteral("segmentTagEditor"));
        for (SegmentRole role : kRoles) {
            combo->addItem(swatch(SegmentTableModel::roleColor(role)), SegmentTableModel::roleText(role), int(role));
            combo->setItemData(combo->count() - 1, SegmentTableModel::roleDescription(role), Qt::ToolTipRole);
        }
        auto* self = const_cast<TagDelegate*>(this);
        QObject::connect(combo, &QComboBox::activated, self, [self, combo] {
            emit self->commitData(combo);
            emit self->closeEditor(combo);
        });
        return combo;
    }

    void setEditorData(QWidget* editor, const QModelIndex& index) const override
    {
        auto* combo = static_cast<QComboBox*>(editor);
        combo->setCurrentIndex(combo->findData(index.data(Qt::EditRole)));
    }

    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override
    {
        // Committed both on choosing and on losing focus: only a change is an edit.
        const QVariant value = static_cast<QComboBox*>(editor)->currentData();
        if (value.isValid() && value != index.data(Qt::EditRole))
            model->setData(index, value, Qt::EditRole);
    }
};

QToolButton* tagButton(const QString& text, const QString& tip, const QString& objectName, QWidget* parent)
{
    auto* button = new QToolButton(parent);
    button->setText(text);
    button->setToolTip(tip);
    button->setObjectName(objectName);
    button->setCheckable(true); // shows whether every selected segment already has it
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    return button;
}

} // namespace

SegmentPanel::SegmentPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("segmentPanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);

    auto* top = new QHBoxLayout;
    m_characters = addCharacterChoice(this, top, QStringLiteral("segmentCharacter"),
                                      tr("The character whose body segments are tagged"));
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(QStringLiteral("segmentFilter"));
    m_filter->setPlaceholderText(tr("Filter segments…"));
    m_filter->setToolTip(tr("Show only the segments whose name or joint contains this text"));
    m_filter->setClearButtonEnabled(true);
    top->addSpacing(8);
    top->addWidget(m_filter, 1);
    layout->addLayout(top);

    auto* bar = new QHBoxLayout;
    bar->setSpacing(2);
    auto* roleLabel = new QLabel(tr("Role:"), this);
    bar->addWidget(roleLabel);
    const QString roleNames[] = {QStringLiteral("tagNone"), QStringLiteral("tagReceiver"), QStringLiteral("tagOccluder")};
    for (SegmentRole role : {SegmentRole::Receiver, SegmentRole::Occluder, SegmentRole::None}) {
        auto* button = tagButton(SegmentTableModel::roleText(role),
                                 tr("Tag the selected segments as %1. %2")
                                     .arg(SegmentTableModel::roleText(role), SegmentTableModel::roleDescription(role)),
                                 roleNames[int(role)], this);
        button->setIcon(swatch(SegmentTableModel::roleColor(role)));
        connect(button, &QToolButton::clicked, this, [this, role] { applyRole(role); });
        bar->addWidget(button);
        if (m_roleButtons.size() <= std::size_t(role))
            m_roleButtons.resize(std::size_t(role) + 1);
        m_roleButtons[std::size_t(role)] = button;
    }
    bar->addStretch(1);
    m_selectionCount = new QLabel(this);
    m_selectionCount->setObjectName(QStringLiteral("segmentSelectionCount"));
    bar->addWidget(m_selectionCount);
    layout->addLayout(bar);

    m_model = new SegmentTableModel(this);
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("segmentTable"));
    m_table->setModel(m_model);
    m_table->setItemDelegate(new TagDelegate(m_table));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(false);
    m_table->setIconSize(QSize(12, 12));
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 8);
    m_table->horizontalHeader()->setHighlightSections(false);
    m_table->horizontalHeader()->setStretchLastSection(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    // Names share what the numbers leave; long ones (l_carpal_distal_phalanx_2) keep both ends.
    m_table->horizontalHeader()->setSectionResizeMode(SegmentTableModel::SegmentColumn, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(SegmentTableModel::JointColumn, QHeaderView::Stretch);
    m_table->setTextElideMode(Qt::ElideMiddle);
    const QFontMetrics metrics = m_table->fontMetrics();
    m_table->setColumnWidth(SegmentTableModel::RoleColumn, metrics.horizontalAdvance(tr("Occluder")) + 44);
    m_table->setColumnWidth(SegmentTableModel::VerticesColumn, metrics.horizontalAdvance(tr("Vertices")) + 20);
    m_table->setColumnWidth(SegmentTableModel::TrianglesColumn, metrics.horizontalAdvance(tr("Triangles")) + 20);
    layout->addWidget(m_table, 1);

    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("segmentMessage"));
    m_message->setWordWrap(true);
    QPalette warning = m_message->palette();
    warning.setColor(QPalette::WindowText, QColor(0xd0, 0x45, 0x3c));
    m_message->setPalette(warning);
    m_message->hide();
    layout->addWidget(m_message);

    m_hint = new QLabel(tr("Click a segment in the viewport to select it (Ctrl toggles, Shift adds). Receivers are "
                           "left out of the shadow proxy; occluders cast shadows but are not lit."),
                        this);
    m_hint->setObjectName(QStringLiteral("segmentHint"));
    m_hint->setWordWrap(true);
    QPalette muted = m_hint->palette();
    muted.setColor(QPalette::WindowText, muted.color(QPalette::PlaceholderText));
    m_hint->setPalette(muted);
    layout->addWidget(m_hint);

    connect(m_characters, &QComboBox::currentIndexChanged, this, [this](int index) { m_model->setCharacter(index); });
    connect(m_filter, &QLineEdit::textChanged, this, [this] { applyFilter(); });
    connect(m_model, &SegmentTableModel::segmentsReloaded, this, &SegmentPanel::onSegmentsReloaded);
    connect(m_model, &SegmentTableModel::problem, this, &SegmentPanel::showMessage);
    connect(m_model, &SegmentTableModel::dataChanged, this, [this] { updateActions(); });
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
        updateActions();
        updateHighlights();
        emit selectionChanged();
    });
    setDocument(nullptr);
}

SegmentPanel::~SegmentPanel()
{
    if (m_preview)
        m_preview->setHighlightedSegments(-1, {});
}

void SegmentPanel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    showMessage({});
    m_model->setDocument(document);
    if (m_document)
        connect(m_document, &Document::edited, this, [this] { refreshCharacters(); });
    refreshCharacters();
}

void SegmentPanel::setScenePreview(ScenePreview* preview)
{
    if (m_preview) {
        disconnect(m_preview, nullptr, this, nullptr);
        m_preview->setHighlightedSegments(-1, {});
    }
    m_preview = preview;
    if (m_preview) {
        connect(m_preview, &ScenePreview::segmentClicked, this, &SegmentPanel::onSegmentClicked);
        connect(m_preview, &ScenePreview::emptySpaceClicked, this, &SegmentPanel::onEmptySpaceClicked);
    }
    updateHighlights();
}

QString SegmentPanel::message() const
{
    return m_message->isHidden() ? QString() : m_message->text();
}

int SegmentPanel::currentCharacter() const
{
    return m_model->character();
}

void SegmentPanel::setCurrentCharacter(int character)
{
    if (character >= 0 && character < m_characters->count())
        m_characters->setCurrentIndex(character); // the model follows (currentIndexChanged)
}

std::vector<int> SegmentPanel::selectedSegments() const
{
    std::vector<int> rows;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows())
        rows.push_back(index.row());
    std::sort(rows.begin(), rows.end());
    return rows;
}

void SegmentPanel::selectSegments(const std::vector<int>& segments)
{
    QItemSelection selection;
    for (int row : segments)
        if (row >= 0 && row < m_model->rowCount() && !m_table->isRowHidden(row))
            selection.select(m_model->index(row, 0), m_model->index(row, SegmentTableModel::ColumnCount - 1));
    m_table->selectionModel()->select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    if (!selection.isEmpty()) {
        const QModelIndex first = selection.first().topLeft();
        m_table->selectionModel()->setCurrentIndex(first, QItemSelectionModel::NoUpdate);
        m_table->scrollTo(first);
    }
}

void SegmentPanel::applyRole(SegmentRole role)
{
    if (auto done = m_model->applyTags(selectedSegments(), role); !done)
        showMessage(fromUtf8(done.error().message));
    else
        showMessage({});
    updateActions();
}

void SegmentPanel::refreshCharacters()
{
    const int character = fillCharacterChoice(m_characters, m_document);
    m_characters->setEnabled(m_characters->count() > 1);
    m_filter->setEnabled(m_document != nullptr);
    m_model->setCharacter(character);
    updateActions();
}

void SegmentPanel::onSegmentsReloaded()
{
    showMessage(m_model->loadError());
    applyFilter();
    updateActions();
    updateHighlights();
    emit selectionChanged();
}

void SegmentPanel::onSegmentClicked(int character, int segment, Qt::KeyboardModifiers modifiers)
{
    if (!m_document || character < 0 || character >= m_characters->count())
        return;
    if (character != currentCharacter())
        setCurrentCharacter(character);
    if (segment < 0 || segment >= m_model->rowCount())
        return;
    if (m_table->isRowHidden(segment))
        m_filter->clear(); // the segment clicked must be seen
    QItemSelectionModel::SelectionFlags flags = QItemSelectionModel::Rows;
    if (modifiers & Qt::ControlModifier)
        flags |= QItemSelectionModel::Toggle;
    else if (modifiers & Qt::ShiftModifier)
        flags |= QItemSelectionModel::Select;
    else
        flags |= QItemSelectionModel::ClearAndSelect;
    const QModelIndex index = m_model->index(segment, SegmentTableModel::SegmentColumn);
    m_table->selectionModel()->setCurrentIndex(index, flags);
    m_table->scrollTo(index);
}

void SegmentPanel::onEmptySpaceClicked(Qt::KeyboardModifiers modifiers)
{
    if (modifiers == Qt::NoModifier)
        m_table->clearSelection();
}

void SegmentPanel::applyFilter()
{
    const QString text = m_filter->text().trimmed();
    QItemSelection hiddenSelected;
    for (int row = 0; row < m_model->rowCount(); ++row) {
        const bool hidden = !text.isEmpty() && !m_model->segmentName(row).contains(text, Qt::CaseInsensitive)
                            && !m_model->jointName(row).contains(text, Qt::CaseInsensitive);
        m_table->setRowHidden(row, hidden);
        if (hidden && m_table->selectionModel()->isRowSelected(row))
            hiddenSelected.select(m_model->index(row, 0), m_model->index(row, SegmentTableModel::ColumnCount - 1));
    }
    // Bulk edits apply to what the user sees selected, never to rows filtered away.
    if (!hiddenSelected.isEmpty())
        m_table->selectionModel()->select(hiddenSelected, QItemSelectionModel::Deselect | QItemSelectionModel::Rows);
}

void SegmentPanel::updateActions()
{
    const std::vector<int> selected = selectedSegments();
    const bool editable = m_document && !selected.empty();
    for (std::size_t r = 0; r < m_roleButtons.size(); ++r) {
        const bool all = editable && std::all_of(selected.begin(), selected.end(),
                                                 [&](int row) { return m_model->role(row) == SegmentRole(r); });
        m_roleButtons[r]->setEnabled(editable);
        m_roleButtons[r]->setChecked(all);
    }
    if (m_model->rowCount() == 0)
        m_selectionCount->clear();
    else
        m_selectionCount->setText(tr("%1 of %2 selected").arg(selected.size()).arg(m_model->rowCount()));
}

void SegmentPanel::updateHighlights()
{
    if (!m_preview)
        return;
    if (isVisible())
        m_preview->setHighlightedSegments(currentCharacter(), selectedSegments());
    else
        m_preview->setHighlightedSegments(-1, {});
}

void SegmentPanel::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    updateHighlights();
}

void SegmentPanel::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    // A hidden editor leaves no tint on the characters.
    if (m_preview)
        m_preview->setHighlightedSegments(-1, {});
}

void SegmentPanel::showMessage(const QString& message)
{
    m_message->setText(message);
    m_message->setVisible(!message.isEmpty());
}

} // namespace thespis::editor
