#pragma once
// The timeline's scrub bar drawn as a DCC time slider: the shot's frames with ticks, a
// strip over the frames computed so far and the handle; a click or drag picks the frame
// under the mouse. It only shows and picks frames: it never computes or seeks them.

#include <QSlider>

#include <cstddef>

class QPainter;

namespace throng::editor {

class TimelineRuler : public QSlider {
    Q_OBJECT

public:
    explicit TimelineRuler(QWidget* parent = nullptr);

    // Frames 0..cachedFrames-1 are computed (the strip along the bottom covers them).
    void setCachedFrames(std::size_t cachedFrames);
    std::size_t cachedFrames() const { return m_cachedFrames; }
    // The frame being computed to, marked until it shows; -1 = none.
    void setTargetFrame(int frame);
    int targetFrame() const { return m_targetFrame; }

    // Where frame `frame` sits, in widget pixels, and the frame nearest a pixel column.
    int xOfFrame(int frame) const;
    int frameAtX(int x) const;
    // The band the cache strip is painted in (computed frames in kCachedColour, the rest
    // in kUncachedColour).
    QRect cacheStrip() const;

    static constexpr QRgb kBackgroundColour = 0xff2f3136;
    static constexpr QRgb kCachedColour = 0xff3fa34d;
    static constexpr QRgb kUncachedColour = 0xff4a4d55;
    static constexpr QRgb kHandleColour = 0xffe8633a;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    bool event(QEvent* event) override;
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    void paintTicks(QPainter& painter) const;
    void paintHandle(QPainter& painter) const;
    // Frames between labelled ticks: 1, 2, 5, 10, 20, 50… so that labels stay apart.
    int labelStep() const;

    std::size_t m_cachedFrames = 0;
    int m_targetFrame = -1;
};

}  // namespace throng::editor
