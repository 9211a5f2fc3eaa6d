#include "editor/face_mapping_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleValidator>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <set>

#include "editor/error_dialog.h"
#include "editor/qt_conversions.h"
#include "scene/fap.h"
#include "scene/face_naming.h"

namespace thespis::editor {

namespace scene = core::scene;

namespace {

enum DriveColumn { DriveTarget, DriveChannel, DriveCoefficient, DriveSide, DriveColumns };
enum JointColumn { JointName, JointChannel, JointAxis, JointRadians, JointColumns };

QString number(double value)
{
    return QString::number(value, 'g', 10);
}

double numberIn(const QTableWidget* table, int row, int column)
{
    const auto* edit = qobject_cast<QLineEdit*>(table->cellWidget(row, column));
    return edit ? edit->text().toDouble() : 0.0;
}

QLineEdit* numberEdit(double value, QWidget* parent)
{
    auto* edit = new QLineEdit(number(value), parent);
    auto* validator = new QDoubleValidator(edit);
    validator->setLocale(QLocale::c());
    edit->setValidator(validator);
    return edit;
}

// An editable list of names with `current` chosen (added when the model lacks it, so that the
// row still says what the table names).
QComboBox* nameChoice(const std::vector<std::string>& names, const std::string& current, QWidget* parent)
{
    auto* combo = new QComboBox(parent);
    combo->setEditable(true);
    combo->setInsertPolicy(QComboBox::NoInsert);
    for (const std::string& name : names)
        combo->addItem(fromUtf8(name));
    combo->setCurrentText(fromUtf8(current));
    return combo;
}

QComboBox* channelChoice(int channel, QWidget* parent)
{
    auto* combo = new QComboBox(parent);
    for (int c = 0; c < scene::kFaceChannelCount; ++c)
        combo->addItem(fromUtf8(scene::faceChannelName(c)), c);
    combo->setCurrentIndex(std::clamp(channel, 0, scene::kFaceChannelCount - 1));
    return combo;
}

QString comboText(const QTableWidget* table, int row, int column)
{
    const auto* combo = qobject_cast<QComboBox*>(table->cellWidget(row, column));
    return combo ? combo->currentText().trimmed() : QString();
}

int comboData(const QTableWidget* table, int row, int column)
{
    const auto* combo = qobject_cast<QComboBox*>(table->cellWidget(row, column));
    return combo ? combo->currentData().toInt() : 0;
}

QTableWidget* makeTable(const QStringList& headers, QWidget* parent)
{
    auto* table = new QTableWidget(0, int(headers.size()), parent);
    table->setHorizontalHeaderLabels(headers);
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table->verticalHeader()->setVisible(false);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    return table;
}

} // namespace

QString chooseFaceMappingFile(QWidget* parent, const QString& title, const QString& start, bool save)
{
    // A dialog object rather than the static helper, so that tests can answer it.
    QFileDialog dialog(parent, title, start, FaceMappingDialog::tr("Face mapping tables (*.json);;All files (*)"));
    dialog.setObjectName(QStringLiteral("faceMappingFileDialog"));
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setAcceptMode(save ? QFileDialog::AcceptSave : QFileDialog::AcceptOpen);
    dialog.setFileMode(save ? QFileDialog::AnyFile : QFileDialog::ExistingFile);
    dialog.setDefaultSuffix(QStringLiteral("json"));
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return {};
    return dialog.selectedFiles().front();
}

FaceMappingDialog::FaceMappingDialog(const scene::Character& model, const scene::FaceMapping& mapping,
                                     const QString& folder, QWidget* parent)
    : QDialog(parent), m_model(model), m_folder(folder)
{
    setObjectName(QStringLiteral("faceMappingDialog"));
    setWindowTitle(tr("Face Mapping of %1").arg(fromUtf8(model.name)));
    auto* intro = new QLabel(tr("Each row drives one of the model's morph targets by a face channel: the target's "
                                "weight is the channel's value times the coefficient (of its positive or negative "
                                "part only, when one side is chosen)."),
                             this);
    intro->setWordWrap(true);
    m_drives = makeTable({tr("Morph target"), tr("Channel"), tr("Coefficient"), tr("Side")}, this);
    m_drives->setObjectName(QStringLiteral("faceDrives"));
    m_joints = makeTable({tr("Joint"), tr("Channel"), tr("Axis (x, y, z)"), tr("Radians per unit")}, this);
    m_joints->setObjectName(QStringLiteral("faceJoints"));
    m_missing = new QLabel(this);
    m_missing->setObjectName(QStringLiteral("faceMissing"));
    m_missing->setWordWrap(true);

    auto* addDrive = new QPushButton(tr("Add Drive"), this);
    auto* removeDrive = new QPushButton(tr("Remove Drive"), this);
    auto* addJoint = new QPushButton(tr("Add Joint Drive"), this);
    auto* removeJoint = new QPushButton(tr("Remove Joint Drive"), this);
    auto* load = new QPushButton(tr("Load…"), this);
    auto* saveAs = new QPushButton(tr("Save As…"), this);
    m_recognise = new QPushButton(tr("Recognise from Model"), this);
    m_recognise->setToolTip(tr("The table the model's names give: ARKit blendshapes, Oculus visemes, expression "
                               "targets, eye and jaw bones"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);

    auto* driveButtons = new QHBoxLayout;
    driveButtons->addWidget(addDrive);
    driveButtons->addWidget(removeDrive);
    driveButtons->addStretch(1);
    auto* jointButtons = new QHBoxLayout;
    jointButtons->addWidget(addJoint);
    jointButtons->addWidget(removeJoint);
    jointButtons->addStretch(1);
    auto* fileButtons = new QHBoxLayout;
    fileButtons->addWidget(load);
    fileButtons->addWidget(saveAs);
    fileButtons->addWidget(m_recognise);
    fileButtons->addStretch(1);
    fileButtons->addWidget(buttons);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addWidget(new QLabel(tr("Morph targets:"), this));
    layout->addWidget(m_drives, 3);
    layout->addLayout(driveButtons);
    layout->addWidget(new QLabel(tr("Joints:"), this));
    layout->addWidget(m_joints, 2);
    layout->addLayout(jointButtons);
    layout->addWidget(m_missing);
    layout->addLayout(fileButtons);

    connect(addDrive, &QPushButton::clicked, this, [this] {
        const std::vector<std::string> targets = scene::morphTargetNames(m_model);
        addDriveRow({targets.empty() ? std::string() : targets.front(), scene::expressionChannel(1), 1.0,
                     scene::MorphDrive::Side::Both});
        updateMissing();
    });
    connect(addJoint, &QPushButton::clicked, this, [this] {
        addJointRow({m_model.skeleton.jointCount() > 0 ? m_model.skeleton.joints().front().name : std::string(),
                     scene::fapChannel(23), {0, 1, 0}, 1e-5});
        updateMissing();
    });
    for (auto [button, table] : {std::pair{removeDrive, m_drives}, std::pair{removeJoint, m_joints}})
        connect(button, &QPushButton::clicked, this, [this, table = table] {
            if (table->currentRow() >= 0)
                table->removeRow(table->currentRow());
            updateMissing();
        });
    connect(load, &QPushButton::clicked, this, [this] {
        if (const QString path = chooseFaceMappingFile(this, tr("Load a Face Mapping Table"), m_folder, false); !path.isEmpty())
            loadFile(path);
    });
    connect(saveAs, &QPushButton::clicked, this, [this] {
        if (const QString path = chooseFaceMappingFile(this, tr("Save the Face Mapping Table"), m_folder, true); !path.isEmpty())
            saveFile(path);
    });
    connect(m_recognise, &QPushButton::clicked, this, [this] { setMapping(scene::recogniseFaceMapping(m_model)); });
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    setMapping(mapping);
    resize(760, 560);
}

void FaceMappingDialog::addDriveRow(const scene::FaceMappingDrive& drive)
{
    const int row = m_drives->rowCount();
    m_drives->insertRow(row);
    auto* target = nameChoice(scene::morphTargetNames(m_model), drive.target, m_drives);
    connect(target, &QComboBox::currentTextChanged, this, &FaceMappingDialog::updateMissing);
    m_drives->setCellWidget(row, DriveTarget, target);
    m_drives->setCellWidget(row, DriveChannel, channelChoice(drive.channel, m_drives));
    m_drives->setCellWidget(row, DriveCoefficient, numberEdit(drive.coefficient, m_drives));
    auto* side = new QComboBox(m_drives);
    side->addItem(tr("Both"), int(scene::MorphDrive::Side::Both));
    side->addItem(tr("Positive values only"), int(scene::MorphDrive::Side::Positive));
    side->addItem(tr("Negative values only"), int(scene::MorphDrive::Side::Negative));
    side->setCurrentIndex(side->findData(int(drive.side)));
    m_drives->setCellWidget(row, DriveSide, side);
}

void FaceMappingDialog::addJointRow(const scene::FaceMappingJoint& joint)
{
    const int row = m_joints->rowCount();
    m_joints->insertRow(row);
    std::vector<std::string> names;
    for (const core::anim::Joint& j : m_model.skeleton.joints())
        names.push_back(j.name);
    auto* name = nameChoice(names, joint.joint, m_joints);
    connect(name, &QComboBox::currentTextChanged, this, &FaceMappingDialog::updateMissing);
    m_joints->setCellWidget(row, JointName, name);
    m_joints->setCellWidget(row, JointChannel, channelChoice(joint.channel, m_joints));
    m_joints->setCellWidget(row, JointAxis, new QLineEdit(QStringLiteral("%1, %2, %3")
                                                              .arg(number(joint.axis.x), number(joint.axis.y),
                                                                   number(joint.axis.z)),
                                                          m_joints));
    m_joints->setCellWidget(row, JointRadians, numberEdit(joint.radiansPerUnit, m_joints));
}

scene::FaceMapping FaceMappingDialog::mapping() const
{
    scene::FaceMapping mapping;
    mapping.name = m_name;
    for (int row = 0; row < m_drives->rowCount(); ++row)
        mapping.drives.push_back({comboText(m_drives, row, DriveTarget).toStdString(),
                                  comboData(m_drives, row, DriveChannel), numberIn(m_drives, row, DriveCoefficient),
                                  scene::MorphDrive::Side(comboData(m_drives, row, DriveSide))});
    for (int row = 0; row < m_joints->rowCount(); ++row) {
        const auto* axisEdit = qobject_cast<QLineEdit*>(m_joints->cellWidget(row, JointAxis));
        const QStringList axis = axisEdit ? axisEdit->text().split(u',') : QStringList();
        const auto component = [&](int i) { return i < axis.size() ? axis[i].trimmed().toDouble() : 0.0; };
        core::anim::Vec3d direction{component(0), component(1), component(2)};
        const double length = std::sqrt(core::anim::dot(direction, direction));
        if (length > 0)
            direction = direction * (1.0 / length);
        else
            direction = {0, 1, 0}; // an axis must have a length: a table file refuses a zero one
        mapping.joints.push_back({comboText(m_joints, row, JointName).toStdString(), comboData(m_joints, row, JointChannel),
                                  direction, numberIn(m_joints, row, JointRadians)});
    }
    return mapping;
}

void FaceMappingDialog::setMapping(const scene::FaceMapping& mapping)
{
    m_name = mapping.name;
    m_drives->setRowCount(0);
    m_joints->setRowCount(0);
    for (const scene::FaceMappingDrive& drive : mapping.drives)
        addDriveRow(drive);
    for (const scene::FaceMappingJoint& joint : mapping.joints)
        addJointRow(joint);
    updateMissing();
}

void FaceMappingDialog::updateMissing()
{
    const std::vector<std::string> targets = scene::morphTargetNames(m_model);
    std::set<QString> lackedTargets, lackedJoints;
    for (int row = 0; row < m_drives->rowCount(); ++row) {
        const QString name = comboText(m_drives, row, DriveTarget);
        if (std::find(targets.begin(), targets.end(), name.toStdString()) == targets.end())
            lackedTargets.insert(name);
    }
    for (int row = 0; row < m_joints->rowCount(); ++row) {
        const std::string name = comboText(m_joints, row, JointName).toStdString();
        const auto& joints = m_model.skeleton.joints();
        if (std::none_of(joints.begin(), joints.end(),
                         [&](const core::anim::Joint& j) { return j.name == name || j.sourceName == name; }))
            lackedJoints.insert(fromUtf8(name));
    }
    const auto listed = [](const std::set<QString>& names) {
        QStringList quoted;
        for (const QString& name : names)
            quoted << QStringLiteral("“%1”").arg(name);
        return quoted.join(QStringLiteral(", "));
    };
    QStringList lines;
    if (!lackedTargets.empty())
        lines << tr("%1 has no morph target %2: those rows move nothing.").arg(fromUtf8(m_model.name), listed(lackedTargets));
    if (!lackedJoints.empty())
        lines << tr("%1 has no joint %2: those rows turn nothing.").arg(fromUtf8(m_model.name), listed(lackedJoints));
    if (lines.isEmpty())
        lines << tr("Every morph target and joint the table names is in %1.").arg(fromUtf8(m_model.name));
    m_missing->setText(lines.join(u'\n'));
    m_missing->setStyleSheet(lackedTargets.empty() && lackedJoints.empty() ? QString()
                                                                            : QStringLiteral("color: #b03000;"));
}

bool FaceMappingDialog::loadFile(const QString& path)
{
    auto mapping = scene::loadFaceMapping(toFsPath(path));
    if (!mapping) {
        showError(this, mapping.error(), tr("Could not load the face mapping table."));
        return false;
    }
    setMapping(*mapping);
    return true;
}

bool FaceMappingDialog::saveFile(const QString& path)
{
    if (auto saved = scene::saveFaceMapping(toFsPath(path), mapping()); !saved) {
        showError(this, saved.error(), tr("Could not save the face mapping table."));
        return false;
    }
    return true;
}

} // namespace thespis::editor
