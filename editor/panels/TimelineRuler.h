#pragma once
// The timeline's scrub bar drawn as a DCC time slider: the shot's frames with ticks, a
// strip over the frames computed so far and the handle; a click or drag picks the frame
// under the mouse. With a retime shown (a layout time offset selected), an arrow marks how
// far it shifts its agents, and a Shift+drag says by how many frames to shift them more.
// It only shows and picks frames: it never computes or seeks them, nor edits the scene.

#include <QSlider>

#include <cstddef>
#include <optional>

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

    // The retime to mark: an arrow from frame `from` to `from + frames` ("+frames"); none
    // clears it (and Shift+drag scrubs again).
    struct Retime {
        int from = 0, frames = 0;
        bool operator==(const Retime&) const = default;
    };
    void setRetime(std::optional<Retime> retime);
    std::optional<Retime> retime() const { return m_retime; }

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
    static constexpr QRgb kRetimeColour = 0xffb58cff;

signals:
    // A Shift+drag with a retime shown: the frames from where it was pressed to the mouse;
    // `finished` on the release.
    void retimeDragged(int frames, bool finished);

public:

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
    void paintRetime(QPainter& painter) const;
    // Frames between labelled ticks: 1, 2, 5, 10, 20, 50… so that labels stay apart.
    int labelStep() const;

    std::size_t m_cachedFrames = 0;
    int m_targetFrame = -1;
    std::optional<Retime> m_retime;
    std::optional<int> m_retimePress;  // the frame a retime drag began on
};

}  // namespace throng::editor
