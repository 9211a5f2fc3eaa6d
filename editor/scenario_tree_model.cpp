#include "editor/scenario_tree_model.h"

#include <QFont>
#include <QPainter>
#include <QPalette>
#include <QPixmap>

#include <cmath>

#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "widgets/pose_view.h"

namespace thespis::editor {

namespace {

QString seconds(double value)
{
    return QString::number(value, 'f', 3);
}

QIcon dotIcon(const QColor& fill, const QColor& outline, bool filled)
{
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(outline, 1.5));
    painter.setBrush(filled ? QBrush(fill) : QBrush(Qt::NoBrush));
    painter.drawEllipse(QRectF(3.5, 3.5, 9, 9));
    return QIcon(pixmap);
}

QIcon swatchIcon(const QColor& color)
{
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(color.darker(150), 1));
    painter.setBrush(color);
    painter.drawRoundedRect(QRectF(1.5, 2.5, 13, 11), 3, 3);
    return QIcon(pixmap);
}

QString describeModifier(const core::scenario::ModifierSpec& modifier)
{
    using core::scenario::ModifierKind;
    switch (modifier.kind) {
    case ModifierKind::TimeStretch: return ScenarioTreeModel::tr("stretch ×%1").arg(modifier.factor);
    case ModifierKind::TimeWarp: return ScenarioTreeModel::tr("time warp over %1 s").arg(modifier.duration);
    case ModifierKind::Loop:
        return modifier.count == 0 ? ScenarioTreeModel::tr("loop forever") : ScenarioTreeModel::tr("loop %n time(s)", nullptr, modifier.count);
    case ModifierKind::Mirror: return ScenarioTreeModel::tr("mirror");
    case ModifierKind::GlobalTransform: return ScenarioTreeModel::tr("move/rotate");
    case ModifierKind::TimeOffset: return ScenarioTreeModel::tr("offset %1 s").arg(modifier.offset);
    case ModifierKind::Trim: return ScenarioTreeModel::tr("trim %1–%2 s").arg(modifier.start).arg(modifier.end);
    case ModifierKind::DependentJointFilter: return ScenarioTreeModel::tr("dependent joints");
    }
    return {};
}

} // namespace

QString describeCurve(const core::anim::Curve& curve)
{
    // Short enough for a table cell; the column's tooltip says what the numbers are.
    using core::anim::CurveKind;
    const core::anim::EnvelopeParams& e = curve.envelope();
    const QString peak = e.peak == 1.0 ? QString() : ScenarioTreeModel::tr(", peak %1").arg(e.peak);
    switch (curve.kind()) {
    case CurveKind::Constant: return ScenarioTreeModel::tr("constant %1").arg(curve.constantValue());
    case CurveKind::LinearFade: return ScenarioTreeModel::tr("linear fade %1 / %2 s").arg(e.attack).arg(e.release) + peak;
    case CurveKind::CubicFade: return ScenarioTreeModel::tr("cubic fade %1 / %2 s").arg(e.attack).arg(e.release) + peak;
    case CurveKind::LinearAdsr:
        return ScenarioTreeModel::tr("linear ADSR %1 / %2 / %3 / %4").arg(e.attack).arg(e.decay).arg(e.sustain).arg(e.release) + peak;
    case CurveKind::CubicAdsr:
        return ScenarioTreeModel::tr("cubic ADSR %1 / %2 / %3 / %4").arg(e.attack).arg(e.decay).arg(e.sustain).arg(e.release) + peak;
    case CurveKind::Keyframed: return ScenarioTreeModel::tr("keyframed, %n key(s)", nullptr, int(curve.keys().size()));
    case CurveKind::Dominance: return ScenarioTreeModel::tr("dominance α %1").arg(e.alpha) + peak;
    }
    return {};
}

QString describeBlendMode(core::anim::BlendMode mode)
{
    switch (mode) {
    case core::anim::BlendMode::Normalized: return ScenarioTreeModel::tr("normalized");
    case core::anim::BlendMode::Additive: return ScenarioTreeModel::tr("additive");
    case core::anim::BlendMode::Override: return ScenarioTreeModel::tr("override");
    }
    return {};
}

ScenarioTreeModel::ScenarioTreeModel(QObject* parent) : QAbstractItemModel(parent)
{
    m_activeIcon = dotIcon(QColor(0x3c, 0xb3, 0x71), QColor(0x2a, 0x80, 0x50), true);
    m_idleIcon = dotIcon(QColor(), QColor(0x9a, 0xa0, 0xa6), false);
}

void ScenarioTreeModel::setDocument(const Document* document)
{
    beginResetModel();
    m_document = document;
    rebuild();
    endResetModel();
}

void ScenarioTreeModel::rebuild()
{
    m_nodes.clear();
    m_topLevel.clear();
    m_characterIcons.clear();
    if (!m_document)
        return;
    const core::scenario::Scenario& scenario = m_document->scenario();
    for (int c = 0; c < int(scenario.characters.size()); ++c) {
        const int characterNode = int(m_nodes.size());
        m_nodes.push_back({NodeKind::Character, c, -1, -1, -1, int(m_topLevel.size()), {}, false});
        m_topLevel.push_back(characterNode);
        m_characterIcons.push_back(swatchIcon(widgets::figureColor(c)));
        const core::scenario::Character& character = scenario.characters[std::size_t(c)];
        for (int l = 0; l < int(character.layers.size()); ++l) {
            const int layerNode = int(m_nodes.size());
            m_nodes.push_back({NodeKind::Layer, c, l, -1, characterNode, l, {}, false});
            m_nodes[std::size_t(characterNode)].children.push_back(layerNode);
            for (int a = 0; a < int(character.layers[std::size_t(l)].actions.size()); ++a) {
                const int actionNode = int(m_nodes.size());
                m_nodes.push_back({NodeKind::Action, c, l, a, layerNode, a, {}, false});
                m_nodes[std::size_t(layerNode)].children.push_back(actionNode);
            }
        }
    }
}

void ScenarioTreeModel::setTime(core::Tick time)
{
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        Node& node = m_nodes[i];
        if (node.kind != NodeKind::Action)
            continue;
        const bool active = actionActive(node, time);
        if (active == node.active)
            continue;
        node.active = active;
        const QModelIndex first = createIndex(node.row, 0, quintptr(i));
        const QModelIndex last = createIndex(node.row, ColumnCount - 1, quintptr(i));
        emit dataChanged(first, last, {Qt::DecorationRole, Qt::FontRole, ActiveRole, Qt::ToolTipRole});
    }
}

bool ScenarioTreeModel::actionActive(const Node& node, core::Tick time) const
{
    const double seconds = core::ticksToSeconds(time); // the schedule's own time
    const core::scenario::ScenarioRuntime& runtime = m_document->runtime();
    if (node.character >= int(runtime.characters.size()))
        return false;
    const core::scenario::CharacterRuntime& character = runtime.characters[std::size_t(node.character)];
    if (node.layer >= int(character.layers.size()) || node.layer >= int(character.actionIds.size()))
        return false;
    const auto& ids = character.actionIds[std::size_t(node.layer)];
    if (node.action >= int(ids.size()))
        return false;
    const core::anim::BlendingSchedule& schedule = *character.layers[std::size_t(node.layer)];
    const core::anim::ActionId id = ids[std::size_t(node.action)];
    const core::anim::BlendingAction* action = schedule.action(id);
    return action && seconds >= action->start && !schedule.isFinished(id, seconds);
}

const ScenarioTreeModel::Node* ScenarioTreeModel::nodeOf(const QModelIndex& index) const
{
    if (!index.isValid() || index.internalId() >= m_nodes.size())
        return nullptr;
    return &m_nodes[std::size_t(index.internalId())];
}

std::optional<ScenarioTreeModel::Location> ScenarioTreeModel::locationOf(const QModelIndex& index) const
{
    const Node* node = nodeOf(index);
    if (!node)
        return std::nullopt;
    return Location{node->kind, node->character, node->layer, node->action};
}

QModelIndex ScenarioTreeModel::indexOf(int character, int layer) const
{
    for (std::size_t n = 0; n < m_nodes.size(); ++n) {
        const Node& node = m_nodes[n];
        const bool wanted = layer < 0 ? node.kind == NodeKind::Character : node.kind == NodeKind::Layer && node.layer == layer;
        if (wanted && node.character == character)
            return createIndex(node.row, 0, quintptr(n));
    }
    return {};
}

QModelIndex ScenarioTreeModel::index(int row, int column, const QModelIndex& parent) const
{
    if (column < 0 || column >= ColumnCount || row < 0)
        return {};
    const std::vector<int>* children = &m_topLevel;
    if (parent.isValid()) {
        const Node* node = nodeOf(parent);
        if (!node)
            return {};
        children = &node->children;
    }
    if (row >= int(children->size()))
        return {};
    return createIndex(row, column, quintptr((*children)[std::size_t(row)]));
}

QModelIndex ScenarioTreeModel::parent(const QModelIndex& child) const
{
    const Node* node = nodeOf(child);
    if (!node || node->parent < 0)
        return {};
    return createIndex(m_nodes[std::size_t(node->parent)].row, 0, quintptr(node->parent));
}

int ScenarioTreeModel::rowCount(const QModelIndex& parent) const
{
    if (!parent.isValid())
        return int(m_topLevel.size());
    if (parent.column() != 0)
        return 0;
    const Node* node = nodeOf(parent);
    return node ? int(node->children.size()) : 0;
}

int ScenarioTreeModel::columnCount(const QModelIndex&) const
{
    return ColumnCount;
}

QVariant ScenarioTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::DisplayRole) {
        switch (section) {
        case NameColumn: return tr("Name");
        case ClipColumn: return tr("Clip");
        case StartColumn: return tr("Start (s)");
        case ModeColumn: return tr("Mode");
        case WeightColumn: return tr("Weight curve");
        case MaskColumn: return tr("Mask");
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case NameColumn:
            return tr("Characters, their animation layers, and the actions in each layer.\n"
                      "A green dot marks an action that plays at the current time.");
        case ClipColumn: return tr("The motion clip an action plays");
        case StartColumn: return tr("When the action starts, in seconds from the start of the scenario");
        case ModeColumn: return tr("How the action or layer blends with the ones below it");
        case WeightColumn:
            return tr("How the action's weight rises and falls over its length.\n"
                      "Fades: fade-in / fade-out seconds. ADSR: attack / decay seconds, sustain level, release seconds.");
        case MaskColumn: return tr("Which joints the action moves (empty: the whole body)");
        default: return {};
        }
    }
    return {};
}

QVariant ScenarioTreeModel::data(const QModelIndex& index, int role) const
{
    const Node* node = nodeOf(index);
    if (!node || !m_document)
        return {};
    switch (role) {
    case Qt::DisplayRole: return displayData(*node, index.column());
    case Qt::ToolTipRole: return toolTip(*node);
    case NodeKindRole: return int(node->kind);
    case ActiveRole: return node->active;
    case Qt::DecorationRole:
        if (index.column() != NameColumn)
            return {};
        if (node->kind == NodeKind::Character)
            return m_characterIcons[std::size_t(node->character)];
        if (node->kind == NodeKind::Action)
            return node->active ? m_activeIcon : m_idleIcon;
        return {};
    case Qt::FontRole:
        if (node->kind == NodeKind::Character || (node->kind == NodeKind::Action && node->active && index.column() == NameColumn)) {
            QFont font;
            font.setBold(true);
            return font;
        }
        return {};
    case Qt::ForegroundRole:
        // Summaries on character and layer rows are secondary to the action rows below them.
        if (node->kind != NodeKind::Action && index.column() != NameColumn)
            return QPalette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == StartColumn)
            return QVariant(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    default: return {};
    }
}

QVariant ScenarioTreeModel::displayData(const Node& node, int column) const
{
    const core::scenario::Character& character = m_document->scenario().characters[std::size_t(node.character)];
    if (node.kind == NodeKind::Character) {
        switch (column) {
        case NameColumn: return fromUtf8(character.name);
        case ClipColumn: return tr("%n clip(s)", nullptr, int(character.clips.size()));
        default: return {};
        }
    }
    const core::scenario::Layer& layer = character.layers[std::size_t(node.layer)];
    if (node.kind == NodeKind::Layer) {
        switch (column) {
        case NameColumn:
            return layer.name.empty() ? tr("Layer %1").arg(node.layer + 1) : fromUtf8(layer.name);
        case ClipColumn:
            switch (layer.kind) {
            case core::scenario::LayerKind::Body: return tr("body layer");
            case core::scenario::LayerKind::Face: return tr("face layer");
            case core::scenario::LayerKind::Gaze: return tr("gaze layer");
            }
            return {};
        case ModeColumn: return node.layer == 0 ? tr("base") : describeBlendMode(layer.mode);
        default: return {};
        }
    }
    const core::scenario::ActionSpec& action = layer.actions[std::size_t(node.action)];
    switch (column) {
    case NameColumn: return action.name.empty() ? tr("Action %1").arg(node.action + 1) : fromUtf8(action.name);
    case ClipColumn: return fromUtf8(action.clip);
    case StartColumn: return seconds(core::ticksToSeconds(action.start));
    case ModeColumn: return describeBlendMode(action.mode);
    case WeightColumn: return describeCurve(action.weight);
    case MaskColumn: return action.mask.empty() ? tr("whole body") : fromUtf8(action.mask);
    default: return {};
    }
}

QString ScenarioTreeModel::toolTip(const Node& node) const
{
    const core::scenario::Character& character = m_document->scenario().characters[std::size_t(node.character)];
    if (node.kind == NodeKind::Character)
        return tr("Character “%1”: %2 skeleton").arg(fromUtf8(character.name), fromUtf8(character.skeleton));
    const core::scenario::Layer& layer = character.layers[std::size_t(node.layer)];
    if (node.kind == NodeKind::Layer)
        return node.layer == 0 ? tr("The base layer: its actions blend with each other")
                               : tr("Blends %1 over the layers above it").arg(describeBlendMode(layer.mode));
    const core::scenario::ActionSpec& action = layer.actions[std::size_t(node.action)];
    QString text = tr("Plays clip “%1” from %2 s").arg(fromUtf8(action.clip), seconds(core::ticksToSeconds(action.start)));
    // The end comes from the built schedule: it depends on the clip's length and modifiers.
    const core::scenario::ScenarioRuntime& runtime = m_document->runtime();
    if (node.character < int(runtime.characters.size())) {
        const core::scenario::CharacterRuntime& rt = runtime.characters[std::size_t(node.character)];
        if (node.layer < int(rt.actionIds.size()) && node.action < int(rt.actionIds[std::size_t(node.layer)].size())) {
            const double end = rt.layers[std::size_t(node.layer)]->endTime(rt.actionIds[std::size_t(node.layer)][std::size_t(node.action)]);
            text += std::isinf(end) ? tr(", without end") : tr(" to %1 s").arg(seconds(end));
        }
    }
    text += QLatin1Char('\n') + tr("Weight: %1").arg(describeCurve(action.weight));
    text += QLatin1Char('\n') + tr("Moves: %1").arg(action.mask.empty() ? tr("the whole body") : tr("mask “%1”").arg(fromUtf8(action.mask)));
    QStringList modifiers;
    for (const core::scenario::ModifierSpec& modifier : action.modifiers)
        modifiers << describeModifier(modifier);
    if (!modifiers.isEmpty())
        text += QLatin1Char('\n') + tr("Modifiers: %1").arg(modifiers.join(QStringLiteral(", ")));
    if (node.active)
        text += QLatin1Char('\n') + tr("Playing now");
    return text;
}

} // namespace thespis::editor
