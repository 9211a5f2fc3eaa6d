#include "editor/joint_mask_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QMenu>
#include <QToolButton>
#include <QVBoxLayout>

#include "anim/hanim.h"
#include "edit/document_edits.h"
#include "editor/commands/command_ids.h"
#include "editor/document.h"
#include "scene/face_mask.h"
#include "widgets/joint_mask_view.h"

namespace thespis::editor {

using core::anim::JointMask;
using core::anim::MaskPreset;
using core::scene::FaceMaskPreset;

namespace {

QToolButton* toolButton(const QString& text, const QString& tip, const QString& objectName, QWidget* parent)
{
    auto* button = new QToolButton(parent);
    button->setText(text);
    button->setToolTip(tip);
    button->setObjectName(objectName);
    button->setAutoRaise(true);
    return button;
}

} // namespace

JointMaskPanel::JointMaskPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("jointMaskPanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_masks = new QComboBox(this);
    m_masks->setObjectName(QStringLiteral("maskCombo"));
    m_masks->setToolTip(tr("The mask to edit; actions that name it all change with it"));
    m_masks->setMinimumContentsLength(12);
    m_add = toolButton(tr("New"), tr("Add a mask of the body's joints or of the face's regions"), QStringLiteral("newMask"), this);
    m_add->setPopupMode(QToolButton::InstantPopup);
    auto* newMenu = new QMenu(m_add);
    newMenu->addAction(tr("Body Mask…"), this, [this] { onNewMask(false); })->setObjectName(QStringLiteral("newBodyMask"));
    newMenu->addAction(tr("Face Mask…"), this, [this] { onNewMask(true); })->setObjectName(QStringLiteral("newFaceMask"));
    m_add->setMenu(newMenu);
    m_rename = toolButton(tr("Rename…"), tr("Rename the mask and every action and gesture using it"), QStringLiteral("renameMask"), this);
    m_remove = toolButton(tr("Delete"), tr("Delete the mask (only when nothing uses it)"), QStringLiteral("deleteMask"), this);
    m_presets = toolButton(tr("Presets"), tr("Replace the weights by a preset"), QStringLiteral("maskPresets"), this);
    m_presets->setPopupMode(QToolButton::InstantPopup);
    auto* presets = new QMenu(m_presets);
    const std::pair<QString, MaskPreset> items[] = {
        {tr("Full Body"), MaskPreset::FullBody},     {tr("Upper Body"), MaskPreset::UpperBody},
        {tr("Lower Body"), MaskPreset::LowerBody},   {tr("Left Arm"), MaskPreset::LeftArm},
        {tr("Right Arm"), MaskPreset::RightArm},     {tr("Head and Neck"), MaskPreset::HeadAndNeck},
        {tr("Spine"), MaskPreset::Spine},
    };
    const auto applyPreset = [this](const QString& text, JointMask mask) {
        if (m_document && maskIndex() >= 0)
            report(m_document->edit(core::edit::setMask(m_document->scenario(), maskIndex(), std::move(mask)),
                                    tr("Apply Mask Preset %1").arg(text)));
    };
    presets->addSection(tr("Body"));
    for (const auto& [text, preset] : items)
        presets->addAction(text, this, [applyPreset, text = text, preset = preset] { applyPreset(text, JointMask::preset(preset)); });
    // The face's regions (paper §5.2: speech high on the mouth, expressions on the eyes and brows).
    const std::pair<QString, FaceMaskPreset> faceItems[] = {
        {tr("Whole Face"), FaceMaskPreset::WholeFace},
        {tr("Speech (mouth, tongue)"), FaceMaskPreset::Speech},
        {tr("Expression (eyes, brows, cheeks)"), FaceMaskPreset::Expression},
        {tr("Eyes"), FaceMaskPreset::Eyes},
    };
    presets->addSection(tr("Face"));
    for (const auto& [text, preset] : faceItems)
        presets->addAction(text, this, [applyPreset, text = text, preset = preset] {
            applyPreset(text, core::scene::faceMaskPreset(preset));
        });
    m_presets->setMenu(presets);
    m_mirror = toolButton(tr("Mirror"), tr("Swap left and right"), QStringLiteral("mirrorMask"), this);
    m_invert = toolButton(tr("Invert"), tr("Every weight w becomes 1 − w"), QStringLiteral("invertMask"), this);
    bar->addWidget(m_masks, 1);
    for (QToolButton* button : {m_add, m_rename, m_remove, m_presets, m_mirror, m_invert})
        bar->addWidget(button);
    layout->addLayout(bar);
    m_view = new widgets::JointMaskView(this);
    m_view->setObjectName(QStringLiteral("jointMaskView"));
    layout->addWidget(m_view, 1);

    connect(m_masks, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
    connect(m_rename, &QToolButton::clicked, this, &JointMaskPanel::onRenameMask);
    connect(m_remove, &QToolButton::clicked, this, &JointMaskPanel::onDeleteMask);
    connect(m_mirror, &QToolButton::clicked, this, [this] {
        if (!m_document || maskIndex() < 0)
            return;
        const JointMask& mask = m_document->scenario().masks[std::size_t(maskIndex())].mask;
        report(m_document->edit(core::edit::setMask(m_document->scenario(), maskIndex(),
                                                    m_face ? core::scene::mirroredFaceMask(mask) : mask.mirrored()),
                                tr("Mirror Mask")));
    });
    connect(m_invert, &QToolButton::clicked, this, [this] {
        if (m_document && maskIndex() >= 0)
            report(m_document->edit(core::edit::setMask(m_document->scenario(), maskIndex(),
                                                        m_document->scenario().masks[std::size_t(maskIndex())].mask.inverted()),
                                    tr("Invert Mask")));
    });
    connect(m_view, &widgets::JointMaskView::weightsPaintRequested, this,
            [this](const QVector<int>& joints, float weight, bool finished) {
                if (!m_document || maskIndex() < 0)
                    return;
                std::vector<std::string> names;
                for (int joint : joints)
                    if (joint >= 0 && std::size_t(joint) < m_keys.size())
                        names.push_back(m_keys[std::size_t(joint)]);
                report(m_document->edit(core::edit::setMaskWeights(m_document->scenario(), maskIndex(), names, weight),
                                        tr("Paint Mask"), Merge{PaintMaskId, finished}));
            });
    connect(m_view, &widgets::JointMaskView::weightRequested, this, [this](int joint, float weight) {
        if (!m_document || maskIndex() < 0 || joint < 0 || std::size_t(joint) >= m_keys.size())
            return;
        const std::string& name = m_keys[std::size_t(joint)];
        report(m_document->edit(core::edit::setMaskWeights(m_document->scenario(), maskIndex(), std::span(&name, 1), weight),
                                m_face ? tr("Set Face Weight") : tr("Set Joint Weight")));
    });
    setDocument(nullptr);
}

void JointMaskPanel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    // The first character's skeleton when it is an H-Anim one, else the paper's 25 joints.
    m_skeleton = core::anim::hanim::skeleton(core::anim::hanim::Level::Subset25);
    if (m_document && !m_document->runtime().characters.empty()
        && !m_document->scenario().characters.front().skeleton.starts_with("clip:"))
        m_skeleton = m_document->runtime().characters.front().skeleton;
    if (m_document)
        connect(m_document, &Document::edited, this, [this] { refreshMaskList(); });
    refreshMaskList();
}

void JointMaskPanel::showMask(const QString& name)
{
    if (const int index = m_masks->findText(name); index >= 0)
        m_masks->setCurrentIndex(index);
}

QString JointMaskPanel::currentMask() const
{
    return m_masks->currentText();
}

int JointMaskPanel::maskIndex() const
{
    if (!m_document)
        return -1;
    const std::string name = m_masks->currentText().toStdString();
    const auto& masks = m_document->scenario().masks;
    for (std::size_t i = 0; i < masks.size(); ++i)
        if (masks[i].name == name)
            return int(i);
    return -1;
}

void JointMaskPanel::refreshMaskList()
{
    const QString current = m_masks->currentText();
    {
        const QSignalBlocker blocker(m_masks);
        m_masks->clear();
        if (m_document)
            for (const auto& mask : m_document->scenario().masks)
                m_masks->addItem(QString::fromStdString(mask.name));
        const int keep = m_masks->findText(current);
        m_masks->setCurrentIndex(keep >= 0 ? keep : (m_masks->count() > 0 ? 0 : -1));
    }
    refresh();
}

void JointMaskPanel::refresh()
{
    const int index = maskIndex();
    const bool editable = index >= 0;
    for (QToolButton* button : {m_rename, m_remove, m_presets, m_mirror, m_invert})
        button->setEnabled(editable);
    m_add->setEnabled(m_document != nullptr);
    m_view->setEnabled(editable);

    const JointMask* shown = editable ? &m_document->scenario().masks[std::size_t(index)].mask : nullptr;
    m_face = shown && core::scene::isFaceMask(*shown);
    if (m_face)
        showFace(*shown);
    else
        showBody(shown);
}

void JointMaskPanel::showBody(const JointMask* mask)
{
    m_keys.clear();
    QVector<widgets::MaskJoint> joints;
    const std::vector<core::anim::Vec3d> rest = m_skeleton.worldPositions(m_skeleton.restFrame());
    std::vector<float> weights(std::size_t(m_skeleton.jointCount()), 0.0f);
    if (mask) {
        const std::vector<float> resolved = mask->resolve(*m_skeleton.frameLayout(), m_skeleton.parents());
        for (int j = 0; j < m_skeleton.jointCount(); ++j)
            weights[std::size_t(j)] = resolved[std::size_t(j)];
    }
    for (int j = 0; j < m_skeleton.jointCount(); ++j) {
        const core::anim::Joint& joint = m_skeleton.joint(j);
        widgets::MaskJoint item;
        item.name = QString::fromStdString(joint.name);
        item.parent = joint.parent;
        // H-Anim: +X is the character's left, +Z its front; seen from the front, its left is on
        // the viewer's right.
        item.position = QPointF(rest[std::size_t(j)].x, rest[std::size_t(j)].y);
        item.weight = weights[std::size_t(j)];
        item.named = mask && mask->weight(joint.name) >= 0;
        joints.push_back(item);
        m_keys.push_back(joint.name);
    }
    m_view->setFaceOutline({});
    m_view->setJoints(std::move(joints));
}

void JointMaskPanel::showFace(const JointMask& mask)
{
    // The regions and their channels on the built-in humanoid's face, seen from the front.
    const auto& elements = core::scene::faceMaskElements();
    const std::vector<float> resolved = mask.resolve(*core::anim::FrameLayout::mpeg4Face());
    const auto layout = core::anim::FrameLayout::mpeg4Face();
    m_keys.clear();
    QVector<widgets::MaskJoint> joints;
    QRectF face;
    for (const core::scene::FaceMaskElement& element : elements) {
        widgets::MaskJoint item;
        item.name = QString::fromStdString(element.label);
        item.parent = element.parent;
        item.position = QPointF(element.position.x, element.position.y);
        item.named = mask.weight(element.key) >= 0;
        const int channel = layout->find(element.key, core::anim::ElementKind::Scalar);
        item.weight = channel >= 0 ? resolved[std::size_t(channel)] : item.named ? mask.weight(element.key) : mask.defaultWeight();
        if (element.key.starts_with("fap"))
            face |= QRectF(item.position, QSizeF(1e-6, 1e-6));
        joints.push_back(item);
        m_keys.push_back(element.key);
    }
    // The oval of the face around its feature points.
    m_view->setFaceOutline(face.adjusted(-0.25 * face.width(), -0.2 * face.height(), 0.25 * face.width(), 0.25 * face.height()));
    m_view->setJoints(std::move(joints));
}

void JointMaskPanel::report(const core::Result<void>& result)
{
    if (!result)
        emit problem(QString::fromStdString(result.error().message));
}

void JointMaskPanel::onNewMask(bool face)
{
    if (!m_document)
        return;
    bool ok = false;
    const QString name = QInputDialog::getText(this, face ? tr("New Face Mask") : tr("New Mask"), tr("Name of the new mask:"),
                                               QLineEdit::Normal, face ? tr("face mask") : tr("mask"), &ok);
    if (!ok || name.isEmpty())
        return;
    // A new face mask starts as the speech preset: a whole-face mask names no region, so it
    // would look like a body mask.
    report(m_document->edit(core::edit::addMask(m_document->scenario(), name.toStdString(),
                                                face ? core::scene::faceMaskPreset(FaceMaskPreset::Speech)
                                                     : JointMask::preset(MaskPreset::FullBody)),
                            tr("Add Mask %1").arg(name)));
    showMask(name);
}

void JointMaskPanel::onRenameMask()
{
    if (!m_document || maskIndex() < 0)
        return;
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Rename Mask"), tr("New name:"), QLineEdit::Normal,
                                               m_masks->currentText(), &ok);
    if (!ok || name.isEmpty())
        return;
    report(m_document->edit(core::edit::renameMask(m_document->scenario(), maskIndex(), name.toStdString()),
                            tr("Rename Mask")));
    showMask(name);
}

void JointMaskPanel::onDeleteMask()
{
    if (m_document && maskIndex() >= 0)
        report(m_document->edit(core::edit::removeMask(m_document->scenario(), maskIndex()),
                                tr("Delete Mask %1").arg(m_masks->currentText())));
}

} // namespace thespis::editor
