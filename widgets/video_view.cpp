#include "widgets/video_view.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace thespis::widgets {

namespace {

constexpr int kMargin = 8;   // between the widget's edge and the overlay's blocks
constexpr int kPadding = 6;  // inside a block
constexpr int kInsetSide = 112; // the inset picture's longer side at most

QColor statusColor(VideoOverlay::Status status)
{
    switch (status) {
    case VideoOverlay::Status::Good: return QColor(0x2e, 0xcc, 0x71);
    case VideoOverlay::Status::Warning: return QColor(0xf3, 0x9c, 0x12);
    case VideoOverlay::Status::Bad: return QColor(0xe7, 0x4c, 0x3c);
    case VideoOverlay::Status::Neutral: break;
    }
    return QColor(0xbd, 0xc3, 0xc7);
}

// A translucent dark rounded box: what the overlay's text sits on, readable over any video.
void drawPanel(QPainter& painter, const QRectF& rect)
{
    QPainterPath path;
    path.addRoundedRect(rect, 4, 4);
    painter.fillPath(path, QColor(0, 0, 0, 150));
}

} // namespace

VideoView::VideoView(QWidget* parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void VideoView::setImage(const QImage& image)
{
    const bool resized = image.size() != m_image.size();
    m_image = image;
    if (resized)
        updateGeometry();
    update();
}

void VideoView::clearImage()
{
    m_image = QImage();
    update();
}

void VideoView::setOverlay(const VideoOverlay& overlay)
{
    m_overlay = overlay;
    update();
}

void VideoView::setMessage(const QString& title, const QString& text)
{
    if (title == m_messageTitle && text == m_messageText)
        return;
    m_messageTitle = title;
    m_messageText = text;
    update();
}

void VideoView::setInset(const QImage& image, const QString& caption)
{
    m_inset = image;
    m_insetCaption = caption;
    update();
}

QRect VideoView::imageRect() const
{
    if (m_image.isNull() || width() <= 0 || height() <= 0)
        return {};
    const QSize scaled = m_image.size().scaled(size(), Qt::KeepAspectRatio);
    return QRect(QPoint((width() - scaled.width()) / 2, (height() - scaled.height()) / 2), scaled);
}

QSize VideoView::sizeHint() const
{
    return QSize(480, 360);
}

QSize VideoView::minimumSizeHint() const
{
    return QSize(160, 120);
}

void VideoView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.fillRect(rect(), QColor(0x1c, 0x1c, 0x1c));
    if (!m_image.isNull()) {
        painter.setRenderHint(QPainter::SmoothPixmapTransform);
        painter.drawImage(imageRect(), m_image);
    }
    painter.setRenderHint(QPainter::Antialiasing);
    if (hasMessage()) {
        if (!m_image.isNull())
            painter.fillRect(imageRect(), QColor(0, 0, 0, 140));
        drawMessage(painter);
    }
    drawOverlay(painter);
    drawInset(painter);
}

void VideoView::drawInset(QPainter& painter) const
{
    if (m_inset.isNull())
        return;
    const QFontMetrics metrics(font());
    const QSize side = m_inset.size().scaled(kInsetSide, kInsetSide, Qt::KeepAspectRatio);
    const int captionHeight = m_insetCaption.isEmpty() ? 0 : metrics.height() + kPadding / 2;
    const int w = std::max(side.width(), metrics.horizontalAdvance(m_insetCaption)) + 2 * kPadding;
    const QRectF box(width() - kMargin - w, height() - kMargin - side.height() - captionHeight - 2 * kPadding, w,
                     side.height() + captionHeight + 2 * kPadding);
    drawPanel(painter, box);
    painter.setPen(Qt::white);
    if (captionHeight > 0)
        painter.drawText(QRectF(box.left(), box.top() + kPadding, box.width(), metrics.height()), Qt::AlignHCenter,
                         m_insetCaption);
    const QRectF picture(box.center().x() - side.width() / 2.0, box.top() + kPadding + captionHeight, side.width(),
                         side.height());
    painter.drawImage(picture, m_inset);
}

void VideoView::drawOverlay(QPainter& painter) const
{
    const QFontMetrics metrics(font());
    if (!m_overlay.lines.isEmpty()) {
        int textWidth = 0;
        for (const QString& line : m_overlay.lines)
            textWidth = std::max(textWidth, metrics.horizontalAdvance(line));
        const int dot = metrics.height() / 2;
        const int lineHeight = metrics.height();
        const QRectF box(kMargin, kMargin, kPadding * 3 + dot + textWidth,
                         kPadding * 2 + lineHeight * int(m_overlay.lines.size()));
        drawPanel(painter, box);
        painter.setPen(Qt::NoPen);
        painter.setBrush(statusColor(m_overlay.status));
        painter.drawEllipse(QRectF(box.left() + kPadding, box.top() + kPadding + (lineHeight - dot) / 2.0, dot, dot));
        painter.setPen(Qt::white);
        int y = int(box.top()) + kPadding;
        for (const QString& line : m_overlay.lines) {
            painter.drawText(QRect(int(box.left()) + kPadding * 2 + dot, y, textWidth + 2, lineHeight),
                             Qt::AlignLeft | Qt::AlignVCenter, line);
            y += lineHeight;
        }
    }
    if (m_overlay.recording) {
        const QString text = m_overlay.recordingText.isEmpty() ? QStringLiteral("REC") : m_overlay.recordingText;
        const int dot = metrics.height() * 2 / 3;
        const int w = kPadding * 3 + dot + metrics.horizontalAdvance(text);
        const QRectF box(width() - kMargin - w, kMargin, w, kPadding * 2 + metrics.height());
        drawPanel(painter, box);
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(0xe7, 0x4c, 0x3c));
        painter.drawEllipse(QRectF(box.left() + kPadding, box.center().y() - dot / 2.0, dot, dot));
        painter.setPen(Qt::white);
        painter.drawText(box.adjusted(kPadding * 2 + dot, 0, -kPadding, 0), Qt::AlignLeft | Qt::AlignVCenter, text);
    }
}

void VideoView::drawMessage(QPainter& painter) const
{
    QFont titleFont = font();
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.6);
    titleFont.setBold(true);
    const QFontMetrics titleMetrics(titleFont);
    const QFontMetrics textMetrics(font());
    const int maxWidth = std::max(120, width() - 6 * kMargin);
    const QRect titleRect = m_messageTitle.isEmpty()
                                ? QRect()
                                : titleMetrics.boundingRect(QRect(0, 0, maxWidth, 10000), Qt::AlignHCenter | Qt::TextWordWrap,
                                                            m_messageTitle);
    const QRect textRect = m_messageText.isEmpty()
                               ? QRect()
                               : textMetrics.boundingRect(QRect(0, 0, maxWidth, 10000), Qt::AlignHCenter | Qt::TextWordWrap,
                                                          m_messageText);
    const int gap = titleRect.isEmpty() || textRect.isEmpty() ? 0 : kPadding;
    const int w = std::max(titleRect.width(), textRect.width()) + 4 * kPadding;
    const int h = titleRect.height() + gap + textRect.height() + 4 * kPadding;
    const QRect box((width() - w) / 2, (height() - h) / 2, w, h);
    drawPanel(painter, box);
    painter.setPen(Qt::white);
    int y = box.top() + 2 * kPadding;
    if (!titleRect.isEmpty()) {
        painter.setFont(titleFont);
        painter.drawText(QRect(box.left(), y, box.width(), titleRect.height()), Qt::AlignHCenter | Qt::TextWordWrap,
                         m_messageTitle);
        y += titleRect.height() + gap;
    }
    if (!textRect.isEmpty()) {
        painter.setFont(font());
        painter.setPen(QColor(0xec, 0xf0, 0xf1));
        painter.drawText(QRect(box.left() + 2 * kPadding, y, box.width() - 4 * kPadding, textRect.height()),
                         Qt::AlignHCenter | Qt::TextWordWrap, m_messageText);
    }
    painter.setFont(font());
}

} // namespace thespis::widgets
