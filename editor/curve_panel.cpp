#include "editor/curve_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "edit/document_edits.h"
#include "editor/commands/command_ids.h"
#include "editor/document.h"

namespace thespis::editor {

using core::anim::Curve;
using core::anim::CurveKind;
using core::anim::CurveKey;
using core::anim::TangentMode;

namespace {

constexpr int kSamples = 240;
constexpr double kOpenEndedSpan = 10.0; // seconds shown of an open-ended action
constexpr double kDefaultAlpha = 5.0;    // α offered for a new dominance curve: the paper's Fig. 9b

QDoubleSpinBox* spinBox(double max, double step, const QString& suffix, const QString& objectName, QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(0, max);
    box->setDecimals(3);
    box->setSingleStep(step);
    box->setSuffix(suffix);
    box->setObjectName(objectName);
    box->setKeyboardTracking(false);
    return box;
}

widgets::CurveTangent toView(TangentMode mode) { return widgets::CurveTangent(int(mode)); }
TangentMode fromView(widgets::CurveTangent mode) { return TangentMode(int(mode)); }

} // namespace

CurvePanel::CurvePanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("curvePanel"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* controls = new QVBoxLayout;
    m_title = new QLabel(this);
    m_title->setObjectName(QStringLiteral("curveTitle"));
    m_title->setWordWrap(true);
    controls->addWidget(m_title);
    auto* form = new QFormLayout;
    m_edited = new QComboBox(this);
    m_edited->setObjectName(QStringLiteral("editedCurve"));
    m_edited->addItems({tr("Weight"), tr("Scale")});
    m_preset = new QComboBox(this);
    m_preset->setObjectName(QStringLiteral("curvePreset"));
    m_preset->addItem(tr("Constant"), int(CurveKind::Constant));
    m_preset->addItem(tr("Linear fade"), int(CurveKind::LinearFade));
    m_preset->addItem(tr("Cubic fade"), int(CurveKind::CubicFade));
    m_preset->addItem(tr("Linear ADSR"), int(CurveKind::LinearAdsr));
    m_preset->addItem(tr("Cubic ADSR"), int(CurveKind::CubicAdsr));
    m_preset->addItem(tr("Dominance (coarticulation)"), int(CurveKind::Dominance));
    m_preset->addItem(tr("Keyframed"), int(CurveKind::Keyframed));
    const QString seconds = tr(" s");
    m_attack = spinBox(3600, 0.05, seconds, QStringLiteral("curveAttack"), this);
    m_decay = spinBox(3600, 0.05, seconds, QStringLiteral("curveDecay"), this);
    m_sustain = spinBox(1, 0.05, QString(), QStringLiteral("curveSustain"), this);
    m_release = spinBox(3600, 0.05, seconds, QStringLiteral("curveRelease"), this);
    m_peak = spinBox(100, 0.05, QString(), QStringLiteral("curvePeak"), this);
    m_alpha = spinBox(50, 0.5, QString(), QStringLiteral("curveAlpha"), this);
    m_alpha->setMinimum(0.1);
    m_alpha->setToolTip(tr("How sharply the dominance curve peaks (paper eq. 3): over the action, "
                           "C_α(x) = e^(−α·2|x−0.5|) − 2|x−0.5|·e^(−α), 0 at both ends and the peak in the middle. "
                           "A small α gives a broad hump, a large α a narrow spike."));
    form->addRow(tr("Edit"), m_edited);
    form->addRow(tr("Shape"), m_preset);
    form->addRow(tr("Attack / fade in"), m_attack);
    form->addRow(tr("Decay"), m_decay);
    form->addRow(tr("Sustain"), m_sustain);
    form->addRow(tr("Release / fade out"), m_release);
    form->addRow(tr("Peak / value"), m_peak);
    form->addRow(tr("Dominance α"), m_alpha);
    m_keyTime = spinBox(3600, 0.01, seconds, QStringLiteral("keyTime"), this);
    m_keyValue = spinBox(100, 0.05, QString(), QStringLiteral("keyValue"), this);
    m_keyValue->setMinimum(-100);
    form->addRow(tr("Key time"), m_keyTime);
    form->addRow(tr("Key value"), m_keyValue);
    controls->addLayout(form);
    controls->addStretch(1);
    layout->addLayout(controls);
    m_view = new widgets::CurveView(this);
    m_view->setObjectName(QStringLiteral("curveView"));
    layout->addWidget(m_view, 1);

    connect(m_edited, &QComboBox::currentIndexChanged, this, [this] { refreshControls(); });
    connect(m_preset, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_updating)
            onPresetEdited(-1);
    });
    for (QDoubleSpinBox* box : {m_attack, m_decay, m_sustain, m_release, m_peak, m_alpha}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
            if (!m_updating)
                onPresetEdited(CurveParameterId);
        });
        // Enter or leaving the box ends its undo step: setting the attack and then the peak is two
        // steps. The empty edit only closes the step; it cannot fail.
        connect(box, &QDoubleSpinBox::editingFinished, this, [this] {
            if (m_document)
                (void)m_document->edit(core::edit::Edit(), QString(), Merge{CurveParameterId, true});
        });
    }
    for (QDoubleSpinBox* box : {m_keyTime, m_keyValue})
        connect(box, &QDoubleSpinBox::valueChanged, this, [this] {
            if (!m_updating)
                onKeyValueEdited();
        });
    connect(m_view, &widgets::CurveView::selectionChanged, this, &CurvePanel::refreshControls);
    connect(m_view, &widgets::CurveView::keyAddRequested, this, &CurvePanel::onKeyAdd);
    connect(m_view, &widgets::CurveView::keysMoveRequested, this, &CurvePanel::onKeysMove);
    connect(m_view, &widgets::CurveView::keysDeleteRequested, this, [this](const QList<widgets::CurveKeyRef>& refs) {
        for (int c : {WeightCurve, ScaleCurve}) {
            const Curve* source = curve(c);
            if (!source || source->kind() != CurveKind::Keyframed)
                continue;
            std::vector<CurveKey> keys;
            for (int k = 0; k < int(source->keys().size()); ++k)
                if (!refs.contains(widgets::CurveKeyRef{c, k}))
                    keys.push_back(source->keys()[std::size_t(k)]);
            if (keys.size() != source->keys().size())
                applyCurve(c, keys.empty() ? core::Result<Curve>(core::makeError(core::ErrorCode::InvalidArgument,
                                                                                 "A keyframed curve keeps at least one key; choose another shape to replace it."))
                                           : Curve::keyframed(std::move(keys)),
                           tr("Delete Curve Keys"));
        }
    });
    connect(m_view, &widgets::CurveView::tangentRequested, this,
            [this](widgets::CurveKeyRef ref, double inSlope, double outSlope, bool finished) {
                const Curve* source = curve(ref.curve);
                if (!source || source->kind() != CurveKind::Keyframed || ref.key >= int(source->keys().size()))
                    return;
                std::vector<CurveKey> keys = source->keys();
                keys[std::size_t(ref.key)].inSlope = inSlope;
                keys[std::size_t(ref.key)].outSlope = outSlope;
                applyCurve(ref.curve, Curve::keyframed(std::move(keys)), tr("Change Tangent"), CurveTangentId, finished);
            });
    connect(m_view, &widgets::CurveView::tangentModeRequested, this,
            [this](const QList<widgets::CurveKeyRef>& refs, widgets::CurveTangent mode) {
                for (int c : {WeightCurve, ScaleCurve}) {
                    const Curve* source = curve(c);
                    if (!source || source->kind() != CurveKind::Keyframed)
                        continue;
                    std::vector<CurveKey> keys = source->keys();
                    bool changed = false;
                    for (const widgets::CurveKeyRef& ref : refs)
                        if (ref.curve == c && ref.key >= 0 && ref.key < int(keys.size())) {
                            keys[std::size_t(ref.key)].mode = fromView(mode);
                            changed = true;
                        }
                    if (changed)
                        applyCurve(c, Curve::keyframed(std::move(keys)), tr("Set Tangent Mode"));
                }
            });
    setAction(std::nullopt);
}

void CurvePanel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_action.reset();
    if (m_document)
        connect(m_document, &Document::edited, this, [this] { refresh(); });
    refresh();
}

void CurvePanel::setAction(std::optional<core::edit::ActionPath> action)
{
    m_action = action;
    m_view->setSelectedKeys({});
    refresh();
}

void CurvePanel::setTime(core::Tick time)
{
    m_time = time;
    if (!curve(WeightCurve))
        return;
    const auto& p = *m_action;
    const core::Tick start =
        m_document->scenario().characters[std::size_t(p.character)].layers[std::size_t(p.layer)].actions[std::size_t(p.action)].start;
    m_view->setPlayhead(core::ticksToSeconds(time - start));
}

void CurvePanel::setEditedCurve(CurveIndex curve)
{
    m_edited->setCurrentIndex(int(curve));
}

const Curve* CurvePanel::curve(int index) const
{
    if (!m_document || !m_action)
        return nullptr;
    const auto& characters = m_document->scenario().characters;
    const auto& p = *m_action;
    if (std::size_t(p.character) >= characters.size() || std::size_t(p.layer) >= characters[std::size_t(p.character)].layers.size())
        return nullptr;
    const auto& actions = characters[std::size_t(p.character)].layers[std::size_t(p.layer)].actions;
    if (std::size_t(p.action) >= actions.size())
        return nullptr;
    return index == WeightCurve ? &actions[std::size_t(p.action)].weight : &actions[std::size_t(p.action)].scale;
}

void CurvePanel::refresh()
{
    const Curve* weight = curve(WeightCurve);
    if (!weight) {
        m_action.reset();
        m_title->setText(tr("Select an action on the timeline to edit its curves."));
        m_view->setCurves({});
        m_view->setPlaceholderText(tr("No action selected"));
        refreshControls();
        return;
    }
    const auto& p = *m_action;
    const auto& character = m_document->scenario().characters[std::size_t(p.character)];
    const auto& spec = character.layers[std::size_t(p.layer)].actions[std::size_t(p.action)];
    m_title->setText(tr("<b>%1</b><br>%2 · %3").arg(QString::fromStdString(spec.name).toHtmlEscaped(),
                                                      QString::fromStdString(character.name).toHtmlEscaped(),
                                                      QString::fromStdString(character.layers[std::size_t(p.layer)].name).toHtmlEscaped()));
    const auto span = core::edit::actionSpan(m_document->scenario(), m_document->runtime(), p);
    m_duration = span && !span->openEnded ? core::ticksToSeconds(span->end - span->start) : Curve::Infinite;
    const double shown = std::isfinite(m_duration) ? m_duration : kOpenEndedSpan;
    QVector<widgets::CurveViewCurve> curves;
    const std::pair<const Curve*, std::pair<QString, QColor>> items[] = {
        {weight, {tr("Weight"), QColor(80, 160, 255)}},
        {curve(ScaleCurve), {tr("Scale"), QColor(255, 170, 60)}},
    };
    for (const auto& [source, look] : items) {
        widgets::CurveViewCurve item;
        item.name = look.first;
        item.color = look.second;
        item.samples.reserve(kSamples + 1);
        for (int i = 0; i <= kSamples; ++i) {
            const double t = shown * i / kSamples;
            item.samples.push_back(QPointF(t, source->evaluate(t, m_duration)));
        }
        if (source->kind() == CurveKind::Keyframed) {
            item.keyable = true;
            for (const CurveKey& key : source->keys())
                item.keys.push_back({key.time, key.value, toView(key.mode), key.inSlope,
                                     key.mode == TangentMode::Broken ? key.outSlope : key.inSlope});
        }
        curves.push_back(std::move(item));
    }
    m_view->setTimeRange(0.0, m_duration);
    m_view->setCurves(std::move(curves));
    setTime(m_time);
    refreshControls();
}

void CurvePanel::refreshControls()
{
    m_updating = true;
    const Curve* edited = curve(m_edited->currentIndex());
    for (QWidget* w : std::initializer_list<QWidget*>{m_edited, m_preset, m_attack, m_decay, m_sustain, m_release, m_peak, m_alpha})
        w->setEnabled(edited != nullptr);
    if (edited) {
        m_preset->setCurrentIndex(m_preset->findData(int(edited->kind())));
        const auto& e = edited->envelope();
        const bool dominance = edited->kind() == CurveKind::Dominance;
        const bool fades = edited->kind() != CurveKind::Constant && edited->kind() != CurveKind::Keyframed && !dominance;
        const bool adsr = edited->kind() == CurveKind::LinearAdsr || edited->kind() == CurveKind::CubicAdsr;
        m_attack->setEnabled(fades);
        m_release->setEnabled(fades);
        m_decay->setEnabled(adsr);
        m_sustain->setEnabled(adsr);
        m_peak->setEnabled(edited->kind() != CurveKind::Keyframed);
        m_alpha->setEnabled(dominance);
        m_attack->setValue(e.attack);
        m_decay->setValue(e.decay);
        m_sustain->setValue(e.sustain);
        m_release->setValue(e.release);
        m_peak->setValue(e.peak);
        m_alpha->setValue(dominance ? e.alpha : kDefaultAlpha);
    }
    // Numeric entry for one selected key.
    const QList<widgets::CurveKeyRef> selected = m_view->selectedKeys();
    const Curve* keyed = selected.size() == 1 ? curve(selected.front().curve) : nullptr;
    const bool oneKey = keyed && keyed->kind() == CurveKind::Keyframed && selected.front().key < int(keyed->keys().size());
    m_keyTime->setEnabled(oneKey);
    m_keyValue->setEnabled(oneKey);
    if (oneKey) {
        m_keyTime->setValue(keyed->keys()[std::size_t(selected.front().key)].time);
        m_keyValue->setValue(keyed->keys()[std::size_t(selected.front().key)].value);
    }
    m_updating = false;
}

Curve CurvePanel::presetCurve() const
{
    const double a = m_attack->value(), d = m_decay->value(), s = m_sustain->value(), r = m_release->value(),
                 peak = m_peak->value();
    switch (CurveKind(m_preset->currentData().toInt())) {
    case CurveKind::Constant: return Curve::constant(peak);
    case CurveKind::LinearFade: return Curve::linearFade(a, r, peak);
    case CurveKind::CubicFade: return Curve::cubicFade(a, r, peak);
    case CurveKind::LinearAdsr: return Curve::linearAdsr(a, d, s, r, peak);
    case CurveKind::CubicAdsr: return Curve::cubicAdsr(a, d, s, r, peak);
    case CurveKind::Dominance: return Curve::dominance(m_alpha->value(), peak);
    case CurveKind::Keyframed: break;
    }
    // Keyframed from a preset: keys where the current curve turns, so the shape carries over.
    const Curve* current = curve(m_edited->currentIndex());
    const double length = std::isfinite(m_duration) ? m_duration : kOpenEndedSpan;
    std::vector<CurveKey> keys;
    std::vector<double> times{0.0, length};
    if (current && current->kind() == CurveKind::Dominance) {
        times = {0.0, length / 4, length / 2, 3 * length / 4, length}; // its rise, peak and fall
    } else if (current && current->kind() != CurveKind::Constant) {
        const auto& e = current->envelope();
        times = {0.0, e.attack, e.attack + e.decay, length - e.release, length};
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](double x, double y) { return std::abs(x - y) < 1e-6; }),
                times.end());
    for (double t : times)
        keys.push_back({t, current ? current->evaluate(t, m_duration) : 1.0, TangentMode::AutoClamped, 0, 0});
    auto keyed = Curve::keyframed(std::move(keys));
    return keyed ? *keyed : Curve();
}

void CurvePanel::applyCurve(int index, core::Result<Curve> curve, const QString& text, int mergeKey, bool finished)
{
    if (!m_document || !m_action)
        return;
    if (!curve) {
        emit problem(QString::fromStdString(curve.error().message));
        return;
    }
    auto edit = core::edit::setActionCurves(m_document->scenario(), *m_action,
                                            index == WeightCurve ? std::optional<Curve>(*curve) : std::nullopt,
                                            index == ScaleCurve ? std::optional<Curve>(*curve) : std::nullopt);
    if (auto done = m_document->edit(std::move(edit), text, Merge{mergeKey, finished}); !done)
        emit problem(QString::fromStdString(done.error().message));
}

void CurvePanel::onPresetEdited(int mergeKey)
{
    // Spin boxes merge while the user keeps stepping one; a preset change is a step of its own.
    applyCurve(m_edited->currentIndex(), presetCurve(),
               m_edited->currentIndex() == WeightCurve ? tr("Change Weight Curve") : tr("Change Scale Curve"), mergeKey,
               mergeKey < 0);
}

void CurvePanel::onKeyAdd(int index, QPointF at)
{
    const Curve* source = curve(index);
    if (!source || source->kind() != CurveKind::Keyframed)
        return;
    std::vector<CurveKey> keys = source->keys();
    keys.push_back({std::max(0.0, at.x()), at.y(), TangentMode::AutoClamped, 0, 0});
    applyCurve(index, Curve::keyframed(std::move(keys)), tr("Add Curve Key"));
}

void CurvePanel::onKeysMove(const QList<widgets::CurveKeyRef>& refs, QPointF delta, bool finished)
{
    if (refs.isEmpty())
        return;
    const int index = refs.front().curve;
    if (!m_dragStart || m_dragCurve != index) {
        const Curve* source = curve(index);
        if (!source || source->kind() != CurveKind::Keyframed)
            return;
        m_dragStart = *source;
        m_dragCurve = index;
    }
    std::vector<CurveKey> keys = m_dragStart->keys();
    for (const widgets::CurveKeyRef& ref : refs)
        if (ref.curve == index && ref.key >= 0 && ref.key < int(keys.size())) {
            keys[std::size_t(ref.key)].time = std::max(0.0, keys[std::size_t(ref.key)].time + delta.x());
            keys[std::size_t(ref.key)].value += delta.y();
        }
    applyCurve(index, Curve::keyframed(std::move(keys)), tr("Move %n Curve Key(s)", nullptr, int(refs.size())),
               MoveCurveKeysId, finished);
    if (finished)
        m_dragStart.reset();
}

void CurvePanel::onKeyValueEdited()
{
    const QList<widgets::CurveKeyRef> selected = m_view->selectedKeys();
    if (selected.size() != 1)
        return;
    const Curve* source = curve(selected.front().curve);
    if (!source || source->kind() != CurveKind::Keyframed || selected.front().key >= int(source->keys().size()))
        return;
    std::vector<CurveKey> keys = source->keys();
    keys[std::size_t(selected.front().key)].time = m_keyTime->value();
    keys[std::size_t(selected.front().key)].value = m_keyValue->value();
    applyCurve(selected.front().curve, Curve::keyframed(std::move(keys)), tr("Set Curve Key"));
}

} // namespace thespis::editor
