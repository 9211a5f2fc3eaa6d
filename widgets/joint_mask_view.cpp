#include "widgets/joint_mask_view.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QPainter>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QStyledItemDelegate>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "widgets/joint_mask_picture.h"

namespace thespis::widgets {

using joint_mask::isDark;
using joint_mask::mix;

namespace {

constexpr int JointRole = Qt::UserRole;      // column 0: the joint's index
constexpr int WeightRole = Qt::UserRole + 1; // column 1: the weight as a float
constexpr int NamedRole = Qt::UserRole + 2;  // column 1: whether the mask sets the joint
constexpr int MinRadius = 2;
constexpr int MaxRadius = 100;

// Colour of the inherited (not named) joints' text in the tree.
QColor inheritedTextColor(const QPalette& palette)
{
    return mix(palette.color(QPalette::Text), palette.color(QPalette::Base), 0.45);
}

} // namespace

// ------------------------------------------------------------------------------------------------
// The tree's delegate: paints the weight column as a number beside a small bar, edits it with a
// spin box and turns the edit into an intent instead of writing the model.

class WeightDelegate : public QStyledItemDelegate {
public:
    WeightDelegate(QObject* parent, std::function<void(int, float)> request)
        : QStyledItemDelegate(parent), m_request(std::move(request))
    {
    }

    void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        if (index.column() != 1) {
            QStyledItemDelegate::paint(painter, option, index);
            return;
        }
        QStyleOptionViewItem opt = option;
        initStyleOption(&opt, index);
        opt.text.clear();
        const QWidget* widget = opt.widget;
        QStyle* style = widget ? widget->style() : nullptr;
        if (style)
            style->drawControl(QStyle::CE_ItemViewItem, &opt, painter, widget);

        const float weight = index.data(WeightRole).toFloat();
        const bool named = index.data(NamedRole).toBool();
        const bool selected = opt.state & QStyle::State_Selected;
        const QColor base = opt.palette.color(QPalette::Base);
        const QColor textColor = selected ? opt.palette.color(QPalette::HighlightedText) : opt.palette.color(QPalette::Text);
        const QRect r = opt.rect.adjusted(6, 0, -6, 0);
        const QFontMetrics metrics(opt.font);
        const int numberW = metrics.horizontalAdvance(QStringLiteral("0.00")) + 4;
        const QRectF bar(r.left(), r.center().y() - 2.5, std::max(8, r.width() - numberW - 6), 5);

        painter->save();
        painter->setRenderHint(QPainter::Antialiasing);
        painter->setPen(Qt::NoPen);
        painter->setBrush(mix(base, opt.palette.color(QPalette::Text), 0.14));
        painter->drawRoundedRect(bar, 2, 2);
        QColor fill = JointMaskView::weightColor(weight, base);
        if (!named)
            fill.setAlphaF(0.6f);
        if (weight > 0) {
            painter->setBrush(fill);
            painter->drawRoundedRect(QRectF(bar.left(), bar.top(), std::max(bar.height(), bar.width() * double(weight)), bar.height()), 2, 2);
        }
        painter->setFont(opt.font);
        painter->setPen(textColor);
        painter->drawText(QRect(r.right() - numberW, r.top(), numberW, r.height()), Qt::AlignRight | Qt::AlignVCenter,
                          QString::number(double(weight), 'f', 2));
        painter->restore();
    }

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex& index) const override
    {
        if (index.column() != 1)
            return nullptr; // joint names are not edited here
        auto* spin = new QDoubleSpinBox(parent);
        spin->setObjectName(QStringLiteral("weightEditor"));
        spin->setRange(0.0, 1.0);
        spin->setSingleStep(0.05);
        spin->setDecimals(2);
        spin->setFrame(false);
        spin->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        return spin;
    }

    void setEditorData(QWidget* editor, const QModelIndex& index) const override
    {
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor))
            spin->setValue(double(index.data(WeightRole).toFloat()));
    }

    void setModelData(QWidget* editor, QAbstractItemModel*, const QModelIndex& index) const override
    {
        // The view shows what the editor feeds it: ask instead of writing the model.
        auto* spin = qobject_cast<QDoubleSpinBox*>(editor);
        if (!spin)
            return;
        spin->interpretText();
        const float value = float(spin->value());
        const float shown = index.data(WeightRole).toFloat();
        // Typing the shown value into an inherited joint still means something: it names it.
        if (std::abs(value - shown) > 1e-4f || !index.data(NamedRole).toBool())
            m_request(index.siblingAtColumn(0).data(JointRole).toInt(), value);
    }

    void updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option, const QModelIndex&) const override
    {
        editor->setGeometry(option.rect);
    }

private:
    std::function<void(int, float)> m_request;
};

// ------------------------------------------------------------------------------------------------

QColor JointMaskView::weightColor(float weight, const QColor& base)
{
    const float t = std::isfinite(weight) ? std::clamp(weight, 0.0f, 1.0f) : 0.0f;
    const bool dark = isDark(base);
    // Grey at 0 towards a saturated orange at 1, in HSL: the hue stays that of the accent while
    // saturation and lightness move, so half weights read as a muted version of the accent.
    const QColor zero = dark ? QColor(0x70, 0x74, 0x7b) : QColor(0xa9, 0xad, 0xb3);
    const QColor one = dark ? QColor(0xff, 0x8c, 0x1a) : QColor(0xef, 0x6c, 0x00);
    const float hue = one.hslHueF();
    const float saturation = zero.hslSaturationF() + (one.hslSaturationF() - zero.hslSaturationF()) * t;
    const float lightness = zero.lightnessF() + (one.lightnessF() - zero.lightnessF()) * t;
    return QColor::fromHslF(hue, saturation, lightness);
}

JointMaskView::JointMaskView(QWidget* parent) : QWidget(parent)
{
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("jointTree"));
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Joint"), tr("Weight")});
    m_tree->setUniformRowHeights(true);
    // H-Anim hierarchies are deep (a spine of 24 vertebrae): a narrow indentation keeps names readable.
    m_tree->setIndentation(12);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::SelectedClicked);
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
    m_tree->setItemDelegate(new WeightDelegate(m_tree, [this](int joint, float weight) {
        if (joint >= 0 && joint < m_joints.size())
            emit weightRequested(joint, weight);
    }));
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::Fixed);
    m_tree->header()->resizeSection(1, m_tree->fontMetrics().horizontalAdvance(QStringLiteral("0.00")) + 56);
    m_tree->header()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* current) { onCurrentItemChanged(current); });
    connect(m_tree, &QWidget::customContextMenuRequested, this, &JointMaskView::onTreeContextMenu);

    // The brush bar above the picture.
    auto* brushBar = new QWidget(this);
    brushBar->setObjectName(QStringLiteral("brushBar"));
    auto* bar = new QHBoxLayout(brushBar);
    bar->setContentsMargins(6, 4, 6, 4);
    bar->setSpacing(6);
    auto* weightLabel = new QLabel(tr("Brush weight"), brushBar);
    m_brushSlider = new QSlider(Qt::Horizontal, brushBar);
    m_brushSlider->setObjectName(QStringLiteral("brushWeightSlider"));
    m_brushSlider->setRange(0, 100);
    m_brushSlider->setPageStep(25);
    m_brushSlider->setMinimumWidth(60);
    m_brushSlider->setToolTip(tr("The weight a left-button stroke paints (the right button paints 0)"));
    m_brushSpin = new QDoubleSpinBox(brushBar);
    m_brushSpin->setObjectName(QStringLiteral("brushWeightSpin"));
    m_brushSpin->setRange(0.0, 1.0);
    m_brushSpin->setSingleStep(0.05);
    m_brushSpin->setDecimals(2);
    m_brushSpin->setToolTip(m_brushSlider->toolTip());
    weightLabel->setBuddy(m_brushSpin);
    auto* radiusLabel = new QLabel(tr("Radius"), brushBar);
    m_radiusSpin = new QSpinBox(brushBar);
    m_radiusSpin->setObjectName(QStringLiteral("brushRadiusSpin"));
    m_radiusSpin->setRange(MinRadius, MaxRadius);
    m_radiusSpin->setSuffix(tr(" px"));
    m_radiusSpin->setToolTip(tr("Radius of the brush in the picture"));
    radiusLabel->setBuddy(m_radiusSpin);
    bar->addWidget(weightLabel);
    bar->addWidget(m_brushSlider, 1);
    bar->addWidget(m_brushSpin);
    bar->addSpacing(8);
    bar->addWidget(radiusLabel);
    bar->addWidget(m_radiusSpin);
    connect(m_brushSlider, &QSlider::valueChanged, this, &JointMaskView::onBrushSliderMoved);
    connect(m_brushSpin, &QDoubleSpinBox::valueChanged, this, &JointMaskView::onBrushSpinChanged);
    connect(m_radiusSpin, &QSpinBox::valueChanged, this, &JointMaskView::onRadiusSpinChanged);

    m_picture = new JointMaskPicture(this);
    auto* right = new QWidget(this);
    auto* rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->setSpacing(0);
    rightLayout->addWidget(brushBar);
    rightLayout->addWidget(m_picture, 1);

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->setObjectName(QStringLiteral("jointMaskSplitter"));
    m_splitter->addWidget(m_tree);
    m_splitter->addWidget(right);
    m_splitter->setChildrenCollapsible(false);
    m_splitter->setStretchFactor(0, 0);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setSizes({320, 440});
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);

    setBrushWeight(m_brushWeight);
    setBrushRadius(m_brushRadius);
}

JointMaskView::~JointMaskView()
{
    // The picture's hide event (sent while QWidget tears the children down) must not emit a
    // finished stroke through a view that is half destroyed.
    m_picture->dropStroke();
}

QWidget* JointMaskView::picture() const
{
    return m_picture;
}

void JointMaskView::setJoints(QVector<MaskJoint> joints)
{
    bool sameStructure = joints.size() == m_joints.size();
    bool samePositions = sameStructure;
    for (int i = 0; sameStructure && i < joints.size(); ++i) {
        sameStructure = joints[i].name == m_joints[i].name && joints[i].parent == m_joints[i].parent;
        samePositions = samePositions && joints[i].position == m_joints[i].position;
    }
    for (MaskJoint& joint : joints)
        joint.weight = std::isfinite(joint.weight) ? std::clamp(joint.weight, 0.0f, 1.0f) : 0.0f;
    m_joints = std::move(joints);
    if (sameStructure) {
        for (int i = 0; i < m_joints.size(); ++i)
            updateItem(i);
    } else {
        buildTree();
    }
    m_picture->jointsChanged(!sameStructure, !samePositions);
}

void JointMaskView::setFaceOutline(QRectF outline)
{
    if (outline == m_faceOutline)
        return;
    m_faceOutline = outline;
    m_picture->jointsChanged(true, true);
}

void JointMaskView::buildTree()
{
    const QTreeWidgetItem* current = m_tree->currentItem();
    const QString currentName = current ? current->text(0) : QString();
    m_updating = true;
    m_tree->clear();
    m_items.clear();
    m_items.reserve(m_joints.size());
    QTreeWidgetItem* restore = nullptr;
    for (int i = 0; i < m_joints.size(); ++i) {
        const int parent = m_joints[i].parent;
        auto* item = parent >= 0 && parent < i ? new QTreeWidgetItem(m_items[parent]) : new QTreeWidgetItem(m_tree);
        item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable);
        item->setText(0, m_joints[i].name);
        item->setData(0, JointRole, i);
        m_items.append(item);
        if (!restore && !currentName.isEmpty() && m_joints[i].name == currentName)
            restore = item;
        updateItem(i);
    }
    m_tree->expandAll();
    if (restore)
        m_tree->setCurrentItem(restore);
    m_updating = false;
}

void JointMaskView::updateItem(int joint)
{
    QTreeWidgetItem* item = m_items.value(joint);
    if (!item)
        return;
    const MaskJoint& j = m_joints[joint];
    item->setData(1, WeightRole, j.weight);
    item->setData(1, NamedRole, j.named);
    item->setData(1, Qt::DisplayRole, QString::number(double(j.weight), 'f', 2));
    QFont font = m_tree->font();
    font.setItalic(!j.named);
    const QBrush foreground = j.named ? QBrush() : QBrush(inheritedTextColor(m_tree->palette()));
    for (int column = 0; column < 2; ++column) {
        item->setData(column, Qt::FontRole, j.named ? QVariant() : QVariant(font));
        item->setData(column, Qt::ForegroundRole, j.named ? QVariant() : QVariant(foreground));
    }
    item->setToolTip(0, j.named ? tr("%1: set by the mask").arg(j.name) : tr("%1: inherited").arg(j.name));
}

void JointMaskView::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange) {
        for (int i = 0; i < m_items.size(); ++i)
            updateItem(i);
        m_picture->jointsChanged(false, true);
    }
}

void JointMaskView::onCurrentItemChanged(QTreeWidgetItem* current)
{
    m_picture->update();
    if (m_updating || !current)
        return;
    emit jointSelected(current->data(0, JointRole).toInt());
}

void JointMaskView::selectFromPicture(int joint)
{
    if (joint < 0 || joint >= m_items.size())
        return;
    if (currentJoint() != joint) {
        setCurrentJoint(joint);
        m_tree->scrollToItem(m_items[joint]);
    }
    emit jointSelected(joint);
}

void JointMaskView::setCurrentJoint(int joint)
{
    m_updating = true;
    m_tree->setCurrentItem(m_items.value(joint));
    m_updating = false;
    m_picture->update();
}

int JointMaskView::currentJoint() const
{
    const QTreeWidgetItem* item = m_tree->currentItem();
    return item ? item->data(0, JointRole).toInt() : -1;
}

void JointMaskView::onTreeContextMenu(const QPoint& pos)
{
    QTreeWidgetItem* item = m_tree->itemAt(pos);
    if (!item)
        return;
    const int joint = item->data(0, JointRole).toInt();
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("jointWeightMenu"));
    menu.setTitle(m_joints.value(joint).name);
    const std::pair<float, QString> choices[] = {{1.0f, tr("Set to 1")}, {0.5f, tr("Set to 0.5")}, {0.0f, tr("Set to 0")}};
    for (const auto& [weight, text] : choices) {
        QAction* action = menu.addAction(text);
        const float value = weight;
        connect(action, &QAction::triggered, this, [this, joint, value] { emit weightRequested(joint, value); });
    }
    menu.exec(m_tree->viewport()->mapToGlobal(pos));
}

void JointMaskView::setBrushWeight(float weight)
{
    m_brushWeight = std::isfinite(weight) ? std::clamp(weight, 0.0f, 1.0f) : 1.0f;
    m_updating = true;
    m_brushSpin->setValue(double(m_brushWeight));
    m_brushSlider->setValue(int(std::lround(m_brushWeight * 100.0f)));
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::setBrushRadius(int pixels)
{
    m_brushRadius = std::clamp(pixels, MinRadius, MaxRadius);
    m_updating = true;
    m_radiusSpin->setValue(m_brushRadius);
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::onBrushSliderMoved(int value)
{
    if (m_updating)
        return;
    m_brushWeight = float(value) / 100.0f;
    m_updating = true;
    m_brushSpin->setValue(double(m_brushWeight));
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::onBrushSpinChanged(double value)
{
    if (m_updating)
        return;
    m_brushWeight = float(value);
    m_updating = true;
    m_brushSlider->setValue(int(std::lround(value * 100.0)));
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::onRadiusSpinChanged(int value)
{
    if (m_updating)
        return;
    m_brushRadius = value;
    m_picture->brushChanged();
}

QPoint JointMaskView::jointPosition(int joint) const
{
    const QPointF p = m_picture->screen(joint);
    return QPoint(int(std::lround(p.x())), int(std::lround(p.y())));
}

int JointMaskView::jointAt(QPoint picturePos) const
{
    return m_picture->jointAt(QPointF(picturePos));
}

} // namespace thespis::widgets
