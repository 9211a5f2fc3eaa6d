#include "editor/blink_properties.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>
#include <cmath>
#include <limits>

#include "editor/qt_conversions.h"

namespace thespis::editor {

namespace {

QSpinBox* millisecondsEdit(const QString& objectName, int minimum, const QString& tip, QWidget* parent)
{
    auto* edit = new QSpinBox(parent);
    edit->setObjectName(objectName);
    edit->setRange(minimum, 399);
    edit->setSuffix(QStringLiteral(" ms"));
    edit->setKeyboardTracking(false);
    edit->setToolTip(tip);
    return edit;
}

} // namespace

BlinkProperties::BlinkProperties(QWidget* parent) : ClipSettingsBox(tr("Blinks"), parent)
{
    setObjectName(QStringLiteral("blinkProperties"));
    auto* form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_rate = new QDoubleSpinBox(this);
    m_rate->setObjectName(QStringLiteral("blinkRate"));
    m_rate->setRange(1.0, 120.0);
    m_rate->setDecimals(1);
    m_rate->setSuffix(tr(" a minute"));
    m_rate->setKeyboardTracking(false);
    m_rate->setToolTip(tr("How often the eyes blink on average: about 17 a minute at rest, 26 in conversation"));
    auto* rest = new QPushButton(tr("At rest"), this);
    rest->setObjectName(QStringLiteral("blinkRateRest"));
    rest->setToolTip(tr("17 blinks a minute, as measured at rest"));
    auto* talking = new QPushButton(tr("Talking"), this);
    talking->setObjectName(QStringLiteral("blinkRateTalking"));
    talking->setToolTip(tr("26 blinks a minute, as measured in conversation"));
    auto* rateRow = new QHBoxLayout;
    rateRow->addWidget(m_rate, 1);
    rateRow->addWidget(rest);
    rateRow->addWidget(talking);
    m_seed = new QSpinBox(this);
    m_seed->setObjectName(QStringLiteral("blinkSeed"));
    m_seed->setRange(0, std::numeric_limits<int>::max());
    m_seed->setKeyboardTracking(false);
    m_seed->setToolTip(tr("Which random intervals the blinks follow: two characters with different seeds do not blink together"));
    const QString whole = tr("A whole blink takes less than 400 ms.");
    m_close = millisecondsEdit(QStringLiteral("blinkClose"), 10, tr("How long the lids take to close (about 100 ms). %1").arg(whole), this);
    m_shut = millisecondsEdit(QStringLiteral("blinkShut"), 0, tr("How long the eyes stay shut. %1").arg(whole), this);
    m_open = millisecondsEdit(QStringLiteral("blinkOpen"), 10, tr("How long the lids take to open again (slower than closing). %1").arg(whole), this);
    form->addRow(tr("Rate:"), rateRow);
    form->addRow(tr("Seed:"), m_seed);
    form->addRow(tr("Closing:"), m_close);
    form->addRow(tr("Shut:"), m_shut);
    form->addRow(tr("Opening:"), m_open);

    const auto setRate = [this](double rate) {
        editClip(tr("Change Blink Rate"), [&](core::scenario::ClipAsset& clip) { clip.blinks->rate = rate; });
    };
    connect(m_rate, &QDoubleSpinBox::valueChanged, this, setRate);
    connect(rest, &QPushButton::clicked, this, [setRate] { setRate(17); });
    connect(talking, &QPushButton::clicked, this, [setRate] { setRate(26); });
    connect(m_seed, &QSpinBox::valueChanged, this, [this](int seed) {
        editClip(tr("Change Blink Seed"), [&](core::scenario::ClipAsset& clip) { clip.blinks->seed = std::uint64_t(seed); });
    });
    const std::pair<QSpinBox*, double core::scenario::BlinkClip::*> times[] = {
        {m_close, &core::scenario::BlinkClip::closeSeconds},
        {m_shut, &core::scenario::BlinkClip::shutSeconds},
        {m_open, &core::scenario::BlinkClip::openSeconds}};
    for (const auto& [edit, field] : times)
        connect(edit, &QSpinBox::valueChanged, this, [this, field = field](int milliseconds) {
            editClip(tr("Change Blink Timing"), [&](core::scenario::ClipAsset& clip) { (*clip.blinks).*field = milliseconds / 1000.0; });
        });
    setVisible(false);
}

void BlinkProperties::show(Document* document, int character, const std::string& clip, bool editable)
{
    m_refreshing = true;
    const auto* asset = find(document, character, clip, [](const core::scenario::ClipAsset& c) { return c.blinks.has_value(); });
    if (asset) {
        const core::scenario::BlinkClip& blinks = *asset->blinks;
        m_rate->setValue(blinks.rate);
        m_seed->setValue(int(std::min<std::uint64_t>(blinks.seed, std::uint64_t(m_seed->maximum()))));
        // A whole blink takes less than 0.4 s: each time may grow only as far as the others leave.
        const int close = int(std::lround(blinks.closeSeconds * 1000)), shut = int(std::lround(blinks.shutSeconds * 1000)),
                  open = int(std::lround(blinks.openSeconds * 1000));
        m_close->setMaximum(std::max(m_close->minimum(), 399 - shut - open));
        m_shut->setMaximum(std::max(m_shut->minimum(), 399 - close - open));
        m_open->setMaximum(std::max(m_open->minimum(), 399 - close - shut));
        m_close->setValue(close);
        m_shut->setValue(shut);
        m_open->setValue(open);
        setTitle(tr("Blinks (clip \"%1\", shared by its actions)").arg(fromUtf8(asset->name)));
        for (QWidget* field : findChildren<QWidget*>())
            field->setEnabled(editable);
    }
    m_refreshing = false;
}

} // namespace thespis::editor
