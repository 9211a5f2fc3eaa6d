#pragma once
// VideoView: shows live video — one picture at a time, scaled to fit and letterboxed — with an
// overlay: a block of short lines in a corner (what the caller wants people to see at a glance:
// frame rate, latency, tracking state), coloured by a status, a recording mark, a small inset
// picture in a corner, and a big
// centred message when there is nothing to show or the video stopped (the last picture stays,
// dimmed, behind it). It knows nothing of where pictures come from; the caller feeds QImages.
// Owns a copy of the picture shown (QImage is implicitly shared, so feeding frames does not copy).

#include <QColor>
#include <QImage>
#include <QRect>
#include <QString>
#include <QStringList>
#include <QWidget>

class QPainter;

namespace thespis::widgets {

/// What the corner block says.
struct VideoOverlay {
    enum class Status { Neutral, Good, Warning, Bad };
    QStringList lines;               ///< one fact each ("29.8 fps", "latency 41 ms", "Tracking: 12 markers")
    Status status = Status::Neutral; ///< colours the block's marker: good (tracking), warning (searching), bad
    bool recording = false;          ///< a red "REC" mark in the other corner
    QString recordingText;           ///< the mark's text (translated by the caller); empty: "REC"
};

class VideoView : public QWidget {
    Q_OBJECT
public:
    explicit VideoView(QWidget* parent = nullptr);

    /// The picture to show (any format; it is drawn as it is, scaled to fit).
    void setImage(const QImage& image);
    void clearImage();
    const QImage& image() const { return m_image; }

    void setOverlay(const VideoOverlay& overlay);
    const VideoOverlay& overlay() const { return m_overlay; }
    /// The corner block as one text, lines joined by newlines (for tests and accessibility).
    QString overlayText() const { return m_overlay.lines.join(QLatin1Char('\n')); }

    /// A big centred message over the picture (which is dimmed behind it); empty: none.
    /// `title` is drawn larger above `text`; either may be empty.
    void setMessage(const QString& title, const QString& text = {});
    QString messageTitle() const { return m_messageTitle; }
    QString messageText() const { return m_messageText; }
    bool hasMessage() const { return !m_messageTitle.isEmpty() || !m_messageText.isEmpty(); }

    /// A small picture in the bottom-right corner under a caption (what a side view sees: the
    /// mirror ball the light comes from); a null image: none.
    void setInset(const QImage& image, const QString& caption = {});
    const QImage& inset() const { return m_inset; }

    /// Where the picture is drawn in the widget (empty without a picture).
    QRect imageRect() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    void drawOverlay(QPainter& painter) const;
    void drawMessage(QPainter& painter) const;
    void drawInset(QPainter& painter) const;

    QImage m_image;
    VideoOverlay m_overlay;
    QString m_messageTitle, m_messageText;
    QImage m_inset;
    QString m_insetCaption;
};

} // namespace thespis::widgets
