#include "editor/character_properties.h"

#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include "edit/content_edits.h"
#include "editor/document.h"
#include "editor/face_mapping_dialog.h"
#include "editor/qt_conversions.h"
#include "scenario/scenario_character.h"
#include "scene/face_naming.h"
#include "scene/gltf_character.h"

namespace thespis::editor {

CharacterProperties::CharacterProperties(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("characterProperties"));
    m_name = new QLineEdit(this);
    m_name->setObjectName(QStringLiteral("characterNameEdit"));
    m_body = new QLabel(this);
    m_body->setObjectName(QStringLiteral("characterBody"));
    m_body->setWordWrap(true);
    m_chooseModel = new QPushButton(tr("Choose Model…"), this);
    m_humanoid = new QPushButton(tr("Built-in Humanoid"), this);
    m_humanoid->setObjectName(QStringLiteral("useHumanoid"));
    m_skeleton = new QComboBox(this);
    m_skeleton->setObjectName(QStringLiteral("characterSkeleton"));
    const char* axes[] = {"x", "y", "z"};
    auto* position = new QHBoxLayout;
    for (int axis = 0; axis < 3; ++axis) {
        m_position[axis] = new QDoubleSpinBox(this);
        m_position[axis]->setObjectName(QStringLiteral("characterPosition_") + QLatin1String(axes[axis]));
        m_position[axis]->setRange(-1000.0, 1000.0);
        m_position[axis]->setDecimals(2);
        m_position[axis]->setSingleStep(0.1);
        m_position[axis]->setSuffix(tr(" m"));
        m_position[axis]->setPrefix(QLatin1String(axes[axis]) + QStringLiteral(" "));
        m_position[axis]->setKeyboardTracking(false);
        position->addWidget(m_position[axis]);
    }
    m_heading = new QDoubleSpinBox(this);
    m_heading->setObjectName(QStringLiteral("characterHeading"));
    m_heading->setRange(-360.0, 360.0);
    m_heading->setDecimals(1);
    m_heading->setSingleStep(5.0);
    m_heading->setSuffix(QStringLiteral("°"));
    m_heading->setKeyboardTracking(false);
    m_heading->setToolTip(tr("Which way the character faces: 0° looks along +Z, 90° along +X"));
    m_contents = new QLabel(this);
    m_contents->setWordWrap(true);
    m_faceMapping = new QLabel(this);
    m_faceMapping->setObjectName(QStringLiteral("characterFaceMapping"));
    m_faceMapping->setWordWrap(true);
    m_chooseFaceMapping = new QPushButton(tr("Choose…"), this);
    m_chooseFaceMapping->setObjectName(QStringLiteral("chooseFaceMapping"));
    m_chooseFaceMapping->setToolTip(tr("Use a face mapping table file (thespis-cli face-mapping --save-mapping writes one)"));
    m_automaticFace = new QPushButton(tr("Automatic"), this);
    m_automaticFace->setObjectName(QStringLiteral("automaticFaceMapping"));
    m_automaticFace->setToolTip(tr("Drive the face by the table recognised from the model's names"));
    m_editFaceMapping = new QPushButton(tr("Edit…"), this);
    m_editFaceMapping->setObjectName(QStringLiteral("editFaceMapping"));

    auto* bodyButtons = new QHBoxLayout;
    bodyButtons->addWidget(m_chooseModel);
    bodyButtons->addWidget(m_humanoid);
    bodyButtons->addStretch(1);
    m_faceButtons = new QWidget(this);
    auto* faceButtons = new QHBoxLayout(m_faceButtons);
    faceButtons->setContentsMargins(0, 0, 0, 0);
    faceButtons->addWidget(m_chooseFaceMapping);
    faceButtons->addWidget(m_automaticFace);
    faceButtons->addWidget(m_editFaceMapping);
    faceButtons->addStretch(1);
    auto* form = new QFormLayout(this);
    m_form = form;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->addRow(tr("Character:"), m_name);
    form->addRow(tr("Body:"), m_body);
    form->addRow(QString(), bodyButtons);
    form->addRow(tr("Face mapping:"), m_faceMapping);
    form->addRow(QString(), m_faceButtons);
    form->addRow(tr("Motion plays on:"), m_skeleton);
    form->addRow(tr("Stands at:"), position);
    form->addRow(tr("Faces:"), m_heading);
    form->addRow(tr("Has:"), m_contents);

    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        if (m_document && m_character >= 0)
            push(tr("Rename Character"),
                 core::edit::renameCharacter(m_document->scenario(), m_character, m_name->text().trimmed().toStdString()));
    });
    connect(m_skeleton, &QComboBox::activated, this, [this] {
        if (!m_document || m_character < 0)
            return;
        const auto& c = m_document->scenario().characters[std::size_t(m_character)];
        push(tr("Change Skeleton"), core::edit::setCharacterBody(m_document->scenario(), m_character, c.model,
                                                                 m_skeleton->currentData().toString().toStdString()));
    });
    connect(m_humanoid, &QPushButton::clicked, this, [this] {
        if (!m_document || m_character < 0)
            return;
        const auto& c = m_document->scenario().characters[std::size_t(m_character)];
        const std::string skeleton = c.skeleton == "model" ? "hanim-25" : c.skeleton;
        push(tr("Use the Built-in Humanoid"), core::edit::setCharacterBody(m_document->scenario(), m_character, "", skeleton));
    });
    connect(m_chooseModel, &QPushButton::clicked, this, [this] {
        if (!m_document)
            return;
        const QString path = QFileDialog::getOpenFileName(this, tr("Choose a glTF Model"), m_document->baseDir(),
                                                          tr("glTF models (*.gltf *.glb)"));
        if (!path.isEmpty())
            setModel(path);
    });
    connect(m_chooseFaceMapping, &QPushButton::clicked, this, [this] {
        if (!m_document)
            return;
        const QString path = chooseFaceMappingFile(this, tr("Choose a Face Mapping Table"), m_document->baseDir(), false);
        if (!path.isEmpty())
            setFaceMappingFile(path);
    });
    connect(m_automaticFace, &QPushButton::clicked, this, [this] { setFaceMappingFile(QString()); });
    connect(m_editFaceMapping, &QPushButton::clicked, this, &CharacterProperties::editFaceMapping);
    for (QDoubleSpinBox* box : {m_position[0], m_position[1], m_position[2], m_heading})
        connect(box, &QDoubleSpinBox::valueChanged, this, &CharacterProperties::onPlacementEdited);
}

void CharacterProperties::show(Document* document, int character)
{
    m_document = document;
    m_character = character;
    refresh();
}

void CharacterProperties::setModel(const QString& path)
{
    if (!m_document || m_character < 0)
        return;
    const QString relative = QDir::fromNativeSeparators(QDir(m_document->baseDir()).relativeFilePath(path));
    push(tr("Change Model"), core::edit::setCharacterBody(m_document->scenario(), m_character, relative.toStdString(), "model"));
}

void CharacterProperties::setFaceMappingFile(const QString& path)
{
    setFaceMapping(path, path.isEmpty() ? tr("Use the Recognised Face Mapping") : tr("Choose Face Mapping"));
}

void CharacterProperties::setFaceMapping(const QString& path, const QString& text)
{
    if (!m_document || m_character < 0)
        return;
    const QString relative =
        path.isEmpty() ? QString() : QDir::fromNativeSeparators(QDir(m_document->baseDir()).relativeFilePath(path));
    push(text, core::edit::setCharacterFaceMapping(m_document->scenario(), m_character, relative.toStdString()));
}

void CharacterProperties::editFaceMapping()
{
    if (!m_document || m_character < 0)
        return;
    const auto& c = m_document->scenario().characters[std::size_t(m_character)];
    if (c.model.empty())
        return;
    const core::scenario::Assets& assets = m_document->assets();
    // The model's own names (its targets and joints) and its recognised table, without textures.
    auto model = core::scene::loadGltfCharacter(assets.path(c.model), {.loadTextures = false});
    if (!model) {
        emit problem(tr("Edit Face Mapping: %1").arg(fromUtf8(model.error().message)));
        return;
    }
    model->name = c.name;
    core::scene::FaceMapping table = core::scene::recogniseFaceMapping(*model);
    if (!c.faceMapping.empty()) {
        auto own = core::scenario::readCharacterFaceMapping(m_document->scenario(), std::size_t(m_character), assets);
        if (own && *own)
            table = std::move(**own);
        else if (!own) // edited from the recognised table, as the character plays now
            emit problem(tr("Edit Face Mapping: %1").arg(fromUtf8(own.error().message)));
    }
    FaceMappingDialog dialog(*model, table, m_document->baseDir(), this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString file = c.faceMapping.empty() ? QString() : fromFsPath(assets.path(c.faceMapping));
    if (file.isEmpty()) {
        const QString suggested = QDir(m_document->baseDir())
                                      .filePath(QFileInfo(fromUtf8(c.model)).completeBaseName() + QStringLiteral("_face.json"));
        file = chooseFaceMappingFile(this, tr("Save the Face Mapping Table"), suggested, true);
        if (file.isEmpty())
            return;
    }
    if (!dialog.saveFile(file))
        return;
    if (!c.faceMapping.empty() && file == fromFsPath(assets.path(c.faceMapping)))
        m_document->fileRewritten(); // the same file, new contents: the views load it again
    else
        setFaceMapping(file, tr("Edit Face Mapping"));
}

void CharacterProperties::push(const QString& text, const auto& made)
{
    if (m_refreshing || !m_document)
        return;
    if (auto done = m_document->edit(made, text); !done) {
        emit problem(tr("%1: %2").arg(text, fromUtf8(done.error().message)));
        refresh();
    }
}

void CharacterProperties::onPlacementEdited()
{
    if (m_refreshing || !m_document || m_character < 0)
        return;
    const core::anim::Vec3 position{float(m_position[0]->value()), float(m_position[1]->value()),
                                    float(m_position[2]->value())};
    push(tr("Move Character"),
         core::edit::setCharacterPlacement(m_document->scenario(), m_character, position, m_heading->value()));
}

void CharacterProperties::refresh()
{
    if (!m_document || m_character < 0 || std::size_t(m_character) >= m_document->scenario().characters.size())
        return;
    m_refreshing = true;
    const auto& c = m_document->scenario().characters[std::size_t(m_character)];
    m_name->setText(fromUtf8(c.name));
    m_body->setText(c.model.empty() ? tr("The built-in humanoid") : QDir::toNativeSeparators(fromUtf8(c.model)));
    m_humanoid->setEnabled(!c.model.empty());
    // The built-in humanoid has its own face: only a glTF model follows a table.
    m_form->setRowVisible(m_faceMapping, !c.model.empty());
    m_form->setRowVisible(m_faceButtons, !c.model.empty());
    m_faceMapping->setText(c.faceMapping.empty() ? tr("Recognised from the model's names")
                                                 : QDir::toNativeSeparators(fromUtf8(c.faceMapping)));
    m_automaticFace->setEnabled(!c.faceMapping.empty());
    m_skeleton->clear();
    m_skeleton->addItem(tr("H-Anim LOA 1 (18 joints)"), QStringLiteral("hanim-loa1"));
    m_skeleton->addItem(tr("H-Anim, the paper's 25 joints"), QStringLiteral("hanim-25"));
    m_skeleton->addItem(tr("H-Anim LOA 2 (71 joints)"), QStringLiteral("hanim-loa2"));
    if (!c.model.empty())
        m_skeleton->addItem(tr("The model's own rig"), QStringLiteral("model"));
    if (c.skeleton.starts_with("clip:"))
        m_skeleton->addItem(tr("The skeleton of clip %1").arg(fromUtf8(c.skeleton.substr(5))), fromUtf8(c.skeleton));
    m_skeleton->setCurrentIndex(std::max(0, m_skeleton->findData(fromUtf8(c.skeleton))));
    m_position[0]->setValue(c.position.x);
    m_position[1]->setValue(c.position.y);
    m_position[2]->setValue(c.position.z);
    m_heading->setValue(c.heading);
    int actions = 0;
    for (const auto& layer : c.layers)
        actions += int(layer.actions.size());
    m_contents->setText(tr("%1, %2, %3")
                            .arg(tr("%n layer(s)", nullptr, int(c.layers.size())), tr("%n clip(s)", nullptr, int(c.clips.size())),
                                 tr("%n action(s)", nullptr, actions)));
    m_refreshing = false;
}

} // namespace thespis::editor
