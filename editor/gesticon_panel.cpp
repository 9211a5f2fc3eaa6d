#include "editor/gesticon_panel.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QStyle>
#include <QStyledItemDelegate>
#include <QTableView>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "edit/document_edits.h"
#include "editor/bml_lexicon_box.h"
#include "editor/character_choice.h"
#include "editor/document.h"
#include "editor/gesticon_model.h"
#include "editor/playback_clock.h"
#include "editor/qt_conversions.h"
#include "editor/text_button.h"
#include "editor/session.h"
#include "util/tick.h"

namespace thespis::editor {

using core::scenario::Gesture;

namespace {

// Editors of the gesticon table: the clip and the body part as combo boxes of what the character
// and the scenario have, the fades and the stroke as spin boxes in seconds, the filter and the
// hold as centred check boxes.
// A combo commits as soon as an entry is picked.
class GestureDelegate : public QStyledItemDelegate {
public:
    GestureDelegate(GesticonModel* model, QObject* parent) : QStyledItemDelegate(parent), m_model(model) {}

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        switch (index.column()) {
        case GesticonModel::ClipColumn:
        case GesticonModel::MaskColumn: {
            auto* combo = new QComboBox(parent);
            combo->setFrame(false);
            if (index.column() == GesticonModel::ClipColumn) {
                for (const QString& clip : m_model->clipNames())
                    combo->addItem(clip, clip);
            } else {
                combo->addItem(GesticonModel::tr("Whole body"), QString());
                for (const QString& mask : m_model->maskNames())
                    combo->addItem(mask, mask);
            }
            auto* self = const_cast<GestureDelegate*>(this);
            QObject::connect(combo, &QComboBox::activated, self, [self, combo] {
                emit self->commitData(combo);
                emit self->closeEditor(combo);
            });
            return combo;
        }
        case GesticonModel::FadeInColumn:
        case GesticonModel::FadeOutColumn: {
            auto* spin = new QDoubleSpinBox(parent);
            spin->setFrame(false);
            spin->setRange(0.0, 60.0);
            spin->setDecimals(2);
            spin->setSingleStep(0.05);
            spin->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            return spin;
        }
        case GesticonModel::StrokeColumn: {
            auto* spin = new QDoubleSpinBox(parent);
            spin->setFrame(false);
            spin->setRange(-1.0, 60.0);
            spin->setDecimals(2);
            spin->setSingleStep(0.05);
            spin->setSpecialValueText(GesticonModel::tr("none"));
            spin->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            return spin;
        }
        case GesticonModel::FilterColumn:
        case GesticonModel::HoldColumn:
            return nullptr; // toggled in place (editorEvent)
        default:
            return QStyledItemDelegate::createEditor(parent, option, index);
        }
    }

    void setEditorData(QWidget* editor, const QModelIndex& index) const override
    {
        const QVariant value = index.data(Qt::EditRole);
        if (auto* combo = qobject_cast<QComboBox*>(editor)) {
            combo->setCurrentIndex(std::max(0, combo->findData(value.toString())));
        } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor)) {
            spin->setValue(value.toDouble());
        } else {
            QStyledItemDelegate::setEditorData(editor, index);
        }
    }

    void setModelData(QWidget* editor, QAbstractItemModel* model, const QModelIndex& index) const override
    {
        if (auto* combo = qobject_cast<QComboBox*>(editor)) {
            model->setData(index, combo->currentData(), Qt::EditRole);
        } else if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor)) {
            spin->interpretText();
            model->setData(index, spin->value(), Qt::EditRole);
        } else {
            QStyledItemDelegate::setModelData(editor, model, index);
        }
    }

    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        // Room between columns sized to their contents, and for the editors' frames.
        return QStyledItemDelegate::sizeHint(option, index) + QSize(18, 0);
    }

    void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        if (!GesticonModel::isCheckColumn(index.column())) {
            QStyledItemDelegate::paint(painter, option, index);
            return;
        }
        QStyleOptionViewItem background = option;
        initStyleOption(&background, index);
        const QWidget* widget = option.widget;
        QStyle* style = widget ? widget->style() : QApplication::style();
        const QRect check = checkRect(background);
        background.features &= ~QStyleOptionViewItem::HasCheckIndicator;
        background.text.clear();
        style->drawControl(QStyle::CE_ItemViewItem, &background, painter, widget);
        QStyleOptionViewItem box = option;
        box.rect = check;
        box.state &= ~QStyle::State_HasFocus;
        box.state |= index.data(Qt::CheckStateRole).value<Qt::CheckState>() == Qt::Checked ? QStyle::State_On
                                                                                             : QStyle::State_Off;
        style->drawPrimitive(QStyle::PE_IndicatorItemViewItemCheck, &box, painter, widget);
    }

    bool editorEvent(QEvent* event, QAbstractItemModel* model, const QStyleOptionViewItem& option,
                     const QModelIndex& index) override
    {
        if (!GesticonModel::isCheckColumn(index.column()))
            return QStyledItemDelegate::editorEvent(event, model, option, index);
        if (!(index.flags() & Qt::ItemIsUserCheckable) || !(index.flags() & Qt::ItemIsEnabled))
            return false;
        switch (event->type()) {
        case QEvent::MouseButtonRelease: {
            auto* mouse = static_cast<QMouseEvent*>(event);
            QStyleOptionViewItem opt = option;
            initStyleOption(&opt, index);
            if (mouse->button() != Qt::LeftButton || !checkRect(opt).contains(mouse->position().toPoint()))
                return false;
            break;
        }
        case QEvent::MouseButtonDblClick: {
            QStyleOptionViewItem opt = option;
            initStyleOption(&opt, index);
            return checkRect(opt).contains(static_cast<QMouseEvent*>(event)->position().toPoint());
        }
        case QEvent::KeyPress: {
            const int key = static_cast<QKeyEvent*>(event)->key();
            if (key != Qt::Key_Space && key != Qt::Key_Select)
                return false;
            break;
        }
        default:
            return false;
        }
        const bool checked = index.data(Qt::CheckStateRole).value<Qt::CheckState>() == Qt::Checked;
        return model->setData(index, checked ? Qt::Unchecked : Qt::Checked, Qt::CheckStateRole);
    }

private:
    static QRect checkRect(const QStyleOptionViewItem& option)
    {
        const QWidget* widget = option.widget;
        QStyle* style = widget ? widget->style() : QApplication::style();
        QStyleOptionViewItem opt = option;
        opt.features |= QStyleOptionViewItem::HasCheckIndicator;
        const QSize size = style->subElementRect(QStyle::SE_ItemViewItemCheckIndicator, &opt, widget).size();
        return QStyle::alignedRect(option.direction, Qt::AlignCenter, size, option.rect);
    }

    GesticonModel* m_model;
};

} // namespace

GesticonPanel::GesticonPanel(QWidget* parent) : QWidget(parent), m_model(new GesticonModel(this))
{
    setObjectName(QStringLiteral("gesticonPanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);

    auto* top = new QHBoxLayout;
    m_characters = addCharacterChoice(this, top, QStringLiteral("gesticonCharacter"),
                                      tr("The character whose gesture database is shown"));
    layout->addLayout(top);

    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("gesticonTable"));
    m_table->setModel(m_model);
    m_table->setItemDelegate(new GestureDelegate(m_model, m_table));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                             | QAbstractItemView::SelectedClicked);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(false);
    m_table->setShowGrid(false);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 10);
    QHeaderView* header = m_table->horizontalHeader();
    header->setHighlightSections(false);
    // Every column fits what it shows, the name first among them; the last takes the room left,
    // and a narrow dock scrolls rather than squeezing the names.
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setStretchLastSection(true);
    layout->addWidget(m_table, 1);

    auto* buttons = new QHBoxLayout;
    m_add = textButton(tr("Add"), tr("Add a gesture playing the character's first clip"), QStringLiteral("addGesture"), this);
    m_remove = textButton(tr("Remove"), tr("Remove the selected gestures"), QStringLiteral("removeGesture"), this);
    m_rename = textButton(tr("Rename"), tr("Rename the selected gesture"), QStringLiteral("renameGesture"), this);
    m_preview = textButton(tr("Preview"), QString(), QStringLiteral("previewGesture"), this);
    m_preview->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_compare = textButton(tr("Before / After"), QString(), QStringLiteral("compareFilter"), this);
    for (QToolButton* button : {m_add, m_remove, m_rename})
        buttons->addWidget(button);
    buttons->addStretch(1);
    buttons->addWidget(m_compare);
    buttons->addWidget(m_preview);
    m_playing = new QLabel(this);
    m_playing->setObjectName(QStringLiteral("gesticonPlaying"));
    m_playing->hide();
    layout->addWidget(m_playing);
    layout->addLayout(buttons);
    m_lexicon = new BmlLexiconBox(this);
    layout->addWidget(m_lexicon);

    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("gesticonMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QPalette palette = m_message->palette();
    palette.setColor(QPalette::WindowText, QColor(0xd0, 0x3a, 0x2f));
    m_message->setPalette(palette);
    m_message->hide();
    layout->addWidget(m_message);

    connect(m_characters, &QComboBox::currentIndexChanged, this, [this](int index) {
        stopPreview();
        m_model->setCharacter(index);
        m_lexicon->setCharacter(index);
        showMessage({});
        if (m_model->rowCount() > 0)
            selectRow(0);
        updateActions();
    });
    connect(m_add, &QToolButton::clicked, this, &GesticonPanel::addGesture);
    connect(m_remove, &QToolButton::clicked, this, &GesticonPanel::removeSelected);
    connect(m_rename, &QToolButton::clicked, this, &GesticonPanel::renameSelected);
    connect(m_preview, &QToolButton::clicked, this, [this] {
        if (m_previewing)
            stopPreview();
        else
            preview();
    });
    connect(m_compare, &QToolButton::clicked, this, [this] {
        if (m_previewing)
            stopPreview();
        else
            compareFilter();
    });
    connect(m_model, &GesticonModel::editFailed, this, &GesticonPanel::showMessage);
    connect(m_lexicon, &BmlLexiconBox::message, this, &GesticonPanel::showMessage);
    connect(m_model, &GesticonModel::editSucceeded, this, [this] { showMessage({}); });
    // Keep the current gesture selected across resets (undo of a removal, another character…).
    connect(m_model, &QAbstractItemModel::modelAboutToBeReset, this, [this] {
        const Gesture* g = m_model->gesture(m_table->currentIndex().row());
        m_keptSelection = g ? fromUtf8(g->name) : QString();
    });
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        if (const int row = m_model->rowOf(m_keptSelection); row >= 0)
            selectRow(row);
        updateActions();
    });
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this, &GesticonPanel::updateActions);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentChanged, this, &GesticonPanel::updateActions);
    setDocument(nullptr);
}

GesticonPanel::~GesticonPanel()
{
    // The scene must not keep playing a preview whose panel is gone, nor the clock keep its range.
    stopPreview();
}

void GesticonPanel::setDocument(Document* document)
{
    stopPreview();
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_model->setDocument(document);
    m_lexicon->setDocument(document);
    if (m_document)
        // Any edit ends a preview: what it shows is no longer the document plus the gesture. Queued,
        // so that whoever shows the edited document has rebuilt from it first.
        connect(m_document, &Document::edited, this, [this] {
            stopPreviewLater();
        });
    showMessage({});
    refreshCharacters();
}

void GesticonPanel::setSession(Session* session)
{
    stopPreview();
    if (m_session)
        disconnect(m_session->clock(), nullptr, this, nullptr);
    m_session = session;
    if (m_session) {
        PlaybackClock* clock = m_session->clock();
        connect(clock, &PlaybackClock::timeChanged, this, &GesticonPanel::onClockTime);
        connect(clock, &PlaybackClock::playingChanged, this, [this](bool playing) {
            // Pausing the clock (the transport, the space bar) stops the preview. Queued: the
            // clock is still inside its own signal, and the stop moves the playhead back.
            if (!playing)
                stopPreviewLater();
        });
    }
    updateActions();
}

QString GesticonPanel::message() const
{
    return m_message->text();
}

int GesticonPanel::currentCharacter() const
{
    return m_model->character();
}

void GesticonPanel::setCurrentCharacter(int character)
{
    if (character >= 0 && character < m_characters->count())
        m_characters->setCurrentIndex(character);
}

QList<int> GesticonPanel::selectedRows() const
{
    QList<int> rows;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows())
        rows << index.row();
    if (rows.isEmpty() && m_table->currentIndex().isValid())
        rows << m_table->currentIndex().row();
    std::sort(rows.begin(), rows.end());
    return rows;
}

void GesticonPanel::selectRow(int row)
{
    if (row < 0 || row >= m_model->rowCount())
        return;
    m_table->setCurrentIndex(m_model->index(row, GesticonModel::NameColumn));
    m_table->selectRow(row);
}

void GesticonPanel::refreshCharacters()
{
    m_model->setCharacter(fillCharacterChoice(m_characters, m_document));
    m_lexicon->setCharacter(m_model->character());
    if (m_model->rowCount() > 0)
        selectRow(0);
    updateActions();
}

void GesticonPanel::updateActions()
{
    const core::scenario::Character* character =
        m_document && currentCharacter() >= 0 ? &m_document->scenario().characters[std::size_t(currentCharacter())]
                                              : nullptr;
    const QList<int> rows = selectedRows();
    const bool hasCurrent = m_model->gesture(m_table->currentIndex().row()) != nullptr;
    m_characters->setEnabled(m_characters->count() > 1);
    m_add->setEnabled(character && !character->clips.empty());
    m_add->setToolTip(character && character->clips.empty()
                          ? tr("The character has no clips to make a gesture from")
                          : tr("Add a gesture playing the character's first clip"));
    m_remove->setEnabled(!rows.isEmpty());
    m_rename->setEnabled(hasCurrent);

    const bool canPreview = m_session && m_session->stage();
    m_preview->setText(m_previewing ? tr("Stop") : tr("Preview"));
    m_preview->setIcon(style()->standardIcon(m_previewing ? QStyle::SP_MediaStop : QStyle::SP_MediaPlay));
    m_preview->setEnabled(m_previewing || (canPreview && hasCurrent));
    if (!canPreview)
        m_preview->setToolTip(tr("Open a scenario to preview its gestures"));
    else if (m_previewing)
        m_preview->setToolTip(tr("Stop the preview and show the document again"));
    else
        m_preview->setToolTip(tr("Play the selected gesture on the character from the playhead, over what it "
                                 "plays, as a script would (the document does not change)"));
    m_compare->setEnabled(!m_previewing && canPreview && hasCurrent);
    m_compare->setToolTip(tr("Play the selected gesture twice from the playhead: without the dependent-joint filter, "
                             "then with it (spine and neck follow the gesture)"));
}

QString GesticonPanel::playing() const
{
    return m_playing->isVisible() ? m_playing->text() : QString();
}

void GesticonPanel::showMessage(const QString& message)
{
    m_message->setText(message);
    m_message->setVisible(!message.isEmpty());
}

void GesticonPanel::addGesture()
{
    const int c = currentCharacter();
    if (!m_document || c < 0)
        return;
    const core::scenario::Character& character = m_document->scenario().characters[std::size_t(c)];
    if (character.clips.empty()) {
        showMessage(tr("Character \"%1\" has no clips to make a gesture from.").arg(fromUtf8(character.name)));
        return;
    }
    std::vector<std::string> names;
    for (const Gesture& g : character.gestures)
        names.push_back(g.name);
    Gesture gesture;
    gesture.name = core::edit::uniqueName(tr("gesture").toStdString(), names);
    gesture.clip = character.clips.front().name;
    gesture.fadeIn = gesture.fadeOut = core::secondsToTicks(0.3);
    const QString name = fromUtf8(gesture.name);
    if (auto done = m_document->edit(core::edit::addGesture(m_document->scenario(), c, std::move(gesture)),
                                     tr("Add Gesture"));
        !done) {
        showMessage(fromUtf8(done.error().message));
        return;
    }
    showMessage({});
    selectRow(m_model->rowOf(name));
}

void GesticonPanel::removeSelected()
{
    const int c = currentCharacter();
    QList<int> rows = selectedRows();
    if (!m_document || c < 0 || rows.isEmpty())
        return;
    // From the last row up, so that each removal leaves the rows of the next ones in place.
    core::edit::Edit edit;
    for (auto row = rows.rbegin(); row != rows.rend(); ++row) {
        auto removal = core::edit::removeGesture(m_document->scenario(), {c, *row});
        if (!removal) {
            showMessage(fromUtf8(removal.error().message));
            return;
        }
        edit.append(std::move(removal).value());
    }
    if (auto done = m_document->edit(std::move(edit), tr("Remove %n Gesture(s)", "", int(rows.size()))); !done) {
        showMessage(fromUtf8(done.error().message));
        return;
    }
    showMessage({});
    selectRow(std::min(rows.front(), m_model->rowCount() - 1));
}

void GesticonPanel::renameSelected()
{
    const int row = m_table->currentIndex().row();
    if (!m_model->gesture(row))
        return;
    const QModelIndex name = m_model->index(row, GesticonModel::NameColumn);
    m_table->setCurrentIndex(name);
    m_table->edit(name);
}

void GesticonPanel::preview()
{
    m_comparePass = 0;
    startPreview(std::nullopt);
}

void GesticonPanel::compareFilter()
{
    m_comparePass = 1;
    startPreview(false);
}

namespace {
// The live action a preview plays: not the gesture's own name, which a script may be playing.
std::string previewActionName(const std::string& gesture)
{
    return gesture + " (gesture preview)";
}
} // namespace

void GesticonPanel::startPreview(std::optional<bool> filter)
{
    const int pass = m_comparePass;
    if (m_previewing)
        stopPreview();
    m_comparePass = pass;
    const int c = currentCharacter();
    const Gesture* current = m_model->gesture(m_table->currentIndex().row());
    if (!m_document || !m_session || !m_session->stage() || c < 0 || !current)
        return;
    core::runtime::Stage& stage = *m_session->stage();
    PlaybackClock& clock = *m_session->clock();
    const std::string& characterName = m_document->scenario().characters[std::size_t(c)].name;
    const QString name = fromUtf8(current->name);
    const core::scenario::GestureActions* gesture = nullptr;
    if (const auto* runtime = stage.runtime().findCharacter(characterName))
        if (const auto found = runtime->gestures.find(current->name); found != runtime->gestures.end())
            gesture = &found->second;
    if (!gesture) {
        showMessage(tr("Cannot preview gesture \"%1\": it cannot be played (Messages says why).").arg(name));
        return;
    }
    const core::anim::BlendingAction& action = !filter ? gesture->played() : *filter ? gesture->withFilter : gesture->withoutFilter;
    if (!action.source) {
        showMessage(tr("Cannot preview gesture \"%1\" with the dependent-joint filter: the scenario names no posture "
                       "bases (a .pca file made by thespis-cli train-pca).")
                        .arg(name));
        return;
    }
    const core::Tick start = clock.time();
    const std::string live = previewActionName(current->name);
    const core::runtime::Track track = gesture->face ? core::runtime::Track::Face : core::runtime::Track::Body;
    if (auto played = stage.playAction(characterName, track, live,
                                       {action.source, action.params, action.renderOutsideDomain},
                                       start, {.fadeIn = 0});
        !played) {
        showMessage(tr("Cannot preview gesture \"%1\": %2").arg(name, fromUtf8(played.error().message)));
        return;
    }
    const auto end = stage.actionEnd(characterName, track, live);
    if (!end || !std::isfinite(*end) || core::secondsToTicks(*end) <= start) {
        (void)stage.removeAction(characterName, track, live);
        showMessage(tr("Cannot preview gesture \"%1\": its clip has no finite length.").arg(name));
        return;
    }

    m_previewing = true;
    ++m_previewSerial;
    m_previewCharacter = characterName;
    m_previewAction = live;
    m_previewOnFace = gesture->face;
    m_previewStart = start;
    m_previewEnd = core::secondsToTicks(*end);
    m_savedLooping = clock.isLooping();
    m_savedClockDuration = clock.duration();
    // The gesture may reach past the end of the timeline: the clock must get there.
    clock.setLooping(false);
    clock.setDuration(std::max(m_savedClockDuration, m_previewEnd));
    m_previewClockDuration = clock.duration();
    showMessage({});
    m_playing->setText(m_comparePass == 1 ? tr("Before: \"%1\" without the dependent-joint filter").arg(name)
                       : m_comparePass == 2
                           ? tr("After: \"%1\" with the dependent-joint filter (spine and neck follow)").arg(name)
                           : QString());
    m_playing->setVisible(m_comparePass != 0);
    updateActions();
    emit previewingChanged(true);
    clock.play();
}

void GesticonPanel::stopPreview()
{
    if (!m_previewing)
        return;
    m_previewing = false;
    m_comparePass = 0;
    m_playing->hide();
    if (m_session && m_session->stage())
        (void)m_session->stage()->removeAction(
            m_previewCharacter, m_previewOnFace ? core::runtime::Track::Face : core::runtime::Track::Body, m_previewAction);
    if (m_session) {
        PlaybackClock* clock = m_session->clock();
        clock->pause();
        // Put back what the preview changed, unless someone (an edit) set the duration since.
        if (clock->duration() == m_previewClockDuration)
            clock->setDuration(m_savedClockDuration);
        const core::Tick before = clock->time();
        clock->seek(std::min(m_previewStart, clock->duration()));
        clock->setLooping(m_savedLooping);
        if (clock->time() == before)
            m_session->tick(); // the views show the stage without the gesture
    }
    updateActions();
    emit previewingChanged(false);
}

void GesticonPanel::onClockTime(core::Tick time)
{
    if (!m_previewing || time < m_previewEnd)
        return;
    if (m_comparePass != 1) {
        stopPreviewLater();
        return;
    }
    // Before has played: After, from the same time. Queued, as a stop is.
    QMetaObject::invokeMethod(this, [this, serial = m_previewSerial] {
        if (m_previewing && serial == m_previewSerial && m_comparePass == 1) {
            stopPreview();
            m_comparePass = 2;
            startPreview(true);
        }
    }, Qt::QueuedConnection);
}

void GesticonPanel::stopPreviewLater()
{
    if (!m_previewing)
        return;
    // Only this preview: a new one may have started by the time the call runs.
    QMetaObject::invokeMethod(this, [this, serial = m_previewSerial] {
        if (m_previewing && serial == m_previewSerial)
            stopPreview();
    }, Qt::QueuedConnection);
}

} // namespace thespis::editor
