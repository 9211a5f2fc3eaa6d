#include "editor/viseme_table.h"

#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "editor/qt_conversions.h"

namespace thespis::editor {
namespace {

enum Column { Name, Phonemes, Alpha, Weight, Spread, ShownAs, ColumnCount };

} // namespace

VisemeTable::VisemeTable(QWidget* parent) : QWidget(parent), m_set(core::speech::mpeg4Visemes())
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("visemeTable"));
    m_table->setHorizontalHeaderLabels({tr("Viseme"), tr("Phonemes"), tr("α"), tr("Weight"), tr("Spread"), tr("Shows as (MPEG-4)")});
    m_table->horizontalHeaderItem(Alpha)->setToolTip(tr("Dominance α (paper eq. 3): larger keeps the mouth shape to its own phoneme"));
    m_table->horizontalHeaderItem(Weight)->setToolTip(tr("How far the shape is reached at the phoneme's centre (0 … 1)"));
    m_table->horizontalHeaderItem(Spread)->setToolTip(tr("How far the shape reaches past its phoneme, as a share of the phoneme's length on each side (0 … 2)"));
    m_table->horizontalHeaderItem(ShownAs)->setToolTip(
        tr("The MPEG-4 viseme (1 … 14) the face shows this one as; 0 keeps the mouth at rest"));
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(Phonemes, QHeaderView::Stretch);
    m_table->verticalHeader()->setVisible(false);
    layout->addWidget(m_table, 1);
    m_problem = new QLabel(this);
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c02020"));
    m_problem->hide();
    layout->addWidget(m_problem);
    auto* buttons = new QHBoxLayout;
    auto* load = new QPushButton(tr("Load…"), this);
    auto* save = new QPushButton(tr("Save…"), this);
    m_builtIn = new QComboBox(this);
    m_builtIn->setObjectName(QStringLiteral("visemeBuiltIn"));
    m_builtIn->setToolTip(tr("Start again from a built-in set: MPEG-4's 14, Oculus Lipsync's 15 or Microsoft's SAPI 21"));
    for (const auto& [name, label] : {std::pair{"mpeg4", tr("MPEG-4 (14)")}, {"oculus", tr("Oculus (15)")}, {"sapi", tr("SAPI (21)")}})
        m_builtIn->addItem(label, QString::fromLatin1(name));
    buttons->addWidget(load);
    buttons->addWidget(save);
    buttons->addStretch(1);
    buttons->addWidget(new QLabel(tr("Built-in:"), this));
    buttons->addWidget(m_builtIn);
    layout->addLayout(buttons);
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load Visemes"), {}, tr("Viseme sets (*.json)"));
        if (!path.isEmpty())
            if (auto loaded = this->load(path); !loaded)
                showProblem(fromUtf8(loaded.error().message));
    });
    connect(save, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Save Visemes"), QStringLiteral("visemes.json"),
                                                          tr("Viseme sets (*.json)"));
        if (!path.isEmpty())
            if (auto saved = this->save(path); !saved)
                showProblem(fromUtf8(saved.error().message));
    });
    connect(m_builtIn, &QComboBox::activated, this, [this](int index) {
        (void)setVisemes(*core::speech::builtInVisemeSet(m_builtIn->itemData(index).toString().toStdString()));
    });
    connect(m_table, &QTableWidget::itemChanged, this, &VisemeTable::onEdited);
    fill();
}

core::Result<void> VisemeTable::setVisemes(core::speech::VisemeSet set)
{
    if (auto valid = set.validate(); !valid)
        return valid;
    m_set = std::move(set);
    m_problem->hide();
    fill();
    emit visemesChanged();
    return {};
}

core::Result<void> VisemeTable::load(const QString& path)
{
    auto loaded = core::speech::loadVisemeSet(toFsPath(path));
    if (!loaded)
        return loaded.error();
    return setVisemes(std::move(loaded).value());
}

core::Result<void> VisemeTable::save(const QString& path) const { return core::speech::saveVisemeSet(toFsPath(path), m_set); }

void VisemeTable::fill()
{
    m_filling = true;
    m_builtIn->setCurrentIndex(m_builtIn->findData(fromUtf8(m_set.name))); // none for the user's own
    m_table->setRowCount(0);
    for (const core::speech::Viseme& v : m_set.visemes) {
        if (v.id == 0)
            continue; // silence: the face at rest
        QStringList phonemes;
        for (const auto& [phoneme, ids] : m_set.phonemes)
            if (std::find(ids.begin(), ids.end(), v.id) != ids.end())
                phonemes.push_back(fromUtf8(phoneme));
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        auto* name = new QTableWidgetItem(QStringLiteral("%1 %2").arg(v.id).arg(fromUtf8(v.name)));
        name->setFlags(name->flags() & ~Qt::ItemIsEditable);
        name->setData(Qt::UserRole, v.id);
        m_table->setItem(row, Name, name);
        m_table->setItem(row, Phonemes, new QTableWidgetItem(phonemes.join(QLatin1Char(' '))));
        for (const auto& [column, value] : {std::pair{Alpha, v.alpha}, {Weight, v.weight}, {Spread, v.spread}}) {
            auto* item = new QTableWidgetItem;
            item->setData(Qt::EditRole, value);
            m_table->setItem(row, column, item);
        }
        auto* shownAs = new QTableWidgetItem;
        shownAs->setData(Qt::EditRole, v.mpeg4);
        if (const core::speech::Viseme* mpeg4 = core::speech::mpeg4Visemes().find(v.mpeg4); mpeg4 && v.mpeg4 != 0)
            shownAs->setToolTip(fromUtf8(mpeg4->name));
        m_table->setItem(row, ShownAs, shownAs);
    }
    m_filling = false;
}

void VisemeTable::onEdited(QTableWidgetItem* item)
{
    if (m_filling)
        return;
    core::speech::VisemeSet next = m_set;
    const int id = m_table->item(item->row(), Name)->data(Qt::UserRole).toInt();
    auto viseme = std::find_if(next.visemes.begin(), next.visemes.end(), [&](const auto& v) { return v.id == id; });
    if (item->column() == Phonemes) {
        // The phonemes typed now show this viseme, and only they of those that showed it.
        for (auto& [phoneme, ids] : next.phonemes)
            std::erase(ids, id);
        for (const QString& phoneme : item->text().toUpper().split(QLatin1Char(' '), Qt::SkipEmptyParts))
            next.phonemes[phoneme.toStdString()].push_back(id);
        std::erase_if(next.phonemes, [](const auto& entry) { return entry.second.empty(); });
    } else if (item->column() == ShownAs) {
        viseme->mpeg4 = item->data(Qt::EditRole).toInt();
    } else {
        const double value = item->data(Qt::EditRole).toDouble();
        (item->column() == Alpha ? viseme->alpha : item->column() == Weight ? viseme->weight : viseme->spread) = value;
    }
    if (auto valid = next.validate(); !valid) {
        // The entry goes back to what the set holds (queued: the table is still handing it over).
        QMetaObject::invokeMethod(this, &VisemeTable::fill, Qt::QueuedConnection);
        showProblem(fromUtf8(valid.error().message));
        return;
    }
    m_set = std::move(next);
    m_problem->hide();
    emit visemesChanged();
}

void VisemeTable::showProblem(const QString& text)
{
    m_problem->setText(text);
    m_problem->show();
}

} // namespace thespis::editor
