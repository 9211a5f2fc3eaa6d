#include "editor/import_motion_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStyle>
#include <QTableWidget>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "anim/bvh.h"
#include "edit/content_edits.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"

namespace thespis::editor {

namespace {

constexpr int kEntryRole = Qt::UserRole + 1; // index into m_entries
constexpr int kClipRole = Qt::UserRole + 2;  // index into the entry's clips (-1: the file row)

QString escaped(const QString& text)
{
    return text.toHtmlEscaped();
}

QString conventionName(const std::string& convention)
{
    if (convention == "cmu")
        return ImportMotionDialog::tr("CMU (MotionBuilder names)");
    if (convention == "cmu-3dsmax")
        return ImportMotionDialog::tr("CMU (3ds Max names)");
    if (convention == "user")
        return ImportMotionDialog::tr("your mapping");
    if (convention == "none")
        return ImportMotionDialog::tr("none recognised");
    if (convention == "automatic")
        return ImportMotionDialog::tr("found from the rig");
    return fromUtf8(convention);
}

} // namespace

ImportMotionDialog::ImportMotionDialog(const Document& document, QStringList files, int character, QWidget* parent)
    : QDialog(parent), m_document(document)
{
    setObjectName(QStringLiteral("importMotionDialog"));
    setWindowTitle(tr("Import Motion"));
    resize(960, 620);

    m_character = new QComboBox(this);
    m_character->setObjectName(QStringLiteral("importCharacter"));
    for (const auto& c : document.scenario().characters)
        m_character->addItem(fromUtf8(c.name));
    m_character->setCurrentIndex(std::clamp(character, 0, std::max(0, m_character->count() - 1)));

    m_files = new QTreeWidget(this);
    m_files->setObjectName(QStringLiteral("importFiles"));
    m_files->setColumnCount(2);
    m_files->setHeaderLabels({tr("File and clips"), tr("What was found")});
    m_files->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_report = new QLabel(this);
    m_report->setObjectName(QStringLiteral("importReport"));
    m_report->setWordWrap(true);
    m_report->setTextFormat(Qt::RichText);
    m_report->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_report->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_mappingTitle = new QLabel(this);
    m_mapping = new QTableWidget(0, 2, this);
    m_mapping->setObjectName(QStringLiteral("importMapping"));
    m_mapping->setHorizontalHeaderLabels({tr("Joint in the file"), tr("Plays as (H-Anim name)")});
    m_mapping->horizontalHeader()->setStretchLastSection(true);
    m_mapping->verticalHeader()->hide();
    m_mapping->verticalHeader()->setDefaultSectionSize(m_mapping->fontMetrics().height() + 6);
    m_mapping->setToolTip(tr("Type the H-Anim joint a file joint should drive (l_hip, vl5, skullbase …); leave it "
                             "empty, or the file's own name, to leave the joint out. Then Apply Mapping."));
    m_applyMapping = new QPushButton(tr("Apply Mapping"), this);
    m_applyMapping->setObjectName(QStringLiteral("applyMapping"));
    m_loadMapping = new QPushButton(tr("Load Mapping…"), this);
    m_saveMapping = new QPushButton(tr("Save Mapping…"), this);

    auto* mappingButtons = new QHBoxLayout;
    mappingButtons->addWidget(m_applyMapping);
    mappingButtons->addStretch(1);
    mappingButtons->addWidget(m_loadMapping);
    mappingButtons->addWidget(m_saveMapping);
    // The report above the mapping, scrolling when a file has much to tell (MakeHuman's 22
    // joints without H-Anim names); the user moves the boundary.
    auto* reportScroll = new QScrollArea(this);
    reportScroll->setWidget(m_report);
    reportScroll->setWidgetResizable(true);
    reportScroll->setFrameShape(QFrame::NoFrame);
    auto* mappingPart = new QWidget(this);
    auto* mappingLayout = new QVBoxLayout(mappingPart);
    mappingLayout->setContentsMargins(0, 0, 0, 0);
    mappingLayout->addWidget(m_mappingTitle);
    mappingLayout->addWidget(m_mapping, 1);
    mappingLayout->addLayout(mappingButtons);
    auto* right = new QSplitter(Qt::Vertical, this);
    right->addWidget(reportScroll);
    right->addWidget(mappingPart);
    right->setChildrenCollapsible(false);
    right->setSizes({190, 400});
    auto* splitter = new QSplitter(this);
    splitter->addWidget(m_files);
    splitter->addWidget(right);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_import = buttons->addButton(tr("Import"), QDialogButtonBox::AcceptRole);
    m_import->setObjectName(QStringLiteral("importButton"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* form = new QFormLayout;
    form->addRow(tr("Import into:"), m_character);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(splitter, 1);
    layout->addWidget(buttons);

    for (const QString& file : files)
        m_entries.push_back(Entry{file, std::nullopt, {}, {}});
    for (Entry& entry : m_entries)
        plan(entry);
    rebuild();

    connect(m_character, &QComboBox::currentIndexChanged, this, [this] {
        for (Entry& entry : m_entries)
            plan(entry);
        rebuild();
    });
    connect(m_files, &QTreeWidget::currentItemChanged, this, [this] { showSelected(); });
    connect(m_files, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item) {
        if (m_filling)
            return;
        // A file's box ticks or clears all its clips.
        if (item->data(0, kClipRole).toInt() < 0) {
            m_filling = true;
            for (int c = 0; c < item->childCount(); ++c)
                item->child(c)->setCheckState(0, item->checkState(0));
            m_filling = false;
        }
        updateImportButton();
    });
    connect(m_applyMapping, &QPushButton::clicked, this, &ImportMotionDialog::onApplyMapping);
    connect(m_loadMapping, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load Joint Mapping"), {},
                                                          tr("Joint mappings (*.map *.txt);;All files (*)"));
        if (!path.isEmpty())
            loadMapping(path);
    });
    connect(m_saveMapping, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save Joint Mapping"), {}, tr("Joint mappings (*.map)"));
        if (!path.isEmpty())
            saveMapping(path);
    });
}

int ImportMotionDialog::character() const
{
    return m_character->currentIndex();
}

void ImportMotionDialog::plan(Entry& entry)
{
    entry.plan.reset();
    entry.error.clear();
    const int c = character();
    const auto& characters = m_document.runtime().characters;
    if (c < 0 || std::size_t(c) >= characters.size()) {
        entry.error = tr("There is no character to import into: add one first (Character ▸ Add Character…).");
        return;
    }
    auto planned = core::scenario::planClipImport(toFsPath(entry.path), m_document.assets(),
                                                  characters[std::size_t(c)].skeleton, entry.mapping);
    if (planned)
        entry.plan = std::move(planned).value();
    else
        entry.error = fromUtf8(planned.error().message);
}

void ImportMotionDialog::rebuild()
{
    const int selected = std::max(0, selectedEntry());
    m_filling = true;
    m_files->clear();
    for (std::size_t e = 0; e < m_entries.size(); ++e) {
        const Entry& entry = m_entries[e];
        auto* item = new QTreeWidgetItem(m_files, {QFileInfo(entry.path).fileName()});
        item->setData(0, kEntryRole, int(e));
        item->setData(0, kClipRole, -1);
        item->setToolTip(0, entry.path);
        const bool usable = entry.plan && entry.plan->problem.empty();
        if (!entry.plan) {
            item->setText(1, tr("cannot be read"));
            item->setIcon(0, style()->standardIcon(QStyle::SP_MessageBoxCritical));
        } else if (!usable) {
            item->setText(1, tr("moves none of the character's joints"));
            item->setIcon(0, style()->standardIcon(QStyle::SP_MessageBoxWarning));
        } else {
            const auto& report = entry.plan->report;
            item->setText(1, tr("%1, %n frame(s) at %2 fps", nullptr, report.frameCount)
                                 .arg(report.format == "gltf" ? tr("glTF") : tr("BVH"))
                                 .arg(report.frameRate, 0, 'g', 4));
        }
        item->setFlags(usable ? Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable
                              : Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        if (usable)
            item->setCheckState(0, Qt::Checked);
        if (usable && entry.plan->report.format == "gltf") {
            for (std::size_t c = 0; c < entry.plan->clips.size(); ++c) {
                auto* clip = new QTreeWidgetItem(item, {fromUtf8(entry.plan->clips[c].name), tr("animation")});
                clip->setData(0, kEntryRole, int(e));
                clip->setData(0, kClipRole, int(c));
                clip->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsUserCheckable);
                clip->setCheckState(0, Qt::Checked);
            }
            item->setExpanded(true);
        }
    }
    m_filling = false;
    if (m_files->topLevelItemCount() > 0)
        m_files->setCurrentItem(m_files->topLevelItem(std::min(selected, m_files->topLevelItemCount() - 1)));
    showSelected();
    updateImportButton();
}

int ImportMotionDialog::selectedEntry() const
{
    const QTreeWidgetItem* item = m_files ? m_files->currentItem() : nullptr;
    return item ? item->data(0, kEntryRole).toInt() : -1;
}

void ImportMotionDialog::showSelected()
{
    const int e = selectedEntry();
    m_mapping->setRowCount(0);
    const bool haveEntry = e >= 0 && std::size_t(e) < m_entries.size();
    m_applyMapping->setEnabled(haveEntry && m_entries[std::size_t(e)].plan.has_value());
    m_saveMapping->setEnabled(m_applyMapping->isEnabled());
    m_loadMapping->setEnabled(haveEntry);
    if (!haveEntry) {
        m_report->setText(tr("No files to import."));
        m_mappingTitle->clear();
        return;
    }
    const Entry& entry = m_entries[std::size_t(e)];
    const QString name = escaped(QFileInfo(entry.path).fileName());
    if (!entry.plan) {
        m_report->setText(tr("<b>%1 cannot be read</b>: %2<br>Nothing of it is imported.").arg(name, escaped(entry.error)));
        m_mappingTitle->clear();
        return;
    }
    const auto& plan = *entry.plan;
    const auto& report = plan.report;
    QStringList lines;
    lines << tr("<b>%1</b>: %2, %n frame(s) at %3 fps.", nullptr, report.frameCount)
                 .arg(name, report.format == "gltf" ? tr("glTF") : tr("BVH"))
                 .arg(report.frameRate, 0, 'g', 4);
    const auto listed = [](const std::vector<std::string>& names) {
        QStringList shown;
        for (std::size_t i = 0; i < names.size() && i < 12; ++i)
            shown << escaped(fromUtf8(names[i]));
        if (names.size() > 12)
            shown << tr("%n more", nullptr, int(names.size() - 12));
        return shown.join(QStringLiteral(", "));
    };
    lines << tr("Joint names: %1; it moves %n of the character's joints.", nullptr, plan.jointsMoved)
                 .arg(conventionName(report.convention));
    if (!plan.unmoved.empty() && plan.jointsMoved > 0)
        lines << tr("The character's joints it leaves at rest: %1.").arg(listed(plan.unmoved));
    if (!report.unitName.empty())
        lines << tr("Unit: %1. The motion is resized to the character by the length of the legs.")
                     .arg(escaped(fromUtf8(report.unitName)));
    if (!report.turnedFrom.empty())
        lines << tr("The body lay %1 in the file: it is stood up (+Y up, facing +Z).").arg(escaped(fromUtf8(report.turnedFrom)));
    if (report.calibrationFrameDropped)
        lines << tr("Its first frame is a calibration pose (a T-pose): it is left out.");
    if (!report.unmapped.empty())
        lines << tr("%n joint(s) have no H-Anim name and keep their own: %1.", nullptr, int(report.unmapped.size()))
                     .arg(listed(report.unmapped));
    if (!plan.movingNothing.empty())
        lines << tr("Of these, %n move(s) nothing of this character (neither they nor a joint below them is in its "
                    "skeleton): %1.", nullptr, int(plan.movingNothing.size()))
                     .arg(listed(plan.movingNothing));
    if (!plan.problem.empty())
        lines << QStringLiteral("<span style='color:#b00020'>%1</span>").arg(escaped(fromUtf8(plan.problem)));
    m_report->setText(lines.join(QStringLiteral("<br>")));

    m_mappingTitle->setText(tr("Joint mapping of %1 (%n joint(s)):", nullptr, int(plan.mapping.size())).arg(name));
    m_filling = true;
    m_mapping->setRowCount(int(plan.mapping.size()));
    int row = 0;
    for (const auto& [joint, playsAs] : plan.mapping) {
        auto* source = new QTableWidgetItem(fromUtf8(joint));
        source->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
        m_mapping->setItem(row, 0, source);
        m_mapping->setItem(row, 1, new QTableWidgetItem(playsAs == joint ? QString() : fromUtf8(playsAs)));
        ++row;
    }
    m_filling = false;
}

void ImportMotionDialog::onApplyMapping()
{
    const int e = selectedEntry();
    if (e < 0)
        return;
    Entry& entry = m_entries[std::size_t(e)];
    std::map<std::string, std::string> mapping;
    for (int row = 0; row < m_mapping->rowCount(); ++row) {
        const std::string joint = m_mapping->item(row, 0)->text().toStdString();
        const std::string playsAs = m_mapping->item(row, 1) ? m_mapping->item(row, 1)->text().trimmed().toStdString() : "";
        if (!playsAs.empty() && playsAs != joint)
            mapping[joint] = playsAs;
    }
    entry.mapping = std::move(mapping);
    plan(entry);
    rebuild();
}

bool ImportMotionDialog::saveMapping(const QString& path)
{
    const int e = selectedEntry();
    if (e < 0 || !m_entries[std::size_t(e)].plan)
        return false;
    return core::scenario::saveMapping(toFsPath(path), m_entries[std::size_t(e)].plan->mapping).ok();
}

bool ImportMotionDialog::loadMapping(const QString& path)
{
    const int e = selectedEntry();
    if (e < 0)
        return false;
    auto mapping = core::anim::bvh::loadMapping(toFsPath(path));
    if (!mapping) {
        m_report->setText(tr("<b>The mapping file cannot be read</b>: %1").arg(escaped(fromUtf8(mapping.error().message))));
        return false;
    }
    m_entries[std::size_t(e)].mapping = std::map<std::string, std::string>(mapping->begin(), mapping->end());
    plan(m_entries[std::size_t(e)]);
    rebuild();
    return true;
}

std::optional<core::edit::Edit> ImportMotionDialog::edit() const
{
    std::vector<core::scenario::ClipAsset> clips;
    for (int i = 0; i < m_files->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* item = m_files->topLevelItem(i);
        const Entry& entry = m_entries[std::size_t(item->data(0, kEntryRole).toInt())];
        if (!entry.plan || !entry.plan->problem.empty())
            continue;
        if (item->childCount() == 0) {
            if (item->checkState(0) == Qt::Checked)
                clips.insert(clips.end(), entry.plan->clips.begin(), entry.plan->clips.end());
            continue;
        }
        for (int c = 0; c < item->childCount(); ++c)
            if (item->child(c)->checkState(0) == Qt::Checked)
                clips.push_back(entry.plan->clips[std::size_t(item->child(c)->data(0, kClipRole).toInt())]);
    }
    if (clips.empty())
        return std::nullopt;
    auto made = core::edit::addClips(m_document.scenario(), character(), std::move(clips));
    if (!made)
        return std::nullopt;
    return std::move(made).value();
}

QStringList ImportMotionDialog::clipNames() const
{
    QStringList names;
    const auto made = edit();
    if (!made)
        return names;
    for (const core::edit::Change& change : made->changes())
        if (const auto* clip = std::get_if<core::edit::ClipChange>(&change); clip && clip->after)
            names << fromUtf8(clip->after->name);
    return names;
}

void ImportMotionDialog::updateImportButton()
{
    const int count = int(clipNames().size());
    m_import->setEnabled(count > 0);
    m_import->setText(count > 0 ? tr("Import %n Clip(s)", nullptr, count) : tr("Import"));
}

} // namespace thespis::editor
