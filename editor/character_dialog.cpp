#include "editor/character_dialog.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

#include "anim/hanim.h"
#include "edit/content_edits.h"
#include "editor/qt_conversions.h"
#include "scenario/clip_import.h"

namespace thespis::editor {

CharacterDialog::CharacterDialog(const QString& baseDir, const QString& suggestedName, QWidget* parent)
    : QDialog(parent), m_baseDir(baseDir)
{
    setObjectName(QStringLiteral("characterDialog"));
    setWindowTitle(tr("Add Character"));
    m_name = new QLineEdit(suggestedName, this);
    m_name->setObjectName(QStringLiteral("characterName"));
    m_humanoid = new QRadioButton(tr("The built-in humanoid"), this);
    m_humanoid->setObjectName(QStringLiteral("humanoidChoice"));
    m_level = new QComboBox(this);
    m_level->setObjectName(QStringLiteral("levelChoice"));
    m_level->addItem(tr("H-Anim LOA 1 (18 joints)"), QStringLiteral("hanim-loa1"));
    m_level->addItem(tr("H-Anim, the paper's 25 joints (spine, neck, clavicles)"), QStringLiteral("hanim-25"));
    m_level->addItem(tr("H-Anim LOA 2 (71 joints, with fingers)"), QStringLiteral("hanim-loa2"));
    m_level->setCurrentIndex(1);
    m_modelChoice = new QRadioButton(tr("A glTF model"), this);
    m_modelChoice->setObjectName(QStringLiteral("modelChoice"));
    m_modelLabel = new QLabel(tr("No model chosen."), this);
    m_modelLabel->setObjectName(QStringLiteral("modelLabel"));
    m_modelLabel->setWordWrap(true);
    m_browse = new QPushButton(tr("Browse…"), this);
    m_importClips = new QCheckBox(this);
    m_importClips->setObjectName(QStringLiteral("importModelClips"));
    auto* group = new QButtonGroup(this);
    group->addButton(m_humanoid);
    group->addButton(m_modelChoice);
    m_humanoid->setChecked(true);

    auto* modelRow = new QHBoxLayout;
    modelRow->addWidget(m_modelLabel, 1);
    modelRow->addWidget(m_browse);
    auto* form = new QFormLayout;
    form->addRow(tr("Name:"), m_name);
    form->addRow(m_humanoid, m_level);
    form->addRow(m_modelChoice, modelRow);
    form->addRow(QString(), m_importClips);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_ok = buttons->addButton(tr("Add Character"), QDialogButtonBox::AcceptRole);
    m_ok->setObjectName(QStringLiteral("addCharacterButton"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);

    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_humanoid, &QRadioButton::toggled, this, &CharacterDialog::updateState);
    connect(m_name, &QLineEdit::textChanged, this, &CharacterDialog::updateState);
    connect(m_browse, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose a glTF Model"), m_baseDir,
                                                          tr("glTF models (*.gltf *.glb)"));
        if (!path.isEmpty())
            setModelFile(path);
    });
    updateState();
}

void CharacterDialog::setModelFile(const QString& path)
{
    m_modelPath = QFileInfo(path).absoluteFilePath();
    m_modelClips.clear();
    m_modelChoice->setChecked(true);
    // Its own animations, as an import into a character on its rig would take them.
    auto rig = core::scenario::readModelRig(toFsPath(m_modelPath));
    if (!rig) {
        m_modelLabel->setText(tr("%1 cannot be used: %2").arg(QFileInfo(path).fileName(), fromUtf8(rig.error().message)));
        m_modelPath.clear();
    } else {
        m_modelLabel->setText(QDir::toNativeSeparators(m_modelPath));
        if (auto plan = core::scenario::planClipImport(toFsPath(m_modelPath), toFsPath(m_baseDir), rig->skeleton); plan)
            m_modelClips = plan->clips;
    }
    m_importClips->setChecked(!m_modelClips.empty());
    if (m_name->text().isEmpty() || m_name->text() == tr("Actor"))
        m_name->setText(QFileInfo(path).completeBaseName());
    updateState();
}

void CharacterDialog::updateState()
{
    const bool model = m_modelChoice->isChecked();
    m_level->setEnabled(!model);
    m_importClips->setVisible(model && !m_modelClips.empty());
    m_importClips->setText(tr("Import its %n animation(s) as clips", nullptr, int(m_modelClips.size())));
    m_ok->setEnabled(!m_name->text().trimmed().isEmpty() && (!model || !m_modelPath.isEmpty()));
}

core::scenario::Character CharacterDialog::character() const
{
    const std::string name = m_name->text().trimmed().toStdString();
    if (m_modelChoice->isChecked() && !m_modelPath.isEmpty()) {
        const QString relative = QDir(m_baseDir).relativeFilePath(m_modelPath);
        return core::edit::newCharacter(name, QDir::fromNativeSeparators(relative).toStdString(), "model");
    }
    return core::edit::newCharacter(name, "", m_level->currentData().toString().toStdString());
}

std::vector<core::scenario::ClipAsset> CharacterDialog::clips() const
{
    if (!m_modelChoice->isChecked() || m_importClips->isHidden() || !m_importClips->isChecked())
        return {};
    return m_modelClips;
}

} // namespace thespis::editor
