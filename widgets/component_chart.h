#pragma once
// ComponentChart: the paper's Figs. 4–5 — the magnitude of a posture's principal components,
// one bar per component index, with reference series drawn as lines over the bars (what captured
// motion typically shows at each index) and marked index ranges (a filter's band). It knows
// nothing of postures: the caller hands it plain numbers. With no bars it shows a message saying
// why.

#include <QColor>
#include <QString>
#include <QVector>
#include <QWidget>

namespace thespis::widgets {

struct ChartSeries {
    QString name;           ///< in the legend
    QColor color;
    QVector<float> values;  ///< one per component, index 1 first
};

/// A band of component indices, shaded behind the bars: [first, last], 1-based.
struct ChartBand {
    int first = 1, last = 1;
    QString label;
};

class ComponentChart : public QWidget {
    Q_OBJECT
public:
    explicit ComponentChart(QWidget* parent = nullptr);

    /// The bars (one series) and the lines over them; either may be empty.
    void setSeries(ChartSeries bars, QVector<ChartSeries> lines);
    void setBands(QVector<ChartBand> bands);
    /// Shown instead of the chart while there are no bars.
    void setMessage(const QString& message);
    /// A line under the title (e.g. the share of energy above a component).
    void setCaption(const QString& caption);

    const ChartSeries& bars() const { return m_bars; }
    const QVector<ChartSeries>& lines() const { return m_lines; }
    QString message() const { return m_message; }
    QString caption() const { return m_caption; }

    QSize sizeHint() const override { return {520, 260}; }
    QSize minimumSizeHint() const override { return {240, 140}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    ChartSeries m_bars;
    QVector<ChartSeries> m_lines;
    QVector<ChartBand> m_bands;
    QString m_message;
    QString m_caption;
};

} // namespace thespis::widgets
