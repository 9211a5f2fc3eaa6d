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

#include "edit/content_edits.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"

namespace thespis::editor {

IdleProperties::IdleProperties(QWidget* parent) : QGroupBox(tr("Idle motion"), parent)
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
        editClip(tr("Change Idle Seed"), [&](core::scenario::IdleSynthesizer& idle) { idle.seed = std::uint64_t(seed); });
    });
    connect(m_amplitude, &QDoubleSpinBox::valueChanged, this, [this](double amplitude) {
        editClip(tr("Change Idle Variations"), [&](core::scenario::IdleSynthesizer& idle) { idle.amplitude = amplitude; });
    });
    connect(m_choose, &QPushButton::clicked, this, [this] {
        if (!m_document)
            return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose an Idle Motion Database"), m_document->baseDir(),
                                                          tr("Idle motion databases (*.idle)"));
        if (!path.isEmpty())
            setDatabase(path);
    });
    setVisible(false);
}

void IdleProperties::show(Document* document, int character, const std::string& clip, bool editable)
{
    m_refreshing = true;
    m_document = document;
    m_character = -1;
    m_clip = -1;
    const core::scenario::ClipAsset* asset = nullptr;
    if (document && character >= 0 && std::size_t(character) < document->scenario().characters.size()) {
        const auto& clips = document->scenario().characters[std::size_t(character)].clips;
        for (std::size_t i = 0; i < clips.size(); ++i)
            if (clips[i].name == clip && clips[i].idle) {
                asset = &clips[i];
                m_character = character;
                m_clip = int(i);
            }
    }
    setVisible(asset != nullptr);
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
    if (!m_document)
        return;
    // Named as the scenario names its files: relative to its folder.
    const std::string database = QDir::fromNativeSeparators(QDir(m_document->baseDir()).relativeFilePath(path)).toStdString();
    editClip(tr("Change Idle Database"), [&](core::scenario::IdleSynthesizer& idle) { idle.database = database; });
}

template <typename Change> void IdleProperties::editClip(const QString& text, Change change)
{
    if (m_refreshing || !m_document || m_clip < 0)
        return;
    core::scenario::ClipAsset clip = m_document->scenario().characters[std::size_t(m_character)].clips[std::size_t(m_clip)];
    change(*clip.idle);
    const auto done = m_document->edit(core::edit::replaceClip(m_document->scenario(), {m_character, m_clip}, std::move(clip)), text);
    if (!done)
        emit problem(tr("%1: %2").arg(text, fromUtf8(done.error().message)));
}

} // namespace thespis::editor
