#include "editor/properties_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "edit/document_edits.h"
#include "editor/blink_properties.h"
#include "editor/character_properties.h"
#include "editor/document.h"
#include "editor/gaze_properties.h"
#include "editor/idle_properties.h"
#include "editor/pointing_properties.h"
#include "editor/qt_conversions.h"
#include "scene/face_mask.h"

namespace thespis::editor {

using core::scenario::ActionSpec;
using core::scenario::ModifierKind;
using core::scenario::ModifierSpec;

namespace {

const ActionSpec* actionAt(const core::scenario::Scenario& scenario, const core::edit::ActionPath& path)
{
    if (path.character < 0 || std::size_t(path.character) >= scenario.characters.size())
        return nullptr;
    const auto& layers = scenario.characters[std::size_t(path.character)].layers;
    if (path.layer < 0 || std::size_t(path.layer) >= layers.size())
        return nullptr;
    const auto& actions = layers[std::size_t(path.layer)].actions;
    if (path.action < 0 || std::size_t(path.action) >= actions.size())
        return nullptr;
    return &actions[std::size_t(path.action)];
}

QString seconds(double value)
{
    return PropertiesPanel::tr("%1 s").arg(value, 0, 'f', 3);
}

QString describeModifier(const ModifierSpec& modifier)
{
    switch (modifier.kind) {
    case ModifierKind::TimeStretch:
        return PropertiesPanel::tr("time stretch ×%1").arg(modifier.factor, 0, 'g', 4);
    case ModifierKind::TimeWarp:
        return PropertiesPanel::tr("time warp over %1").arg(seconds(modifier.duration));
    case ModifierKind::Loop:
        return modifier.count == 0 ? PropertiesPanel::tr("loop forever")
                                   : PropertiesPanel::tr("loop ×%1").arg(modifier.count);
    case ModifierKind::Mirror:
        return PropertiesPanel::tr("mirror left/right");
    case ModifierKind::GlobalTransform:
        return PropertiesPanel::tr("moved to (%1, %2, %3) m")
            .arg(modifier.translation.x, 0, 'f', 2)
            .arg(modifier.translation.y, 0, 'f', 2)
            .arg(modifier.translation.z, 0, 'f', 2);
    case ModifierKind::TimeOffset:
        return PropertiesPanel::tr("offset %1").arg(seconds(modifier.offset));
    case ModifierKind::Trim:
        return PropertiesPanel::tr("trim %1 – %2").arg(seconds(modifier.start), seconds(modifier.end));
    case ModifierKind::DependentJointFilter:
        return PropertiesPanel::tr("dependent joints follow (PCs kept to %1, muted above %2)")
            .arg(modifier.fadeFrom)
            .arg(modifier.muteAbove);
    }
    return {};
}

} // namespace

PropertiesPanel::PropertiesPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("propertiesPanel"));
    auto* layout = new QVBoxLayout(this);
    m_pages = new QStackedWidget(this);
    layout->addWidget(m_pages);

    m_scenarioSummary = new QLabel(m_pages);
    m_scenarioSummary->setObjectName(QStringLiteral("scenarioSummary"));
    m_scenarioSummary->setWordWrap(true);
    m_scenarioSummary->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_scenarioSummary->setTextFormat(Qt::RichText);
    m_pages->addWidget(m_scenarioSummary);

    auto* actionPage = new QWidget(m_pages);
    auto* form = m_form = new QFormLayout(actionPage);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_owner = new QLabel(actionPage);
    m_owner->setObjectName(QStringLiteral("actionOwner"));
    m_name = new QLineEdit(actionPage);
    m_name->setObjectName(QStringLiteral("actionName"));
    m_clip = new QComboBox(actionPage);
    m_clip->setObjectName(QStringLiteral("actionClip"));
    m_start = new QDoubleSpinBox(actionPage);
    m_start->setObjectName(QStringLiteral("actionStart"));
    m_start->setDecimals(3);
    m_start->setRange(0.0, 24 * 3600.0);
    m_start->setSingleStep(1.0 / 30.0);
    m_start->setSuffix(tr(" s"));
    m_start->setKeyboardTracking(false); // one edit when typing is done, not one per digit
    m_mode = new QComboBox(actionPage);
    m_mode->setObjectName(QStringLiteral("actionMode"));
    m_mode->addItem(tr("Normalized (weighted average)"), int(core::anim::BlendMode::Normalized));
    m_mode->addItem(tr("Additive (on top of the layers below)"), int(core::anim::BlendMode::Additive));
    m_mode->addItem(tr("Override (replaces by its weight)"), int(core::anim::BlendMode::Override));
    m_mask = new QComboBox(actionPage);
    m_mask->setObjectName(QStringLiteral("actionMask"));
    m_outsideDomain = new QCheckBox(tr("Hold the first and last pose outside the action"), actionPage);
    m_outsideDomain->setObjectName(QStringLiteral("actionOutsideDomain"));
    m_placement = new QComboBox(actionPage);
    m_placement->setObjectName(QStringLiteral("actionPlacement"));
    m_placement->addItem(tr("Where it was recorded"), int(core::scenario::Placement::World));
    m_placement->addItem(tr("Where the character stands"), int(core::scenario::Placement::Character));
    m_placement->addItem(tr("Where the previous action leaves it"), int(core::scenario::Placement::Continue));
    m_placement->setToolTip(tr("Where the motion's first frame puts the body on the floor (and which way it faces)"));
    m_repeat = new QSpinBox(actionPage);
    m_repeat->setObjectName(QStringLiteral("actionRepeat"));
    m_repeat->setRange(0, 1000);
    m_repeat->setSpecialValueText(tr("forever"));
    m_repeat->setSuffix(tr(" ×"));
    m_repeat->setKeyboardTracking(false);
    m_rootMotion = new QCheckBox(tr("Each time on from where it ended (walks on)"), actionPage);
    m_rootMotion->setObjectName(QStringLiteral("actionRootMotion"));
    m_length = new QLabel(actionPage);
    m_fades = new QLabel(actionPage);
    m_modifiers = new QLabel(actionPage);
    m_modifiers->setWordWrap(true);
    form->addRow(tr("Action of:"), m_owner);
    form->addRow(tr("Name:"), m_name);
    form->addRow(tr("Clip:"), m_clip);
    form->addRow(tr("Start:"), m_start);
    form->addRow(tr("Length:"), m_length);
    form->addRow(tr("Fades:"), m_fades);
    form->addRow(tr("Starts:"), m_placement);
    form->addRow(tr("Plays:"), m_repeat);
    form->addRow(QString(), m_rootMotion);
    form->addRow(tr("Blend mode:"), m_mode);
    m_maskLabel = new QLabel(tr("Body part:"), actionPage);
    form->addRow(m_maskLabel, m_mask);
    form->addRow(QString(), m_outsideDomain);
    form->addRow(tr("Modifiers:"), m_modifiers);
    m_idle = new IdleProperties(actionPage);
    form->addRow(m_idle);
    connect(m_idle, &IdleProperties::problem, this, &PropertiesPanel::problem);
    m_blinks = new BlinkProperties(actionPage);
    form->addRow(m_blinks);
    connect(m_blinks, &BlinkProperties::problem, this, &PropertiesPanel::problem);
    m_gaze = new GazeProperties(actionPage);
    form->addRow(m_gaze);
    connect(m_gaze, &GazeProperties::gazeEditRequested, this, [this](const core::scenario::GazeSpec& gaze) {
        editAction(tr("Change Gaze"), [&](ActionSpec& spec) { spec.gaze = gaze; });
    });
    m_pointing = new PointingProperties(actionPage);
    form->addRow(m_pointing);
    connect(m_pointing, &PointingProperties::pointingEditRequested, this,
            [this](const std::optional<core::scenario::PointingSpec>& pointing) {
                editAction(tr("Change Pointing"), [&](ActionSpec& spec) { spec.pointing = pointing; });
            });
    m_pages->addWidget(actionPage);
    m_characterPage = new CharacterProperties(m_pages);
    m_pages->addWidget(m_characterPage);
    connect(m_characterPage, &CharacterProperties::problem, this, &PropertiesPanel::problem);

    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const std::string name = m_name->text().trimmed().toStdString();
        editAction(tr("Rename Action"), [&](ActionSpec& spec) { spec.name = name; });
    });
    connect(m_clip, &QComboBox::activated, this, [this] {
        const std::string clip = m_clip->currentData().toString().toStdString();
        editAction(tr("Change Clip"), [&](ActionSpec& spec) { spec.clip = clip; });
    });
    connect(m_mode, &QComboBox::activated, this, [this] {
        const auto mode = core::anim::BlendMode(m_mode->currentData().toInt());
        editAction(tr("Change Blend Mode"), [&](ActionSpec& spec) { spec.mode = mode; });
    });
    connect(m_mask, &QComboBox::activated, this, [this] {
        const std::string mask = m_mask->currentData().toString().toStdString();
        editAction(tr("Change Body Part"), [&](ActionSpec& spec) { spec.mask = mask; });
    });
    connect(m_outsideDomain, &QCheckBox::toggled, this, [this](bool on) {
        editAction(tr("Change Outside Domain"), [&](ActionSpec& spec) { spec.renderOutsideDomain = on; });
    });
    connect(m_start, &QDoubleSpinBox::valueChanged, this, &PropertiesPanel::onStartEdited);
    connect(m_placement, &QComboBox::activated, this, [this] {
        const auto placement = core::scenario::Placement(m_placement->currentData().toInt());
        editAction(tr("Change Where the Action Starts"), [&](ActionSpec& spec) { spec.placement = placement; });
    });
    connect(m_repeat, &QSpinBox::valueChanged, this, &PropertiesPanel::onRepeatEdited);
    connect(m_rootMotion, &QCheckBox::toggled, this, &PropertiesPanel::onRepeatEdited);
    refresh();
}

void PropertiesPanel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_action.reset();
    if (m_document)
        connect(m_document, &Document::edited, this, &PropertiesPanel::refresh);
    refresh();
}

void PropertiesPanel::setAction(std::optional<core::edit::ActionPath> action)
{
    m_action = action;
    refresh();
}

template <typename Change> void PropertiesPanel::editAction(const QString& text, Change change)
{
    if (m_refreshing || !m_document || !m_action)
        return;
    const ActionSpec* current = actionAt(m_document->scenario(), *m_action);
    if (!current)
        return;
    ActionSpec spec = *current;
    change(spec);
    const auto result = m_document->edit(core::edit::replaceAction(m_document->scenario(), *m_action, std::move(spec)), text);
    if (!result) {
        emit problem(tr("%1: %2").arg(text, fromUtf8(result.error().message)));
        refresh(); // show what the document still holds
    }
}

void PropertiesPanel::onRepeatEdited()
{
    // The action's loop: the first Loop modifier (added in front, wrapping the clip; taken
    // away when it plays once).
    const int times = m_repeat->value();
    const bool rootMotion = m_rootMotion->isChecked();
    editAction(tr("Change How Often the Action Plays"), [&](ActionSpec& spec) {
        auto loop = std::find_if(spec.modifiers.begin(), spec.modifiers.end(),
                                 [](const ModifierSpec& m) { return m.kind == ModifierKind::Loop; });
        if (times == 1) {
            if (loop != spec.modifiers.end())
                spec.modifiers.erase(loop);
            return;
        }
        if (loop == spec.modifiers.end())
            loop = spec.modifiers.insert(spec.modifiers.begin(), ModifierSpec{.kind = ModifierKind::Loop});
        loop->count = times;
        loop->rootMotion = rootMotion;
    });
}

void PropertiesPanel::onStartEdited()
{
    if (m_refreshing || !m_document || !m_action)
        return;
    const ActionSpec* current = actionAt(m_document->scenario(), *m_action);
    if (!current)
        return;
    const core::Tick delta = core::secondsToTicks(m_start->value()) - current->start;
    const core::edit::ActionPath paths[] = {*m_action};
    const auto result = m_document->edit(core::edit::moveActions(m_document->scenario(), paths, delta), tr("Move Action"));
    if (!result) {
        emit problem(tr("Move Action: %1").arg(fromUtf8(result.error().message)));
        refresh();
    }
}

void PropertiesPanel::setCharacter(std::optional<int> character)
{
    m_character = character;
    refresh();
}

void PropertiesPanel::refresh()
{
    m_refreshing = true;
    if (m_document && m_action && actionAt(m_document->scenario(), *m_action)) {
        showAction();
    } else if (m_document && m_character && std::size_t(*m_character) < m_document->scenario().characters.size()) {
        m_pages->setCurrentWidget(m_characterPage);
        m_characterPage->show(m_document, *m_character);
    } else {
        showScenario();
    }
    m_refreshing = false;
}

void PropertiesPanel::showScenario()
{
    m_pages->setCurrentIndex(0);
    if (!m_document) {
        m_scenarioSummary->setText(tr("No scenario is open."));
        return;
    }
    const auto& scenario = m_document->scenario();
    int actions = 0;
    for (const auto& character : scenario.characters)
        for (const auto& layer : character.layers)
            actions += int(layer.actions.size());
    QString file = m_document->filePath().isEmpty() ? tr("not saved yet") : m_document->filePath().toHtmlEscaped();
    // An empty scenario says where to begin.
    const QString hint = scenario.characters.empty()
                             ? tr("<i>No characters yet: Character ▸ Add Character… adds one, then File ▸ Import "
                                  "Motion… brings in its motion capture.</i>")
                             : tr("<i>Select an action on the timeline, or a character in the scenario outline, to "
                                  "see and edit its properties.</i>");
    m_scenarioSummary->setText(
        tr("<b>%1</b><br>File: %2<br>%3, %4, %5 markers<br>Length: %6<br><br>%7")
            .arg(m_document->scenarioName().toHtmlEscaped(), file,
                 tr("%n character(s)", nullptr, int(scenario.characters.size())),
                 tr("%n action(s)", nullptr, actions))
            .arg(scenario.markers.size())
            .arg(seconds(core::ticksToSeconds(m_document->duration())), hint));
}

void PropertiesPanel::showAction()
{
    m_pages->setCurrentIndex(1);
    const auto& scenario = m_document->scenario();
    const auto& character = scenario.characters[std::size_t(m_action->character)];
    const auto& layer = character.layers[std::size_t(m_action->layer)];
    const ActionSpec& spec = *actionAt(scenario, *m_action);
    const bool editable = !layer.lock;

    m_owner->setText(tr("%1 ▸ %2%3").arg(fromUtf8(character.name), fromUtf8(layer.name),
                                         layer.lock ? tr(" (locked)") : QString()));
    m_name->setText(fromUtf8(spec.name));

    m_clip->clear();
    for (const auto& clip : character.clips)
        m_clip->addItem(fromUtf8(clip.name), fromUtf8(clip.name));
    m_clip->setCurrentIndex(m_clip->findData(fromUtf8(spec.clip)));

    m_start->setValue(core::ticksToSeconds(spec.start));
    m_mode->setCurrentIndex(m_mode->findData(int(spec.mode)));

    // A face layer's actions take face masks (its regions), a body layer's the others.
    const bool face = layer.kind == core::scenario::LayerKind::Face;
    m_maskLabel->setText(face ? tr("Face regions:") : tr("Body part:"));
    m_mask->clear();
    m_mask->addItem(face ? tr("Whole face") : tr("Whole body"), QString());
    for (const auto& mask : scenario.masks)
        if (core::scene::isFaceMask(mask.mask) == face || mask.name == spec.mask)
            m_mask->addItem(fromUtf8(mask.name), fromUtf8(mask.name));
    m_mask->setCurrentIndex(std::max(0, m_mask->findData(fromUtf8(spec.mask))));
    m_outsideDomain->setChecked(spec.renderOutsideDomain);
    m_placement->setCurrentIndex(std::max(0, m_placement->findData(int(spec.placement))));
    const auto loop = std::find_if(spec.modifiers.begin(), spec.modifiers.end(),
                                   [](const ModifierSpec& m) { return m.kind == ModifierKind::Loop; });
    m_repeat->setValue(loop == spec.modifiers.end() ? 1 : loop->count);
    m_rootMotion->setChecked(loop != spec.modifiers.end() && loop->rootMotion);
    m_rootMotion->setEnabled(editable && loop != spec.modifiers.end());

    const auto span = core::edit::actionSpan(scenario, m_document->runtime(), *m_action);
    if (!span)
        m_length->setText(tr("unknown"));
    else if (span->openEnded)
        m_length->setText(tr("open-ended (plays until cut off)"));
    else
        m_length->setText(seconds(core::ticksToSeconds(span->end - span->start)));

    const auto& weight = spec.weight;
    using core::anim::CurveKind;
    if (weight.kind() == CurveKind::Constant)
        m_fades->setText(tr("none (constant weight %1)").arg(weight.constantValue(), 0, 'g', 3));
    else if (weight.kind() == CurveKind::Keyframed)
        m_fades->setText(tr("keyframed weight curve (%n key(s))", nullptr, int(weight.keys().size())));
    else if (weight.kind() == CurveKind::Dominance)
        m_fades->setText(tr("none (dominance weight curve, α %1)").arg(weight.envelope().alpha, 0, 'g', 3));
    else
        m_fades->setText(tr("in %1, out %2").arg(seconds(weight.envelope().attack), seconds(weight.envelope().release)));

    QStringList modifiers;
    for (const ModifierSpec& modifier : spec.modifiers)
        modifiers << describeModifier(modifier);
    m_modifiers->setText(modifiers.isEmpty() ? tr("none") : modifiers.join(QStringLiteral(", ")));
    m_idle->show(m_document, m_action->character, spec.clip, editable);
    m_blinks->show(m_document, m_action->character, spec.clip, editable);
    // A gaze action plays no clip: what it looks at replaces what blends a clip.
    const bool gaze = layer.kind == core::scenario::LayerKind::Gaze;
    m_gaze->show(scenario, m_action->character, gaze ? spec.gaze : std::nullopt, editable);
    m_pointing->show(scenario, m_action->character, spec.pointing, layer.kind == core::scenario::LayerKind::Body, editable);
    for (QWidget* clipField : {static_cast<QWidget*>(m_clip), static_cast<QWidget*>(m_placement),
                               static_cast<QWidget*>(m_repeat), static_cast<QWidget*>(m_rootMotion),
                               static_cast<QWidget*>(m_mode), static_cast<QWidget*>(m_mask),
                               static_cast<QWidget*>(m_outsideDomain)})
        m_form->setRowVisible(clipField, !gaze);

    for (QWidget* field : {static_cast<QWidget*>(m_name), static_cast<QWidget*>(m_clip), static_cast<QWidget*>(m_start),
                           static_cast<QWidget*>(m_mode), static_cast<QWidget*>(m_mask), static_cast<QWidget*>(m_outsideDomain),
                           static_cast<QWidget*>(m_placement), static_cast<QWidget*>(m_repeat)})
        field->setEnabled(editable);
}

} // namespace thespis::editor
