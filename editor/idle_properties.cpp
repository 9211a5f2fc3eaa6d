#include "editor/idle_properties.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

#include <limits>

#include "editor/document.h"
#include "editor/qt_conversions.h"

namespace thespis::editor {

IdleProperties::IdleProperties(QWidget* parent) : ClipSettingsBox(tr("Idle motion"), parent)
{
    setObjectName(QStringLiteral("idleProperties"));
    auto* form = new QFormLayout(this);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_database = new QLabel(this);
    m_database->setObjectName(QStringLiteral("idleDatabase"));
    m_database->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_choose = new QPushButton(tr("Choose…"), this);
    m_choose->setObjectName(QStringLiteral("idleChooseDatabase"));
    m_choose->setToolTip(tr("Play another idle motion database (.idle, made by thespis-cli build-idle)"));
    auto* databaseRow = new QHBoxLayout;
    databaseRow->addWidget(m_database, 1);
    databaseRow->addWidget(m_choose);
    m_seed = new QSpinBox(this);
    m_seed->setObjectName(QStringLiteral("idleSeed"));
    m_seed->setRange(0, std::numeric_limits<int>::max());
    m_seed->setKeyboardTracking(false);
    m_seed->setToolTip(tr("Which motion program the character follows: characters with different seeds shift their "
                          "weight at different times"));
    m_amplitude = new QDoubleSpinBox(this);
    m_amplitude->setObjectName(QStringLiteral("idleAmplitude"));
    m_amplitude->setRange(0.0, 10.0);
    m_amplitude->setDecimals(2);
    m_amplitude->setSingleStep(0.1);
    m_amplitude->setKeyboardTracking(false);
    m_amplitude->setToolTip(tr("Size of the small posture variations: 0 none, 1 as much as in the recordings"));
    form->addRow(tr("Database:"), databaseRow);
    form->addRow(tr("Seed:"), m_seed);
    form->addRow(tr("Variations:"), m_amplitude);

    connect(m_seed, &QSpinBox::valueChanged, this, [this](int seed) {
        editClip(tr("Change Idle Seed"), [&](core::scenario::ClipAsset& clip) { clip.idle->seed = std::uint64_t(seed); });
    });
    connect(m_amplitude, &QDoubleSpinBox::valueChanged, this, [this](double amplitude) {
        editClip(tr("Change Idle Variations"), [&](core::scenario::ClipAsset& clip) { clip.idle->amplitude = amplitude; });
    });
    connect(m_choose, &QPushButton::clicked, this, [this] {
        if (!document())
            return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose an Idle Motion Database"), document()->baseDir(),
                                                          tr("Idle motion databases (*.idle)"));
        if (!path.isEmpty())
            setDatabase(path);
    });
    setVisible(false);
}

void IdleProperties::show(Document* document, int character, const std::string& clip, bool editable)
{
    m_refreshing = true;
    const auto* asset = find(document, character, clip, [](const core::scenario::ClipAsset& c) { return c.idle.has_value(); });
    if (asset) {
        const auto& idle = *asset->idle;
        m_database->setText(QFileInfo(fromUtf8(idle.database)).fileName());
        m_database->setToolTip(fromUtf8(idle.database));
        m_seed->setValue(int(std::min<std::uint64_t>(idle.seed, std::uint64_t(m_seed->maximum()))));
        m_amplitude->setValue(idle.amplitude);
        setTitle(tr("Idle motion (clip \"%1\", shared by its actions)").arg(fromUtf8(asset->name)));
        for (QWidget* field : {static_cast<QWidget*>(m_choose), static_cast<QWidget*>(m_seed),
                               static_cast<QWidget*>(m_amplitude)})
            field->setEnabled(editable);
    }
    m_refreshing = false;
}

void IdleProperties::setDatabase(const QString& path)
{
    if (!document())
        return;
    // Named as the scenario names its files: relative to its folder.
    const std::string database = QDir::fromNativeSeparators(QDir(document()->baseDir()).relativeFilePath(path)).toStdString();
    editClip(tr("Change Idle Database"), [&](core::scenario::ClipAsset& clip) { clip.idle->database = database; });
}

} // namespace thespis::editor
